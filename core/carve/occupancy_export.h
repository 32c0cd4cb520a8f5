// Exporting a carved map as a standard OctoMap occupancy tree (.bt), which OctoMap's own tools
// (octovis) open. Occupied voxels on the shell of occupied space (with a face neighbour that
// is not occupied) are written as occupied, and the carved voxels of the blocks (8^3 voxels)
// holding them as free: the structure and the water around it. Left out, and so unknown to a
// viewer: the rest of the carved water, and occupied voxels buried inside occupied space
// (under a seabed no view could carve, tens of millions of voxels): as octree nodes they
// would take gigabytes. The file is written without building an octree (the bytes OctoMap's
// writer would write for the same voxels; memory: the exported blocks, 520 bytes each, and
// the file).
#pragma once

#include <filesystem>

#include "carve/voxel_map.h"

namespace sonarcarve {

/// Writes atomically; throws Error on failure, keeping any previous file.
void writeOccupancyBt(const VoxelMap& map, const std::filesystem::path& path);

}  // namespace sonarcarve
