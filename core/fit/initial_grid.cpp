#include "fit/initial_grid.h"

#include <algorithm>

namespace sonarcarve {

FitGrid initialGrid(const VoxelMap& map, const SurfacePoints& surface, int band_voxels) {
  FitGrid fit{BlockGrid(map.voxelSize()), {}};
  BlockGrid& grid = fit.grid;
  const int r = std::max(0, band_voxels);
  for (const SurfacePoint& point : surface) {
    const Eigen::Vector3i centre = map.voxelOf(point.position_m.cast<double>());
    for (int dz = -r; dz <= r; ++dz) {
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const Eigen::Vector3i voxel = centre + Eigen::Vector3i(dx, dy, dz);
          const auto index = static_cast<std::size_t>(grid.addVoxel(voxel));
          fit.in_band.resize(grid.voxelCount(), 0);
          if (fit.in_band[index] != 0) {
            continue;
          }
          fit.in_band[index] = 1;
          grid.logits()[index] = map.value(voxel) == 0.0f ? kCarvedLogit : kOccupiedLogit;
          grid.reflectance()[index] = 1.0f;
        }
      }
    }
  }
  return fit;
}

}  // namespace sonarcarve
