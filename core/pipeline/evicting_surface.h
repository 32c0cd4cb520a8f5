// Occlusion resolution and the surface of a run that lets finished regions of its map go
// (eviction, docs/scaling.md): with every pose known before carving, an EvictionSchedule says
// after which carved frame each cell (a page of the block table, 8^3 blocks) is final, each
// frame's occlusion can run, and each cell's surface is final. After each carved frame this
// takes the candidates of the cells that became final (occupied voxels on the shell) and their
// .bt export blocks into an OcclusionResolver and counts the frames that see them, releases the
// map's pages that no frame carves and no neighbour reads any more, resolves the frames that
// became ready, and takes the surface points of the cells every frame seeing them has resolved. The
// surface is the in-memory path's, point for point: the same voxels are candidates, counted by the
// same frames and resolved against the same occluders. Pages the survey leaves and comes back to
// more than `aside_gap` frames later are set aside in a temporary file meanwhile
// (carve/page_spill.h) and held again, as they were, before the frame that comes back.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "carve/carve_params.h"
#include "carve/occupancy_store.h"
#include "carve/page_spill.h"
#include "carve/voxel_map.h"
#include "common/thread_pool.h"
#include "occlusion/occlusion_resolver.h"
#include "occlusion/surface_points.h"
#include "pipeline/eviction_schedule.h"
#include "pipeline/frame_stage.h"

namespace sonarcarve {

class EvictingSurface {
 public:
  /// `frames` in carving order at their planned poses; `carve` the parameters the map is
  /// carved with (its region the map's box).
  EvictingSurface(std::vector<PosedFrame> frames, const SonarModel& sonar, CarveParams carve,
                  std::uint32_t min_views, ThreadPool& pool, std::int32_t aside_gap = 0);

  /// Before frame `position` of the carving order is carved (or fails to load): holds again
  /// the pages it touches that were set aside.
  void frameStarting(std::size_t position, VoxelMap& map);
  /// After frame `position` of the carving order was carved at `T_world_sonar` into `map`.
  /// Frames not reported (they failed to load) are neither counted nor resolved.
  void frameCarved(std::size_t position, const Eigen::Isometry3d& T_world_sonar, VoxelMap& map);
  /// After the last frame: whatever is left, in order.
  void finish(VoxelMap& map);

  /// The surface points, in the order the in-memory path gives them (voxelOrderLess).
  SurfacePoints surface() const;
  OccupancyStore takeOccupancy() { return std::move(occupancy_); }
  std::size_t occupiedVoxels() const { return occupied_voxels_; }
  /// The most the map and the resolver held after a frame.
  std::size_t peakBytes() const { return peak_bytes_; }
  double occlusionMs() const { return occlusion_ms_; }
  /// Pages of the map released before the last frame was carved.
  std::size_t pagesFreedEarly() const { return pages_freed_early_; }
  const EvictionSchedule* schedule() const { return schedule_.get(); }
  /// Pages set aside over the run, and the most bytes their file held.
  std::size_t pagesSetAside() const { return spill_ ? spill_->pagesSetAside() : 0; }
  std::uint64_t asideFileBytes() const { return aside_file_bytes_; }
  /// Why the temporary files could not be used (pages, or map.bt's blocks, then kept in
  /// memory); empty when they could.
  std::string temporaryFileProblem() const {
    return file_problem_.empty() ? occupancy_.problem() : file_problem_;
  }

 private:
  void plan(const VoxelMap& map);
  void runStep(std::size_t step, VoxelMap& map);
  void settle(const std::vector<std::uint32_t>& cells, const VoxelMap& map);
  void takeSurface(const std::vector<std::uint32_t>& cells, const VoxelMap& map);

  std::vector<PosedFrame> frames_;
  std::vector<bool> carved_;
  const SonarModel& sonar_;
  CarveParams carve_;
  std::uint32_t min_views_;
  ThreadPool& pool_;
  std::int32_t aside_gap_;
  std::unique_ptr<EvictionSchedule> schedule_;
  std::unique_ptr<PageSpill> spill_;  // made when a page is first set aside
  std::uint64_t aside_file_bytes_ = 0;
  std::string file_problem_;
  OcclusionResolver resolver_;
  std::size_t next_step_ = 0;
  SurfacePoints surface_;
  OccupancyStore occupancy_;
  std::vector<std::uint8_t> leaving_;  // per cell, while its blocks are taken out
  std::size_t occupied_voxels_ = 0;
  std::size_t peak_bytes_ = 0;
  std::size_t pages_freed_early_ = 0;
  double occlusion_ms_ = 0.0;
};

}  // namespace sonarcarve
