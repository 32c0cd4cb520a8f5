// ElevationFan: the elevation samples of one beam's fan of rays, shared by the simulator and
// the forward model (model/forward_model.h) so that both trace the same elevations with the
// same weights and normalisation.
//
// A fan traced over [-half, +half] is split into `count` equal steps; sample k stands for the
// step around its centre, theta_k = -half + (k + 1/2) step. A sample of the realistic beam
// stands for a cell of solid angle cos(theta) dtheta dphi, so its weight is the beam's power
// times cos(theta); its energy is scaled by dtheta / A (A the -3 dB aperture) and shared among
// the beam's sub-rays, so that a wall filling the aperture returns about one unit per unit of
// gain whatever the step.
#pragma once

#include <Eigen/Core>

namespace sonarcarve {

struct ElevationFan {
  double half_rad = 0.0;  ///< traced on each side of the axis
  int count = 0;          ///< samples
  double step_rad = 0.0;  ///< 2 half / count

  /// Elevation of sample k (radians, positive up).
  double angle(int k) const { return -half_rad + (k + 0.5) * step_rad; }
};

/// The fan over [-half_rad, half_rad] with a step no coarser than `nominal_step_rad` (at least
/// two samples).
ElevationFan elevationFan(double half_rad, double nominal_step_rad);

/// Weight of a sample at `elevation_rad` whose beam power is `power`: the power times the
/// solid angle of its cell, cos(theta).
double solidAngleWeight(double power, double elevation_rad);

/// The energy scale of one sample: gain * dtheta / (aperture * rays).
double elevationSampleScale(double gain, double step_rad, double aperture_rad, int rays);

/// Unit direction of a ray at (bearing, elevation) in the sonar frame.
Eigen::Vector3d rayDirection(double bearing_rad, double elevation_rad);

}  // namespace sonarcarve
