// OcclusionResolver: the seed paper's last step. Every frame is re-read against the carved
// map: along each bearing and each elevation of the aperture (at the elevation step), only
// the first occupied voxel outward in range is kept. Implemented as a z-buffer over
// (beam, elevation bin): each occupied voxel in the frustum is splatted over the beams and
// elevation bins its footprint covers and the nearest one wins each cell; a voxel that wins a
// cell in a frame gains one supporting view. Voxels with at least `min_views` views form the
// surface. Frames are resolved in parallel; add frames, then call result().
// For a run that lets finished regions go (pipeline/evicting_surface.h) the voxels can also
// come in batches (addVoxels), be counted against the frames that see them
// (countObservations over the groups of a batch) and leave with their points (takeBlocks).
// Ties between equally far voxels go to the first in voxelOrderLess, so the result does not
// depend on the order in which voxels came.
#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <functional>
#include <vector>

#include "carve/carve_params.h"
#include "carve/carving_geometry.h"
#include "carve/voxel_map.h"
#include "common/thread_pool.h"
#include "occlusion/surface_points.h"

namespace sonarcarve {

/// The order of voxels (global indices) the resolver keeps: by block of 8^3 (z, y, x), then
/// within the block (z, y, x).
bool voxelOrderLess(const Eigen::Vector3i& a, const Eigen::Vector3i& b);

class OcclusionResolver {
 public:
  /// Takes the occupied voxels of a carved map (global voxel indices and values).
  OcclusionResolver(const std::vector<Eigen::Vector3i>& voxels, const std::vector<float>& values,
                    const SonarModel& sonar, const CarveParams& params);

  /// Adds voxels of blocks not held yet; returns the first of the groups (blocks) they make,
  /// which run to groups(). Not thread safe.
  std::size_t addVoxels(const std::vector<Eigen::Vector3i>& voxels,
                        const std::vector<float>& values);
  std::size_t groups() const { return block_keys_.size(); }
  /// Takes out the groups whose block (global block index) `leaves` names, with the surface
  /// points (at least `min_views` views) among their voxels. Not thread safe.
  SurfacePoints takeBlocks(const std::function<bool(const Eigen::Vector3i&)>& leaves,
                           std::uint32_t min_views);

  /// Counts the voxels inside the frustum of one pose (of groups [first_group, groups())).
  /// Thread safe. Call it for every view before addView when using requireObservations().
  void countObservations(const Eigen::Isometry3d& T_world_sonar, std::size_t first_group = 0);
  /// From now on only voxels inside at least `views` frustums take part in the z-buffers.
  /// Noise that survives carving lies where few views overlap (near the sonar); without
  /// this it would hide the structure behind it. Not thread safe.
  void requireObservations(std::uint32_t views);
  /// Finds the first returns seen from one pose. Thread safe: call from several threads.
  void addView(const Eigen::Isometry3d& T_world_sonar);
  /// Range of the first occupied voxel in each (beam, elevation bin) cell seen from a pose,
  /// beam-major (beam * elevationBins() + bin); +inf where the cell sees nothing. Thread safe.
  std::vector<float> firstReturnRanges(const Eigen::Isometry3d& T_world_sonar) const;
  int elevationBins() const { return elevation_bins_; }
  /// Occupied voxels that were first returns in at least `min_views` views.
  SurfacePoints result(std::uint32_t min_views = 1) const;
  std::size_t occupiedVoxels() const { return centres_.size(); }
  /// Bytes of the voxels and counters held.
  std::size_t memoryBytes() const;

 private:
  struct Cell {
    float range = 0.0f;
    std::int32_t voxel = -1;
  };
  std::vector<Cell> zBuffer(const Eigen::Isometry3d& T_world_sonar) const;
  void addGroups(const std::vector<Eigen::Vector3i>& voxels, const std::vector<float>& values);
  CarvingGeometry geometry_;
  double voxel_size_m_;
  int elevation_bins_;
  double elevation_step_;
  // Occupied voxels, grouped by block for culling.
  std::vector<Eigen::Vector3f> centres_;
  std::vector<float> intensities_;
  std::vector<Eigen::Vector3i> voxels_;  // global indices, for ties and for takeBlocks
  std::vector<Eigen::Vector3f> block_centres_;
  std::vector<Eigen::Vector3i> block_keys_;    // global block index of each group
  std::vector<std::uint32_t> block_begin_{0};  // voxels of group g: [begin[g], begin[g + 1])
  double block_radius_;
  // Counters updated through std::atomic_ref by the threads resolving frames.
  std::vector<std::uint32_t> views_;
  std::vector<std::uint32_t> observed_;
  std::uint32_t required_observations_ = 0;
  // Calls f(voxel index, range, bearing, elevation, angular radius) for each voxel in view
  // among groups [first_group, groups()).
  template <typename F>
  void forEachVoxelInView(const Eigen::Isometry3d& T_world_sonar, std::size_t first_group,
                          F&& f) const;
};

}  // namespace sonarcarve
