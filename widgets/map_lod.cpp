#include "map_lod.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

#include "carve/voxel_map.h"

namespace sonarcarve::widgets {

static_assert(1 << MapLod::kBlockLevel == VoxelMap::kBlockSide,
              "one point per block is the level of cells as wide as a block");

namespace {

// The cell of `level` that holds `p` (all of a block's points share one at kBlockLevel).
std::array<int, 3> cellOf(const Eigen::Vector3f& p, int level, double voxel_size_m) {
  if (level >= MapLod::kBlockLevel) {
    return {0, 0, 0};
  }
  const double cell_m = voxel_size_m * static_cast<double>(1 << level);
  return {static_cast<int>(std::floor(p.x() / cell_m)),
          static_cast<int>(std::floor(p.y() / cell_m)),
          static_cast<int>(std::floor(p.z() / cell_m))};
}

}  // namespace

MapViewBlock coarsened(const MapViewBlock& block, int level, double voxel_size_m) {
  const std::size_t n = block.points.size();
  std::vector<std::array<int, 3>> cells(n);
  for (std::size_t k = 0; k < n; ++k) {
    cells[k] = cellOf(block.points[k], level, voxel_size_m);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cells[a] < cells[b]; });
  const bool with_errors = block.errors_m.size() == n;
  MapViewBlock out;
  out.block = block.block;
  out.frames_done = block.frames_done;
  out.level = std::max(block.level, level);
  for (std::size_t first = 0; first < n;) {
    std::size_t last = first;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    double value = 0.0;
    double error = 0.0;
    std::size_t voxels = 0;
    // Each point weighs the voxels it already stands for: the means are the voxels' own.
    for (; last < n && cells[order[last]] == cells[order[first]]; ++last) {
      const std::size_t k = order[last];
      const auto w = static_cast<double>(block.voxelsAt(k));
      position += w * block.points[k].cast<double>();
      value += w * (k < block.values.size() ? block.values[k] : 0.0f);
      error += with_errors ? w * block.errors_m[k] : 0.0;
      voxels += block.voxelsAt(k);
    }
    const auto total = static_cast<double>(voxels);
    out.points.push_back((position / total).cast<float>());
    out.values.push_back(static_cast<float>(value / total));
    if (with_errors) {
      out.errors_m.push_back(static_cast<float>(error / total));
    }
    out.voxels.push_back(static_cast<std::uint32_t>(voxels));
    first = last;
  }
  return out;
}

MapLod::MapLod(std::size_t max_points, double voxel_size_m)
    : max_points_(max_points), voxel_size_m_(voxel_size_m) {}

void MapLod::setMaxPoints(std::size_t max_points) {
  max_points_ = max_points;
  keepWithinBudget();
}

void MapLod::apply(std::vector<MapViewBlock> blocks) {
  for (MapViewBlock& b : blocks) {
    if (auto held = blocks_.find(b.block); held != blocks_.end()) {
      points_ -= held->second.points.size();
      voxels_ -= held->second.voxelCount();
      blocks_.erase(held);
    }
    if (!b.points.empty()) {
      points_ += b.points.size();
      voxels_ += b.voxelCount();
      blocks_[b.block] = std::move(b);
    }
  }
  if (points_ > max_points_) {
    keepWithinBudget();
  }
}

MapLod::Blocks MapLod::take() {
  Blocks taken;
  taken.swap(blocks_);
  points_ = 0;
  voxels_ = 0;
  return taken;
}

void MapLod::setLevel(MapViewBlock& block, int level) {
  points_ -= block.points.size();
  block = coarsened(block, level, voxel_size_m_);
  points_ += block.points.size();
}

void MapLod::keepWithinBudget() {
  if (points_ <= max_points_) {
    return;
  }
  // Back under nine tenths of the budget, so that the next updates do not start this again.
  const std::size_t target = max_points_ - max_points_ / 10;
  for (int level = 1; level <= kBlockLevel && points_ > target; ++level) {
    // The blocks changed longest ago first: those the survey has left.
    std::vector<std::tuple<std::size_t, std::size_t, MapViewBlock*>> finer;
    for (auto& [id, b] : blocks_) {
      if (b.level < level) {
        finer.emplace_back(b.frames_done, id, &b);
      }
    }
    std::sort(finer.begin(), finer.end(), [](const auto& a, const auto& b) {
      return std::tie(std::get<0>(a), std::get<1>(a)) < std::tie(std::get<0>(b), std::get<1>(b));
    });
    for (const auto& entry : finer) {
      if (points_ <= target) {
        break;
      }
      setLevel(*std::get<2>(entry), level);
    }
  }
}

}  // namespace sonarcarve::widgets
