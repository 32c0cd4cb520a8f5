#include "carve/shadow_limit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sonarcarve {

ShadowLimits shadowLimits(const cv::Mat& pixels, const Eigen::Isometry3d& T_world_sonar,
                          const VoxelMap& map, const CarvingGeometry& geometry,
                          const ShadowLimitSetup& setup, ThreadPool& pool) {
  const SonarModel& sonar = geometry.sonar();
  const int bins = visibilityBins(setup.half_elevation_rad, setup.elevation_step_rad);
  const int beams = sonar.cols();
  const double step = 2.0 * setup.half_elevation_rad / bins;
  const double aperture_half = 0.5 * sonar.verticalAperture();
  ShadowLimits out;
  out.elevation_bins = bins;
  out.elevation_step_rad = step;
  std::vector<float>& limits = out.first_return_m;
  limits.assign(static_cast<std::size_t>(beams) * static_cast<std::size_t>(bins),
                std::numeric_limits<float>::infinity());
  // Per bin: its elevation's cosine, sine and the beam's inverse gain there.
  std::vector<double> cos_el(static_cast<std::size_t>(bins)), sin_el(cos_el.size());
  std::vector<float> inverse_gain(cos_el.size(), 1.0f);
  std::vector<bool> in_reach(cos_el.size(), true);
  for (int k = 0; k < bins; ++k) {
    const double el = -setup.half_elevation_rad + (k + 0.5) * step;
    cos_el[k] = std::cos(el);
    sin_el[k] = std::sin(el);
    if (setup.beam_aware) {
      inverse_gain[k] = geometry.inverseGain(static_cast<float>(std::abs(sin_el[k])));
    } else {
      in_reach[k] = std::abs(el) <= aperture_half;
    }
  }
  const int rows = std::min(pixels.rows, sonar.rows());
  const Eigen::Matrix3d R = T_world_sonar.linear();
  const Eigen::Vector3d origin = T_world_sonar.translation();
  const double voxel_size = map.voxelSize();
  pool.parallelFor(static_cast<std::size_t>(beams), 8, [&](std::size_t begin, std::size_t end) {
    std::vector<char> open(static_cast<std::size_t>(bins));
    std::vector<Eigen::Vector3d> direction(static_cast<std::size_t>(bins));  // world, unit
    for (std::size_t b = begin; b < end; ++b) {
      const int beam = static_cast<int>(b);
      const double bearing = sonar.bearings().centre(beam);
      const double cb = std::cos(bearing), sb = std::sin(bearing);
      for (int k = 0; k < bins; ++k) {
        direction[k] = R * Eigen::Vector3d(cos_el[k] * cb, cos_el[k] * sb, -sin_el[k]);
      }
      float* limit = limits.data() + b * static_cast<std::size_t>(bins);
      std::fill(open.begin(), open.end(), char{1});
      int left = bins;
      for (int row = 0; row < rows && left > 0; ++row) {
        const float intensity = pixels.at<float>(row, beam);
        if (!(intensity > 0.0f)) {
          continue;
        }
        const double r = sonar.range().centre(row);
        if (r < geometry.rangeMin() || r >= geometry.rangeMax()) {
          continue;
        }
        for (int k = 0; k < bins; ++k) {
          if (!open[k] || !in_reach[k]) {
            continue;
          }
          if (setup.beam_aware && intensity * inverse_gain[k] <= setup.keep_level) {
            continue;  // no surface above the keep level could light this pixel from there
          }
          const Eigen::Vector3d voxel = ((origin + r * direction[k]) / voxel_size).array().floor();
          const float value = map.value(voxel.cast<int>());
          if (value == 0.0f || (value == VoxelMap::kUnknown && !setup.unknown_may_hide)) {
            continue;  // carved: empty water, whatever lit the pixel is elsewhere on the arc
          }
          limit[k] = static_cast<float>(r);
          open[k] = 0;
          --left;
        }
      }
    }
  });
  return out;
}

}  // namespace sonarcarve
