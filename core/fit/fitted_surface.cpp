#include "fit/fitted_surface.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <unordered_map>

#include "model/elevation_fan.h"
#include "model/ray_march.h"
#include "model/voxel_stencil.h"

namespace sonarcarve {
namespace {

struct Crossings {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double reflectance = 0.0;
  std::size_t count = 0;
  std::uint32_t views = 0;
  std::size_t last_frame = static_cast<std::size_t>(-1);
};

using CrossingMap = std::unordered_map<std::int64_t, Crossings>;

std::int64_t voxelKey(const BlockGrid& grid, const Eigen::Vector3d& p) {
  Eigen::Vector3i voxel;
  if (!grid.voxelOf(p, voxel)) {
    return -1;
  }
  const std::int64_t index = grid.voxelIndex(voxel);
  return index;
}

// Where the ray's transmittance falls through 1/2, if it does: within the sample (length ds
// around its range) that takes it there, as if it fell exponentially across the sample.
bool halfCrossing(const std::vector<RaySample>& samples, double ds, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& direction, Eigen::Vector3d& at, double& reflectance) {
  for (const RaySample& s : samples) {
    const double after = s.transmittance * (1.0 - s.alpha);
    if (after <= 0.5) {
      const double drop = std::log(s.transmittance / std::max(after, 1e-300));
      const double share = drop > 0.0 ? std::log(s.transmittance / 0.5) / drop : 0.5;
      at = origin + (s.range_m + (share - 0.5) * ds) * direction;
      reflectance = s.reflectance;
      return true;
    }
  }
  return false;
}

}  // namespace

SurfacePoints fittedSurface(const BlockGrid& grid, const SonarModel& sonar,
                            const std::vector<MapFitFrame>& frames, const MapFitParams& params,
                            std::uint32_t min_views, ThreadPool& pool, Progress& progress) {
  const double half = 0.5 * sonar.verticalAperture();
  const ElevationFan fan = elevationFan(half, params.elevation_step_rad);
  const double ds = sonar.range().resolution_m / params.samples_per_bin;
  const MarchLimits limits{sonar.range(), params.samples_per_bin, 1e-3, 1e-4};
  const ActiveCells active = ActiveCells::reaching(grid, limits.min_alpha);
  CrossingMap merged;
  std::mutex merge_mutex;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (progress.cancelled()) {
      throw Cancelled();
    }
    const Eigen::Isometry3d& pose = frames[f].T_world_sonar;
    const Eigen::Vector3d origin = pose.translation();
    pool.parallelFor(static_cast<std::size_t>(sonar.cols()), 8,
                     [&](std::size_t begin, std::size_t end) {
                       CrossingMap local;
                       StencilReader reader(grid, &active);
                       std::vector<RaySample> samples;
                       for (auto b = begin; b < end; ++b) {
                         const double bearing = sonar.bearings().centre(static_cast<int>(b));
                         for (int k = 0; k < fan.count; ++k) {
                           const Eigen::Vector3d d_sonar = rayDirection(bearing, fan.angle(k));
                           const Eigen::Vector3d d = pose.linear() * d_sonar;
                           marchRay(reader, grid.voxelSize(), origin, d, d_sonar, limits, samples);
                           Eigen::Vector3d at;
                           double reflectance = 0.0;
                           if (!halfCrossing(samples, ds, origin, d, at, reflectance)) {
                             continue;
                           }
                           const std::int64_t key = voxelKey(grid, at);
                           if (key < 0) {
                             continue;
                           }
                           Crossings& c = local[key];
                           c.sum += at;
                           c.reflectance += reflectance;
                           ++c.count;
                         }
                       }
                       const std::lock_guard lock(merge_mutex);
                       for (const auto& [key, c] : local) {
                         Crossings& m = merged[key];
                         m.sum += c.sum;
                         m.reflectance += c.reflectance;
                         m.count += c.count;
                         if (m.last_frame != f) {
                           m.last_frame = f;
                           ++m.views;
                         }
                       }
                     });
    progress.report("fitted surface", f + 1, frames.size());
  }
  std::vector<std::int64_t> keys;  // in order, so that the points are the same every run
  for (const auto& [key, c] : merged) {
    if (c.views >= min_views) {
      keys.push_back(key);
    }
  }
  std::sort(keys.begin(), keys.end());
  SurfacePoints points;
  for (const std::int64_t key : keys) {
    const Crossings& c = merged.at(key);
    SurfacePoint point;
    point.position_m = (c.sum / static_cast<double>(c.count)).cast<float>();
    point.intensity = static_cast<float>(c.reflectance / static_cast<double>(c.count));
    point.views = c.views;
    points.push_back(point);
  }
  return points;
}

}  // namespace sonarcarve
