// Exporting a carved map as a standard OctoMap occupancy tree (.bt), which OctoMap's own tools
// (octovis) open. Occupied voxels are written as occupied, and the carved voxels of the blocks
// (8^3 voxels) that hold occupied ones as free: the free space around the structure. The rest
// of the carved water is left out (tens of millions of voxels, gigabytes as octree nodes):
// a viewer shows it as unknown.
#pragma once

#include <filesystem>

#include "carve/voxel_map.h"

namespace sonarcarve {

/// Writes atomically; throws Error on failure, keeping any previous file.
void writeOccupancyBt(const VoxelMap& map, const std::filesystem::path& path);

}  // namespace sonarcarve
