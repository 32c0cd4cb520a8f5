#include "pipeline/evicting_surface.h"

#include <algorithm>
#include <chrono>

#include "carve/carving_geometry.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

EvictingSurface::EvictingSurface(std::vector<PosedFrame> frames, const SonarModel& sonar,
                                 CarveParams carve, std::uint32_t min_views, ThreadPool& pool,
                                 std::int32_t aside_gap)
    : frames_(std::move(frames)),
      carved_(frames_.size(), false),
      sonar_(sonar),
      carve_(std::move(carve)),
      min_views_(min_views),
      pool_(pool),
      aside_gap_(aside_gap),
      resolver_({}, {}, sonar, carve_) {
  resolver_.requireObservations(min_views);
}

void EvictingSurface::plan(const VoxelMap& map) {
  // What a frame touches: the bounding box of what it carves and of what occlusion resolution
  // reads (the vertical aperture), grown by two voxels for the voxels whose footprint reaches
  // into the frustum from outside it.
  const CarvingGeometry geometry(sonar_, carve_);
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(2.0 * map.voxelSize());
  std::vector<CellSpan> spans(frames_.size());
  for (std::size_t f = 0; f < frames_.size(); ++f) {
    const Eigen::Isometry3d& T = frames_[f].T_world_sonar;
    Eigen::AlignedBox3d box = geometry.frustumBounds(T);
    box.extend(geometry.frustumBounds(T, 0.5 * sonar_.verticalAperture()));
    box = Eigen::AlignedBox3d(box.min() - grow, box.max() + grow);
    Eigen::Vector3i lo, hi;
    if (map.blockSpan(box, lo, hi)) {
      const auto page = [](const Eigen::Vector3i& b) {
        return Eigen::Vector3i(b.x() / VoxelMap::kPageSide, b.y() / VoxelMap::kPageSide,
                               b.z() / VoxelMap::kPageSide);
      };
      spans[f] = {page(lo), page(hi)};
    }
  }
  schedule_ = std::make_unique<EvictionSchedule>(spans, map.pageDims(), aside_gap_);
  leaving_.assign(map.pageCount(), 0);
}

void EvictingSurface::frameCarved(std::size_t position, const Eigen::Isometry3d& T_world_sonar,
                                  VoxelMap& map) {
  if (!schedule_) {
    plan(map);
  }
  carved_[position] = true;
  frames_[position].T_world_sonar = T_world_sonar;
  peak_bytes_ = std::max(peak_bytes_, map.memoryBytes() + resolver_.memoryBytes());
  for (; next_step_ <= position; ++next_step_) {
    runStep(next_step_, map);
  }
}

void EvictingSurface::frameStarting(std::size_t position, VoxelMap& map) {
  if (!schedule_) {
    plan(map);
  }
  // Frames before it were carved or failed: what they made possible comes first, so that every
  // page is set aside before it is held again.
  for (; next_step_ < position; ++next_step_) {
    runStep(next_step_, map);
  }
  if (spill_) {
    for (std::uint32_t c : schedule_->cellsBackBefore(position)) {
      spill_->holdAgain(map, c);
    }
  }
}

void EvictingSurface::finish(VoxelMap& map) {
  if (!schedule_) {
    plan(map);
  }
  for (; next_step_ < frames_.size(); ++next_step_) {
    runStep(next_step_, map);
  }
}

void EvictingSurface::runStep(std::size_t step, VoxelMap& map) {
  const auto t0 = Clock::now();
  settle(schedule_->cellsSettledAt(step), map);
  std::vector<std::uint32_t> ready;
  for (std::uint32_t f : schedule_->framesReadyAt(step)) {
    if (carved_[f]) {
      ready.push_back(f);
    }
  }
  pool_.parallelFor(ready.size(), 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      resolver_.addView(frames_[ready[i]].T_world_sonar);
    }
  });
  const bool early = step + 1 < frames_.size();
  for (std::uint32_t c : schedule_->cellsReleasedAt(step)) {
    pages_freed_early_ += early && map.pageHeld(c) ? 1 : 0;
    map.releasePage(c);
  }
  takeSurface(schedule_->cellsFreedAt(step), map);
  for (std::uint32_t c : schedule_->cellsAsideAt(step)) {
    if (!map.pageHeld(c) || !file_problem_.empty()) {
      continue;
    }
    // A file that cannot take a page (no temporary directory, a full disk) leaves it and the
    // pages after it in memory, as without setting aside: the run goes on, and says so.
    try {
      if (!spill_) {
        spill_ = std::make_unique<PageSpill>();
      }
      spill_->setAside(map, c);
    } catch (const Error& e) {
      file_problem_ = e.what();
    }
    aside_file_bytes_ =
        std::max<std::uint64_t>(aside_file_bytes_, spill_ ? spill_->fileBytes() : 0);
  }
  occlusion_ms_ += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

