// Sizes a reconstruction derives from its parameters and the frames' poses, checked against
// the documented limits (common/input_limits.h) and the run's memory budget
// (pipeline/memory_budget.h) before the map or any buffer is allocated; and what the later
// stages will hold, estimated before they start.
#pragma once

#include <Eigen/Geometry>
#include <optional>

#include "carve/carve_params.h"
#include "pipeline/memory_budget.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// What a reconstruction will hold in memory at least, in bytes, before it starts.
struct MemoryEstimate {
  /// The map's block table over its box (9 bytes a block of 8^3 voxels) and the contents of
  /// the blocks a surface across the box's largest face occupies (two layers of 2 KiB blocks).
  double map = 0.0;
  /// Per worker thread: a frame and its denoised copy (4 bytes a pixel each).
  double frames = 0.0;
  /// Per worker thread: the occlusion buffer (beams x elevation steps, 8 bytes a cell).
  double occlusion = 0.0;
  double total() const { return map + frames + occlusion; }
};

MemoryEstimate estimateMemory(const Eigen::AlignedBox3d& bounds, const SonarModel& sonar,
                              const CarveParams& carve, unsigned threads);

/// Throws Error naming the parameter that takes most of the memory when `estimate` exceeds
/// `budget` (nothing is checked when there is no budget: the memory available is not known).
void requireMemory(const MemoryEstimate& estimate, const CarveParams& carve,
                   const std::optional<MemoryBudget>& budget);

/// Throws Error naming the parameter to change when the map's box (`bounds`, NED metres) holds
/// more than kMaxMapVoxels voxels at carve.voxel_size_m, when a frame's occlusion buffer
/// (beams x elevation steps over the aperture) exceeds kMaxFramePixels cells, or when the
/// estimate for `threads` worker threads exceeds the budget. Returns the estimate.
MemoryEstimate requireBoundedSizes(const Eigen::AlignedBox3d& bounds, const SonarModel& sonar,
                                   const CarveParams& carve, unsigned threads,
                                   const std::optional<MemoryBudget>& budget);

/// What occlusion resolution holds beyond the map, for `occupied_voxels` occupied voxels (an
/// upper bound of its surface candidates): the candidates and their values (16 bytes each),
/// the resolver's copy with its view counters (24) and the surface points it returns (20).
/// The per-thread z-buffers are MemoryEstimate::occlusion.
double occlusionStageBytes(std::size_t occupied_voxels);

/// What the mesh stage holds at its peak for `surface_points` surface points: the occupancy
/// grid around them, VTK's copies through smoothing and cleaning, and the mesh it returns
/// (measured, with a margin: docs/reliability.md, "Limits").
double meshStageBytes(std::size_t surface_points);

}  // namespace sonarcarve
