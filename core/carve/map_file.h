// The carved map on disk (`.scmap`, docs/formats.md), and the fusion of two maps.
//
// A map file holds a VoxelMap's grid (voxel size, first block, block dimensions) and every
// block that is not Unknown: Free blocks by their index only, Mixed blocks with their 512
// values (the minimum over the views, +inf where no view observed the voxel). It is written
// atomically; a reader checks every field and names the byte where a file goes wrong.
// Voxel counts (robust carving's votes, pose refinement's view counts) are not kept.
//
// Space carving keeps, per voxel, the minimum over the views that observed it, and minimum is
// associative and commutative: merging the maps carved from two sets of frames gives the map
// carved from all of them, voxel by voxel, wherever both were carved with the same
// parameters (the same keep level for beam-aware carving, one vote).
#pragma once

#include <filesystem>
#include <memory>

#include "carve/voxel_map.h"

namespace sonarcarve {

/// Writes `map` to `path` atomically. Throws Error naming the path on failure, leaving a
/// previous file intact.
void saveMap(const VoxelMap& map, const std::filesystem::path& path);

/// Reads a map file. Throws Error naming the file, the byte and what was expected on an
/// empty, cut, corrupt or foreign file, or when the map would not fit in the memory available.
std::unique_ptr<VoxelMap> loadMap(const std::filesystem::path& path);

/// The box spanned by the centres of `map`'s outermost voxels: a map built over it (or over a
/// box that contains it) has the same blocks, whereas VoxelMap::bounds() reaches the next
/// block's first voxel.
Eigen::AlignedBox3d voxelCentresBox(const VoxelMap& map);

/// Fuses `source` into `target` by the voxel-wise minimum, where `source`'s blocks lie inside
/// `target`'s box (those outside are left out). Throws Error when the voxel sizes differ.
void fuseInto(VoxelMap& target, const VoxelMap& source);

/// The voxel-wise minimum of two maps on one grid (the same voxel size), over the union of
/// their boxes; unknown where neither observed a voxel. Throws Error when the voxel sizes
/// differ.
std::unique_ptr<VoxelMap> mergeMaps(const VoxelMap& a, const VoxelMap& b);

/// True when both maps hold the same value in every voxel of either's box (their boxes may
/// differ where the larger one holds only unknown voxels).
bool sameVoxels(const VoxelMap& a, const VoxelMap& b);

}  // namespace sonarcarve
