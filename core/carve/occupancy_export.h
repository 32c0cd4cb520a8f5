// Exporting a carved map as a standard OctoMap occupancy tree (.bt), which OctoMap's own tools
// (octovis) open. Occupied voxels are written as occupied; the carved voxels of blocks that
// also hold occupied or unknown voxels are written as free. Wholly free blocks are left out
// (they would be tens of millions of voxels): a viewer shows them as unknown.
#pragma once

#include <filesystem>

#include "carve/voxel_map.h"

namespace sonarcarve {

/// Writes atomically; throws Error on failure, keeping any previous file.
void writeOccupancyBt(const VoxelMap& map, const std::filesystem::path& path);

}  // namespace sonarcarve
