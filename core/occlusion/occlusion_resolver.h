// OcclusionResolver: the seed paper's last step. Every frame is re-read against the carved
// map: along each bearing and each elevation of the aperture (at the elevation step), only
// the first occupied voxel outward in range is kept. Implemented as a z-buffer over
// (beam, elevation bin): each occupied voxel in the frustum is splatted over the beams and
// elevation bins its footprint covers and the nearest one wins each cell; a voxel that wins a
// cell in a frame gains one supporting view. Voxels with at least `min_views` views form the
// surface. Frames are resolved in parallel; add frames, then call result().
#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <vector>

#include "carve/carve_params.h"
#include "carve/carving_geometry.h"
#include "carve/voxel_map.h"
#include "common/thread_pool.h"
#include "occlusion/surface_points.h"

namespace sonarcarve {

class OcclusionResolver {
 public:
  /// Takes the occupied voxels of a carved map (global voxel indices and values).
  OcclusionResolver(const std::vector<Eigen::Vector3i>& voxels, const std::vector<float>& values,
                    const SonarModel& sonar, const CarveParams& params);

  /// Counts the voxels inside the frustum of one pose. Thread safe. Call it for every view
  /// before addView when using requireObservations().
  void countObservations(const Eigen::Isometry3d& T_world_sonar);
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

 private:
  struct Cell {
    float range = 0.0f;
    std::int32_t voxel = -1;
  };
  std::vector<Cell> zBuffer(const Eigen::Isometry3d& T_world_sonar) const;
  CarvingGeometry geometry_;
  double voxel_size_m_;
  int elevation_bins_;
  double elevation_step_;
  // Occupied voxels, grouped by block for culling.
  std::vector<Eigen::Vector3f> centres_;
  std::vector<float> intensities_;
  std::vector<Eigen::Vector3f> block_centres_;
  std::vector<std::uint32_t> block_begin_;  // voxels of group g: [begin[g], begin[g + 1])
  double block_radius_;
  std::unique_ptr<std::atomic<std::uint32_t>[]> views_;
  std::unique_ptr<std::atomic<std::uint32_t>[]> observed_;
  std::uint32_t required_observations_ = 0;
  // Calls f(voxel index, range, bearing, elevation, angular radius) for each voxel in view.
  template <typename F>
  void forEachVoxelInView(const Eigen::Isometry3d& T_world_sonar, F&& f) const;
};

}  // namespace sonarcarve
