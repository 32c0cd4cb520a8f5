#include "occlusion/occlusion_resolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace sonarcarve {

bool voxelOrderLess(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
  const auto key = [](const Eigen::Vector3i& v) {
    // floor division by 8, then the place in the block
    return std::make_tuple(v.z() >> 3, v.y() >> 3, v.x() >> 3, v.z() & 7, v.y() & 7, v.x() & 7);
  };
  return key(a) < key(b);
}

OcclusionResolver::OcclusionResolver(const std::vector<Eigen::Vector3i>& voxels,
                                     const std::vector<float>& values, const SonarModel& sonar,
                                     const CarveParams& params)
    : geometry_(sonar, params), voxel_size_m_(params.voxel_size_m) {
  elevation_step_ = params.elevation_step_rad;
  elevation_bins_ =
      std::max(1, static_cast<int>(std::ceil(sonar.verticalAperture() / elevation_step_)));
  block_radius_ = 0.5 * std::sqrt(3.0) * VoxelMap::kBlockSide * voxel_size_m_;
  addGroups(voxels, values);
}

std::size_t OcclusionResolver::addVoxels(const std::vector<Eigen::Vector3i>& voxels,
                                         const std::vector<float>& values) {
  const std::size_t first = groups();
  addGroups(voxels, values);
  return first;
}

void OcclusionResolver::addGroups(const std::vector<Eigen::Vector3i>& voxels,
                                  const std::vector<float>& values) {
  // Group the voxels by block of 8^3 so that whole groups are culled against each frustum.
  const auto blockOf = [](const Eigen::Vector3i& v) {
    return Eigen::Vector3i(v.x() >> 3, v.y() >> 3, v.z() >> 3);  // floor division by 8
  };
  std::vector<std::size_t> order(voxels.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return voxelOrderLess(voxels[a], voxels[b]); });
  const double block = VoxelMap::kBlockSide * voxel_size_m_;
  for (std::size_t n = 0; n < order.size(); ++n) {
    const Eigen::Vector3i& v = voxels[order[n]];
    if (n == 0 || blockOf(v) != block_keys_.back()) {
      if (n > 0) {
        block_begin_.push_back(static_cast<std::uint32_t>(centres_.size()));
      }
      block_keys_.push_back(blockOf(v));
      block_centres_.push_back(
          ((blockOf(v).cast<double>() + Eigen::Vector3d::Constant(0.5)) * block).cast<float>());
    }
    centres_.push_back(
        ((v.cast<double>() + Eigen::Vector3d::Constant(0.5)) * voxel_size_m_).cast<float>());
    voxels_.push_back(v);
    intensities_.push_back(values[order[n]]);
  }
  if (!order.empty()) {
    block_begin_.push_back(static_cast<std::uint32_t>(centres_.size()));
  }
  views_.resize(centres_.size(), 0);
  observed_.resize(centres_.size(), 0);
}

SurfacePoints OcclusionResolver::takeBlocks(
    const std::function<bool(const Eigen::Vector3i&)>& leaves, std::uint32_t min_views) {
  SurfacePoints taken;
  std::size_t kept_voxels = 0;
  std::size_t kept_groups = 0;
  std::vector<std::uint32_t> begin{0};
  for (std::size_t g = 0; g < groups(); ++g) {
    const std::uint32_t b = block_begin_[g];
    const std::uint32_t e = block_begin_[g + 1];
    if (leaves(block_keys_[g])) {
      for (std::uint32_t i = b; i < e; ++i) {
        if (views_[i] >= min_views && views_[i] > 0) {
          taken.push_back({centres_[i], intensities_[i], views_[i]});
        }
      }
      continue;
    }
    for (std::uint32_t i = b; i < e; ++i, ++kept_voxels) {
      centres_[kept_voxels] = centres_[i];
      intensities_[kept_voxels] = intensities_[i];
      voxels_[kept_voxels] = voxels_[i];
      views_[kept_voxels] = views_[i];
      observed_[kept_voxels] = observed_[i];
    }
    block_keys_[kept_groups] = block_keys_[g];
    block_centres_[kept_groups] = block_centres_[g];
    begin.push_back(static_cast<std::uint32_t>(kept_voxels));
    ++kept_groups;
  }
  centres_.resize(kept_voxels);
  intensities_.resize(kept_voxels);
  voxels_.resize(kept_voxels);
  views_.resize(kept_voxels);
  observed_.resize(kept_voxels);
  block_keys_.resize(kept_groups);
  block_centres_.resize(kept_groups);
  block_begin_ = std::move(begin);
  return taken;
}

template <typename F>
void OcclusionResolver::forEachVoxelInView(const Eigen::Isometry3d& T_world_sonar,
                                           std::size_t first_group, F&& f) const {
  const SonarModel& sonar = geometry_.sonar();
  const Eigen::Isometry3d T_sonar_world = T_world_sonar.inverse();
  const Eigen::Matrix3f R = T_sonar_world.linear().cast<float>();
  const Eigen::Vector3f t = T_sonar_world.translation().cast<float>();
  const float half_aperture = static_cast<float>(0.5 * sonar.verticalAperture());
  const float voxel_radius = static_cast<float>(0.5 * std::sqrt(3.0) * voxel_size_m_);
  const float rmin = static_cast<float>(geometry_.rangeMin());
  const float rmax = static_cast<float>(geometry_.rangeMax());
  for (std::size_t g = first_group; g + 1 < block_begin_.size(); ++g) {
    if (!geometry_.sphereMayTouchFrustum((R * block_centres_[g] + t).cast<double>(),
                                         block_radius_)) {
      continue;
    }
    for (std::uint32_t i = block_begin_[g]; i < block_begin_[g + 1]; ++i) {
      const Eigen::Vector3f p = R * centres_[i] + t;
      const float r = p.norm();
      if (r < rmin || r >= rmax || r <= voxel_radius) {
        continue;
      }
      const float elevation = std::asin(std::clamp(-p.z() / r, -1.0f, 1.0f));
      const float spread = std::asin(voxel_radius / r);
      if (std::abs(elevation) - spread > half_aperture) {
        continue;
      }
      f(i, r, fastAtan2(p.y(), p.x()), elevation, spread);
    }
  }
}