void EvictingSurface::settle(const std::vector<std::uint32_t>& cells, const VoxelMap& map) {
  std::vector<Eigen::Vector3i> voxels;
  std::vector<float> values;
  std::vector<std::uint32_t> seeing;  // frames that touch one of the cells
  std::vector<OccupancyBlock> blocks;
  for (std::uint32_t c : cells) {
    if (!map.pageHeld(c)) {
      continue;
    }
    map.forEachOccupiedOnShellIn(c, [&](const Eigen::Vector3i& v, float value) {
      voxels.push_back(v);
      values.push_back(value);
    });
    blocks.clear();
    collectOccupancyBlocks(map, c, blocks);
    occupancy_.add(blocks);
    for (std::size_t b = std::size_t{c} * VoxelMap::kPageBlocks;
         b < (std::size_t{c} + 1) * VoxelMap::kPageBlocks; ++b) {
      if (const float* v = map.values(b)) {
        occupied_voxels_ +=
            static_cast<std::size_t>(std::count_if(v, v + VoxelMap::kBlockVoxels, [](float x) {
              return x > 0.0f && x < VoxelMap::kUnknown;
            }));
      }
    }
    const Eigen::Vector3i cell = schedule_->cellCoords(c);
    for (auto f = static_cast<std::size_t>(schedule_->first(c));
         f <= static_cast<std::size_t>(schedule_->last(c)); ++f) {
      if (carved_[f] && schedule_->span(f).contains(cell)) {
        seeing.push_back(static_cast<std::uint32_t>(f));
      }
    }
  }
  if (voxels.empty()) {
    return;
  }
  std::sort(seeing.begin(), seeing.end());
  seeing.erase(std::unique(seeing.begin(), seeing.end()), seeing.end());
  const std::size_t first_group = resolver_.addVoxels(voxels, values);
  pool_.parallelFor(seeing.size(), 4, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      resolver_.countObservations(frames_[seeing[i]].T_world_sonar, first_group);
    }
  });
}

void EvictingSurface::takeSurface(const std::vector<std::uint32_t>& cells, const VoxelMap& map) {
  if (cells.empty()) {
    return;
  }
  for (std::uint32_t c : cells) {
    leaving_[c] = 1;
  }
  const Eigen::Vector3i first_block = map.firstBlock();
  const SurfacePoints points = resolver_.takeBlocks(
      [&](const Eigen::Vector3i& block) {
        const Eigen::Vector3i rel = block - first_block;
        return leaving_[map.pageIndex(Eigen::Vector3i(rel.x() / VoxelMap::kPageSide,
                                                      rel.y() / VoxelMap::kPageSide,
                                                      rel.z() / VoxelMap::kPageSide))] != 0;
      },
      min_views_);
  surface_.insert(surface_.end(), points.begin(), points.end());
  for (std::uint32_t c : cells) {
    leaving_[c] = 0;
  }
}

SurfacePoints EvictingSurface::surface() const {
  SurfacePoints sorted = surface_;
  const double voxel = carve_.voxel_size_m;
  const auto index = [voxel](const SurfacePoint& p) {
    return (p.position_m.cast<double>() / voxel).array().floor().cast<int>().matrix().eval();
  };
  std::sort(sorted.begin(), sorted.end(), [&](const SurfacePoint& a, const SurfacePoint& b) {
    return voxelOrderLess(index(a), index(b));
  });
  return sorted;
}

}  // namespace sonarcarve
