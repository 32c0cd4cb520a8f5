// MapViewBlock: one block of the carved map as the 3D view holds it (plain data, no Qt, no VTK).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace sonarcarve::widgets {

/// One block of the map as the viewer receives it (a block with no points has become empty).
struct MapViewBlock {
  std::size_t block = 0;
  std::vector<Eigen::Vector3f> points;  ///< voxel centres, world NED
  std::vector<float> values;            ///< carved intensities
  std::vector<float> errors_m;          ///< distance to the ground truth, or empty
  std::size_t frames_done = 0;          ///< frames carved when the block last changed
  /// Held at a coarser level of detail (MapLod): the occupied voxels each point stands for
  /// (their centroid, mean value and mean error); empty: each point is one voxel.
  std::vector<std::uint32_t> voxels;
  int level = 0;  ///< MapLod's level: 0 every voxel, k one point per 2^k voxels a side

  /// The occupied voxels point `k` stands for.
  std::size_t voxelsAt(std::size_t k) const { return k < voxels.size() ? voxels[k] : 1; }
  /// The occupied voxels the block's points stand for.
  std::size_t voxelCount() const {
    return voxels.empty() ? points.size()
                          : std::accumulate(voxels.begin(), voxels.end(), std::size_t{0});
  }
};

}  // namespace sonarcarve::widgets