void OcclusionResolver::countObservations(const Eigen::Isometry3d& T_world_sonar,
                                          std::size_t first_group) {
  forEachVoxelInView(T_world_sonar, first_group,
                     [&](std::uint32_t i, float, float bearing, float, float) {
                       if (geometry_.beamOf(bearing) >= 0) {
                         std::atomic_ref(observed_[i]).fetch_add(1, std::memory_order_relaxed);
                       }
                     });
}

void OcclusionResolver::requireObservations(std::uint32_t views) {
  required_observations_ = views;
}

std::vector<OcclusionResolver::Cell> OcclusionResolver::zBuffer(
    const Eigen::Isometry3d& T_world_sonar) const {
  const int beams = geometry_.sonar().cols();
  const int bins = elevation_bins_;
  std::vector<Cell> zbuffer(static_cast<std::size_t>(beams * bins));
  const float half_aperture = static_cast<float>(0.5 * geometry_.sonar().verticalAperture());
  const float inv_step = static_cast<float>(1.0 / elevation_step_);
  forEachVoxelInView(
      T_world_sonar, 0,
      [&](std::uint32_t i, float r, float bearing, float elevation, float spread) {
        // Counting is done before frames resolve (no thread writes observed_ meanwhile).
        if (required_observations_ > 0 && observed_[i] < required_observations_) {
          return;
        }
        // Splat the voxel's angular footprint over the cells it covers; the nearest wins.
        int beam_lo = geometry_.beamOf(bearing - spread);
        int beam_hi = geometry_.beamOf(bearing + spread);
        if (beam_lo < 0 && beam_hi < 0) {
          return;
        }
        beam_lo = beam_lo < 0 ? 0 : beam_lo;
        beam_hi = beam_hi < 0 ? beams - 1 : beam_hi;
        const int e_lo =
            std::max(0, static_cast<int>((elevation - spread + half_aperture) * inv_step));
        const int e_hi =
            std::min(bins - 1, static_cast<int>((elevation + spread + half_aperture) * inv_step));
        for (int j = beam_lo; j <= beam_hi; ++j) {
          Cell* row = &zbuffer[static_cast<std::size_t>(j * bins)];
          for (int e = e_lo; e <= e_hi; ++e) {
            if (row[e].voxel < 0 || r < row[e].range ||
                (r == row[e].range && voxelOrderLess(voxels_[i], voxels_[row[e].voxel]))) {
              row[e] = {r, static_cast<std::int32_t>(i)};
            }
          }
        }
      });
  return zbuffer;
}

std::vector<float> OcclusionResolver::firstReturnRanges(
    const Eigen::Isometry3d& T_world_sonar) const {
  const std::vector<Cell> zbuffer = zBuffer(T_world_sonar);
  std::vector<float> ranges(zbuffer.size(), std::numeric_limits<float>::infinity());
  for (std::size_t i = 0; i < zbuffer.size(); ++i) {
    if (zbuffer[i].voxel >= 0) {
      ranges[i] = zbuffer[i].range;
    }
  }
  return ranges;
}

void OcclusionResolver::addView(const Eigen::Isometry3d& T_world_sonar) {
  const std::vector<Cell> zbuffer = zBuffer(T_world_sonar);
  // Each voxel that won at least one cell gains one view. Several cells may name the same
  // voxel: count it once per frame.
  std::vector<std::int32_t> winners;
  for (const Cell& c : zbuffer) {
    if (c.voxel >= 0) {
      winners.push_back(c.voxel);
    }
  }
  std::sort(winners.begin(), winners.end());
  winners.erase(std::unique(winners.begin(), winners.end()), winners.end());
  for (std::int32_t w : winners) {
    std::atomic_ref(views_[static_cast<std::size_t>(w)]).fetch_add(1, std::memory_order_relaxed);
  }
}

std::size_t OcclusionResolver::memoryBytes() const {
  return centres_.capacity() * sizeof(Eigen::Vector3f) + intensities_.capacity() * sizeof(float) +
         voxels_.capacity() * sizeof(Eigen::Vector3i) +
         block_centres_.capacity() * sizeof(Eigen::Vector3f) +
         block_keys_.capacity() * sizeof(Eigen::Vector3i) +
         block_begin_.capacity() * sizeof(std::uint32_t) +
         (views_.capacity() + observed_.capacity()) * sizeof(std::uint32_t);
}

SurfacePoints OcclusionResolver::result(std::uint32_t min_views) const {
  SurfacePoints points;
  for (std::size_t i = 0; i < centres_.size(); ++i) {
    const std::uint32_t v = views_[i];
    if (v >= min_views && v > 0) {
      points.push_back({centres_[i], intensities_[i], v});
    }
  }
  return points;
}

}  // namespace sonarcarve
