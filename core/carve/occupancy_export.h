// Exporting a carved map as a standard OctoMap occupancy tree (.bt), which OctoMap's own tools
// (octovis) open. Occupied voxels on the shell of occupied space (with a face neighbour that
// is not occupied) are written as occupied, and the carved voxels of the blocks (8^3 voxels)
// holding them as free: the structure and the water around it. Left out, and so unknown to a
// viewer: the rest of the carved water, and occupied voxels buried inside occupied space
// (under a seabed no view could carve, tens of millions of voxels): as octree nodes they
// would take gigabytes. The file is written without building an octree (the bytes OctoMap's
// writer would write for the same voxels; memory: the exported blocks, 520 bytes each, and
// the file). A run that lets finished regions of its map go collects their exported blocks as
// they go (carve/occupancy_store.h: 16 bytes each in memory, the rest in a temporary file) and
// writes the file from them at the end.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "carve/voxel_map.h"

namespace sonarcarve {

/// The exported voxels of one block (the occupied ones on the shell, and the carved ones
/// beside them) as Morton-ordered leaves of two bits: leaf m is the voxel whose offsets in
/// the block have the bits of m interleaved (x, y, z).
struct OccupancyBlock {
  std::uint64_t morton = 0;  ///< of the block's key (voxel key >> 3)
  std::array<std::uint64_t, VoxelMap::kBlockVoxels / 32> leaves{};
};

/// Exported blocks sorted by Morton key, read one at a time (carve/occupancy_store.h keeps
/// them in a file): `mortons` ascending, `read(n, out)` fills out.leaves with the n-th's.
struct SortedOccupancy {
  std::vector<std::uint64_t> mortons;
  std::function<void(std::size_t n, OccupancyBlock& out)> read;
};

/// OctoMap's keys are 16 bits: voxel index + 32768, so a .bt holds voxels -32768 to 32767 on
/// each axis (+-655.36 m at 2 cm voxels); a voxel beyond would wrap to the other side.
inline constexpr int kOctoMapKeyOffset = 32768;

/// Why a map over `box` (world NED, metres) cannot be written as .bt at `voxel_size_m` (its
/// keys would wrap), in words naming the limit; nothing when it can.
std::optional<std::string> octoMapKeyProblem(const Eigen::AlignedBox3d& box, double voxel_size_m);

/// Adds the exported blocks of one page of `map` (its face neighbours' voxels must be final);
/// voxels beyond OctoMap's keys are left out.
void collectOccupancyBlocks(const VoxelMap& map, std::size_t page,
                            std::vector<OccupancyBlock>& blocks);

/// Writes atomically; throws Error on failure, keeping any previous file, and when the map's
/// box does not fit OctoMap's keys (octoMapKeyProblem). A map local to a mission origin that is
/// not zero says so in a header comment (`# origin_ned_m N E D ...`, which OctoMap skips), and
/// a mission's CRS (`crs`, when not empty) in another (`# crs EPSG:32631`).
void writeOccupancyBt(const VoxelMap& map, const std::filesystem::path& path,
                      const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero(),
                      const std::string& crs = "");
/// The same from collected blocks (any order), of a map of `voxel_size_m` whose box fits
/// OctoMap's keys (the caller checks it: blocks beyond have wrapped keys).
void writeOccupancyBt(std::vector<OccupancyBlock> blocks, double voxel_size_m,
                      const std::filesystem::path& path,
                      const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero(),
                      const std::string& crs = "");
void writeOccupancyBt(const SortedOccupancy& blocks, double voxel_size_m,
                      const std::filesystem::path& path,
                      const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero(),
                      const std::string& crs = "");

}  // namespace sonarcarve
