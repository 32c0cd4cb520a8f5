// The fit's starting point: the carved map's band around its surface as a block grid of
// occupancy logits and reflectances (model/block_grid.h). Voxels within `band_voxels` of a
// surface point take the carved map's verdict: carved voxels are nearly transparent (a ray
// crossing the band loses a few per cent), occupied and unknown ones nearly opaque, every
// reflectance 1. Outside the band the grid holds nothing (empty): the fit only moves the
// surface within the band carving left it.
#pragma once

#include <cstdint>
#include <vector>

#include "carve/voxel_map.h"
#include "model/block_grid.h"
#include "occlusion/surface_points.h"

namespace sonarcarve {

/// Logits the band starts from: alpha = sigmoid(logit) is the chance that one ray sample (half
/// a range bin) stops there.
inline constexpr float kCarvedLogit = -4.0f;
inline constexpr float kOccupiedLogit = 4.0f;

/// The grid the fit changes and which of its voxels (flat index) lie in the band.
struct FitGrid {
  BlockGrid grid;
  std::vector<std::uint8_t> in_band;
};

/// The band of `map` around `surface`, at the map's voxel size.
FitGrid initialGrid(const VoxelMap& map, const SurfacePoints& surface, int band_voxels);

}  // namespace sonarcarve
