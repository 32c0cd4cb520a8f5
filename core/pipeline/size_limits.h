// Sizes a reconstruction derives from its parameters and the frames' poses, checked against
// the documented limits (common/input_limits.h) and the memory available
// (common/available_memory.h) before the map or any buffer is allocated.
#pragma once

#include <Eigen/Geometry>
#include <optional>

#include "carve/carve_params.h"
#include "common/available_memory.h"
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
/// `available` (nothing is checked when the memory available is not known).
void requireMemory(const MemoryEstimate& estimate, const CarveParams& carve,
                   const std::optional<AvailableMemory>& available);

/// Throws Error naming the parameter to change when the map's box (`bounds`, NED metres) holds
/// more than kMaxMapVoxels voxels at carve.voxel_size_m, when a frame's occlusion buffer
/// (beams x elevation steps over the aperture) exceeds kMaxFramePixels cells, or when the
/// estimate for `threads` worker threads exceeds the memory available.
void requireBoundedSizes(const Eigen::AlignedBox3d& bounds, const SonarModel& sonar,
                         const CarveParams& carve, unsigned threads);

}  // namespace sonarcarve
