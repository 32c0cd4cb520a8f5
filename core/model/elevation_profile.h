// ElevationProfile: the elevation beam pattern as the forward model fits it, a smooth profile
// symmetric in elevation given by n >= 3 knots in dB at |theta| = theta_max * m / (n - 1),
// m = 0 .. n-1, joined by a uniform Catmull-Rom spline in |theta|. The spline is mirrored
// about theta = 0 (so the profile is smooth there) and continued linearly past the last knot.
// Power p(theta) = 10^(dB(theta) / 10). Each value is a fixed linear combination of at most
// four knots, so d p / d knot is p ln(10) / 10 times the spline weight (profileWeights).
// A Catmull-Rom spline reproduces a quadratic exactly: a gaussian (a parabola in dB) is a
// profile of this family, up to the last segment.
#pragma once

#include <array>
#include <vector>

#include "sonar/beam_pattern.h"

namespace sonarcarve {

/// The knots that one profile value depends on and their weights in it.
struct ProfileWeights {
  std::array<int, 4> knot{};
  std::array<double, 4> weight{};
};

class ElevationProfile {
 public:
  /// Throws Error unless theta_max_rad > 0 and there are at least 3 finite knots.
  ElevationProfile(double theta_max_rad, std::vector<double> knots_db);

  /// The realistic array's sinc^2 pattern of -3 dB aperture `aperture_rad`, traced to
  /// `theta_max_rad`, with `knots` knots; levels below `floor_db` (the nulls) are raised to it.
  static ElevationProfile sincSquared(double aperture_rad, double theta_max_rad, int knots,
                                      double floor_db = -40.0);
  /// The seed paper's clipped pattern (BeamPattern: a sinc main lobe, nothing past its first
  /// null), floored at `floor_db` where it is zero.
  static ElevationProfile clipped(const BeamPattern& pattern, double theta_max_rad, int knots,
                                  double floor_db = -40.0);

  double thetaMax() const { return theta_max_rad_; }
  const std::vector<double>& knotsDb() const { return knots_db_; }
  std::vector<double>& knotsDb() { return knots_db_; }
  double knotAngle(int m) const;

  /// The spline's knots and weights at elevation `theta_rad` (|theta| clamped to theta_max).
  ProfileWeights weights(double theta_rad) const;
  /// Level in dB and power at `theta_rad`.
  double levelDb(double theta_rad) const;
  double power(double theta_rad) const;
  /// Full width (radians) of the main lobe at `level_db` below the level on the axis: twice
  /// the first |theta| where the profile falls that far (thetaMax if it never does).
  double width(double level_db) const;

 private:
  double theta_max_rad_;
  std::vector<double> knots_db_;
};

}  // namespace sonarcarve
