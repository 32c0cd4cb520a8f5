// SonarSimulator: forms noise-free polar images of a Scene, following the seed paper's imaging
// model. Each pixel (range, bearing) sums, over the elevations of the vertical aperture
// (|theta| <= aperture/2), the returns of the first surface along each ray, weighted by the
// beam pattern b(theta), the Lambertian term cos(incidence) and the surface reflectivity:
//
//   I(r, phi) = gain * sum over rays in the pixel of  R * cos(incidence) * b(theta) * dtheta / A
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
#include <vector>

#include "common/thread_pool.h"
#include "sim/ray_caster.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

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
};

/// Called with each surface point a ray hit inside the sonar's window (world frame), when the
/// hit is not grazing (ImagingSettings::visible_min_cos_incidence).
using HitSink = std::function<void(const Eigen::Vector3f& p_world)>;

class SonarSimulator {
 public:
  /// Renders each frame's beams in parallel on `pool`.
  SonarSimulator(const RayCaster& caster, const SonarModel& sonar, ImagingSettings settings,
                 ThreadPool& pool);

  /// Noise-free CV_32F image seen from `T_world_sonar`. If `hits` is set it receives every
  /// surface point seen (called from several threads, one at a time under a lock).
  cv::Mat render(const Eigen::Isometry3d& T_world_sonar, const HitSink& hits = {}) const;

  const ImagingSettings& settings() const { return settings_; }
  std::size_t raysPerFrame() const { return directions_.size(); }

 private:
  const RayCaster& caster_;
  const SonarModel& sonar_;
  ImagingSettings settings_;
  ThreadPool& pool_;
  int elevations_ = 0;
  std::vector<Eigen::Vector3f> directions_;  // sonar frame; [beam][sub-ray][elevation]
  std::vector<float> beam_weight_;           // b(theta) per elevation sample
};

}  // namespace sonarcarve
