// SonarSimulator: forms noise-free polar images of a Scene, following the seed paper's imaging
// model. Each pixel (range, bearing) sums, over elevation, the returns of the first surface
// along each ray, weighted by the beam's power pattern p(theta), the Lambertian term
// cos(incidence) and the surface reflectivity:
//
//   I(r, phi) = gain * sum over rays in the pixel of  R * cos(incidence) * p(theta) * dtheta / A
//
// Two beams (ImagingSettings::beam):
// - Realistic: p is sinc^2 (-3 dB at +-aperture/2, sonar/beam_pattern.h) times cos(theta), the
//   solid angle of a ray's cell, traced in elevation past the main lobe to the null after the
//   last traced side lobe (the second null, +-45.2 degrees for a 20 degree aperture, by
//   default), or another family of elevation pattern (ImagingSettings::elevation_beam,
//   sim/elevation_pattern.h) traced as far as it reaches; in bearing each beam also takes the rays
//   of its neighbours, weighted by a sinc^2 of the horizontal beam width, to the same null (bearing
//   leakage), rays being traced past the fan's edges for the outer beams.
// - Clipped: the seed paper's model, p = the sinc of BeamPattern over |theta| <= aperture/2
//   only, each ray in its own beam.
//
// Rays are cast `rays_per_beam` times per beam and every `elevation_step_rad`; between two
// consecutive elevations that hit the same continuous surface, the return is spread over the
// ranges between the two hits, so that surfaces seen at grazing angles (a seabed) give no
// striping. Only the first surface along a ray returns, so objects cast acoustic shadows.
// Thread safe: render() may run concurrently with other render() calls.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <vector>

#include "common/thread_pool.h"
#include "model/elevation_fan.h"
#include "sim/elevation_pattern.h"
#include "sim/ray_caster.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

enum class SimulatedBeam { Clipped, Realistic };

/// "clipped" / "realistic", and back (throws Error on other names).
std::string beamName(SimulatedBeam beam);
SimulatedBeam beamFromName(const std::string& name);

struct ImagingSettings {
  double elevation_step_rad = 0.1 * 3.14159265358979323846 / 180.0;  ///< ray spacing in theta
  int rays_per_beam = 2;  ///< rays across each beam's bearing interval
  /// Counts for a full aperture of unit, normal returns. High enough that the weak returns
  /// of a seabed at grazing incidence (thousandths of a facing wall's, spread over many
  /// range bins) survive the rounding to whole counts of 16-bit frames.
  double gain = 20000.0;
  double spreading_exponent = 0.0;  ///< intensity times r^-k (spreading loss); 0 = off
  double tvg_exponent = 0.0;        ///< intensity times r^k (range-dependent gain); 0 = off
  /// Hits reported as seen (HitSink) need at least this cos(incidence): a surface met at more
  /// than 78 degrees returns under a fifth of a facing one and cannot be placed in elevation
  /// (its returns span a fraction of an elevation step), so no reconstruction recovers it.
  double visible_min_cos_incidence = 0.2;
  /// The beam model (see the top of this file). Realistic by default: real sonars put energy
  /// into their images from outside the -3 dB aperture, and the engine is judged on that.
  SimulatedBeam beam = SimulatedBeam::Realistic;
  /// Realistic beam: side lobes traced on each side, in elevation and in bearing; the traced
  /// extent ends at the null after the last of them (>= 0; 0 = the main lobe only).
  int side_lobes = 1;
  /// Realistic beam: the pattern in elevation (sim/elevation_pattern.h); sinc2 by default.
  /// The clipped beam takes only sinc2 (which it ignores).
  ElevationBeamSpec elevation_beam;
  /// Realistic beam: -3 dB width of each beam in bearing; 0 = its spacing in the bearing table.
  double horizontal_beam_width_rad = 0.0;
  /// Hits reported as seen (HitSink) lie inside the elevation main lobe where its power is at
  /// least this level (dB, < 0): -3 dB = |theta| <= aperture/2, where the engines back-project.
  double visible_beam_level_db = -3.0;
  /// The seen points are thinned to one per cell of this side (sim/visible_surface.h); 0: none
  /// kept. They grow with the area seen: at 1 cm, about 0.6 MB of memory per square metre of
  /// seabed a long survey sees (docs/simulator.md, "The seabed field").
  double visible_cell_m = 0.01;
};

/// Called with the surface points rays hit inside the sonar's window (world frame), when the
/// hit is not grazing (ImagingSettings::visible_min_cos_incidence) and lies inside the
/// visible part of the beam (ImagingSettings::visible_beam_level_db): a batch of neighbouring
/// rays' hits at a time, from several threads at once (it must be thread safe).
using HitSink = std::function<void(std::span<const Eigen::Vector3f> p_world)>;

class SonarSimulator {
 public:
  /// Renders each frame's beams in parallel on `pool`.
  SonarSimulator(const RayCaster& caster, const SonarModel& sonar, ImagingSettings settings,
                 ThreadPool& pool);

  /// Noise-free CV_32F image seen from `T_world_sonar`. If `hits` is set it receives every
  /// surface point seen (HitSink).
  cv::Mat render(const Eigen::Isometry3d& T_world_sonar, const HitSink& hits = {}) const;

  const ImagingSettings& settings() const { return settings_; }
  std::size_t raysPerFrame() const { return directions_.size(); }
  /// Elevation traced on each side of the axis, radians.
  double tracedElevation() const { return traced_elevation_rad_; }

 private:
  void traceBearings(const SonarModel& sonar);
  void addBearingLeakage(const SonarModel& sonar);
  /// Realistic beam: each beam's column from its taps' sub-ray columns (both held transposed,
  /// a row of range bins per column).
  cv::Mat leak(const cv::Mat& ray_columns) const;

  const RayCaster& caster_;
  const SonarModel& sonar_;
  ImagingSettings settings_;
  ThreadPool& pool_;
  ElevationFan fan_;  // the elevation samples of every beam (model/elevation_fan.h)
  int elevations_ = 0;
  double traced_elevation_rad_ = 0.0;
  float sample_scale_ = 0.0f;                // gain * dtheta / (A * rays_per_beam)
  std::vector<Eigen::Vector3f> directions_;  // sonar frame; [traced beam][sub-ray][elevation]
  std::vector<float> beam_weight_;           // p(theta) per elevation sample
  std::vector<char> visible_elevation_;      // per elevation sample: hits there are "seen"
  // Realistic beam: beams traced beyond each edge of the fan (for the outer beams' leakage),
  // and for every image beam its taps over the traced sub-ray columns.
  int pad_beams_ = 0;
  std::vector<int> tap_first_;   // first sub-ray column of each beam's taps
  std::vector<int> tap_offset_;  // start of each beam's weights in tap_weight_ (cols + 1)
  std::vector<float> tap_weight_;
};

}  // namespace sonarcarve
