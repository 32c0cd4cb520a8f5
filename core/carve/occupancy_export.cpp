#include "carve/occupancy_export.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/number_text.h"
#include "geo/crs.h"
#include "io/files/atomic_file.h"
#include "sonar/mission_origin.h"

// The .bt file is written as OctoMap's OcTree::writeBinary writes it, without building the
// octree (hundreds of megabytes of nodes for a riser): the exported voxels lie in the map's
// blocks of 8^3 voxels, which are the octree's subtrees three levels above its leaves, so the
// tree is written depth first from the blocks sorted in Morton order of their keys.
// OctoMap's format (octomap/OccupancyOcTreeBase.hxx, writeBinaryNode): a header, then for
// each inner node two bytes holding two bits per child (children 0-3, then 4-7; bit 2i and
// 2i+1 of each byte: 00 unknown, 10 free leaf, 01 occupied leaf, 11 inner node), then the
// inner children in order. A child's index is its key's bit at that level on x (1), y (2) and
// z (4). Eight children that are leaves of one state are pruned into a leaf of that state,
// as OcTree::prune does after the maximum-likelihood step of writeBinary.

namespace sonarcarve {
namespace {

constexpr int kTreeDepth = 16;   // OctoMap's; key = voxel index + 32768
constexpr int kBlockLevels = 3;  // a block is a subtree of 2^3 voxels a side

// A node's state; its value is the node's two-bit code in its parent's bytes.
enum class NodeState : std::uint8_t { Unknown = 0, Free = 1, Occupied = 2, Inner = 3 };

NodeState leafOf(const OccupancyBlock& block, std::size_t m) {
  return static_cast<NodeState>((block.leaves[m / 32] >> (2 * (m % 32))) & 3u);
}

void setLeaf(OccupancyBlock& block, std::size_t m, NodeState state) {
  std::uint64_t& word = block.leaves[m / 32];
  const int shift = static_cast<int>(2 * (m % 32));
  word = (word & ~(std::uint64_t{3} << shift)) | static_cast<std::uint64_t>(state) << shift;
}

std::uint64_t interleave(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  std::uint64_t m = 0;
  for (int b = bits - 1; b >= 0; --b) {
    m = m << 3 | ((z >> b) & 1u) << 2 | ((y >> b) & 1u) << 1 | ((x >> b) & 1u);
  }
  return m;
}

}  // namespace

void collectOccupancyBlocks(const VoxelMap& map, std::size_t page,
                            std::vector<OccupancyBlock>& blocks) {
  // Occupied voxels on the shell of occupied space, which come block after block.
  std::size_t current = map.blockCount();
  map.forEachOccupiedOnShellIn(page, [&](const Eigen::Vector3i& voxel, float) {
    if ((voxel.array() < -kOctoMapKeyOffset).any() || (voxel.array() >= kOctoMapKeyOffset).any()) {
      return;  // no key holds it: the run writes no map.bt (octoMapKeyProblem says why)
    }
    const Eigen::Vector3i key = voxel + Eigen::Vector3i::Constant(kOctoMapKeyOffset);
    const Eigen::Vector3i block_key = key / VoxelMap::kBlockSide;
    const std::size_t index = map.blockIndex(
        block_key - Eigen::Vector3i::Constant(kOctoMapKeyOffset / VoxelMap::kBlockSide) -
        map.firstBlock());
    if (index != current) {
      current = index;
      OccupancyBlock block;
      block.morton = interleave(
          static_cast<std::uint32_t>(block_key.x()), static_cast<std::uint32_t>(block_key.y()),
          static_cast<std::uint32_t>(block_key.z()), kTreeDepth - kBlockLevels);
      // The carved voxels of a block that holds shell voxels: the water next to them.
      const float* values = map.values(index);
      for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
        if (values[i] == 0.0f) {
          const int x = i % 8, y = (i / 8) % 8, z = i / 64;
          setLeaf(block, interleave(x, y, z, kBlockLevels), NodeState::Free);
        }
      }
      blocks.push_back(block);
    }
    const Eigen::Vector3i offset = key - block_key * VoxelMap::kBlockSide;
    setLeaf(blocks.back(), interleave(offset.x(), offset.y(), offset.z(), kBlockLevels),
            NodeState::Occupied);
  });
}

namespace {

// Writes the subtrees below one node depth first and says what the node is.
class BtWriter {
 public:
  explicit BtWriter(const SortedOccupancy& blocks) : blocks_(blocks) {}
  std::size_t nodes = 0;  ///< nodes written, the root not included

  /// Appends to `out` the node at `level` (0: a voxel) whose key prefix is `prefix`, made of
  /// blocks [b, e), unless it is a leaf; returns its state. The root is never pruned.
  NodeState node(int level, std::uint64_t prefix, std::size_t b, std::size_t e, std::string& out) {
    std::array<NodeState, 8> child{};
    std::array<std::string, 8> below;
    if (level == kBlockLevels) {
      blocks_.read(b, block_);  // the voxels below come from this block alone
    }
    const auto& mortons = blocks_.mortons;
    for (int c = 0; c < 8; ++c) {
      const std::uint64_t child_prefix = prefix << 3 | static_cast<std::uint64_t>(c);
      if (level - 1 >= kBlockLevels) {
        // Blocks whose Morton key starts with the child's prefix.
        const int shift = 3 * (level - 1 - kBlockLevels);
        const auto first =
            std::lower_bound(mortons.begin() + static_cast<long>(b),
                             mortons.begin() + static_cast<long>(e), child_prefix << shift);
        auto last = first;
        while (last != mortons.begin() + static_cast<long>(e) && (*last >> shift) == child_prefix) {
          ++last;
        }
        if (first != last) {
          child[c] =
              node(level - 1, child_prefix, static_cast<std::size_t>(first - mortons.begin()),
                   static_cast<std::size_t>(last - mortons.begin()), below[c]);
        }
      } else if (level - 1 == 0) {
        child[c] = leafOf(block_, child_prefix & 0x1FF);
      } else {
        child[c] = node(level - 1, child_prefix, b, e, below[c]);
      }
    }
    if (std::all_of(child.begin(), child.end(),
                    [](NodeState s) { return s == NodeState::Unknown; })) {
      return NodeState::Unknown;  // OctoMap holds no node where nothing is known
    }
    // Eight leaves of one state are pruned into one (OctoMap's prune stops at the first level
    // that prunes nothing; here no level above one that prunes nothing can prune anything:
    // a block, or a cube of 4^3 voxels, never holds only occupied shell voxels).
    if (level < kTreeDepth && (child[0] == NodeState::Free || child[0] == NodeState::Occupied) &&
        std::all_of(child.begin(), child.end(), [&](NodeState s) { return s == child[0]; })) {
      return child[0];
    }
    std::uint8_t bytes[2] = {0, 0};
    for (int c = 0; c < 8; ++c) {
      if (child[c] == NodeState::Unknown) {
        continue;
      }
      ++nodes;
      const auto bits = static_cast<std::uint8_t>(child[c]);
      bytes[c / 4] = static_cast<std::uint8_t>(bytes[c / 4] | bits << (2 * (c % 4)));
    }
    out.push_back(static_cast<char>(bytes[0]));
    out.push_back(static_cast<char>(bytes[1]));
    for (int c = 0; c < 8; ++c) {
      if (child[c] == NodeState::Inner) {
        out += below[c];
      }
    }
    return NodeState::Inner;
  }

 private:
  const SortedOccupancy& blocks_;
  OccupancyBlock block_;  // the block being written
};

}  // namespace

std::optional<std::string> octoMapKeyProblem(const Eigen::AlignedBox3d& box, double voxel_size_m) {
  const double lo = (box.min() / voxel_size_m).array().floor().minCoeff();
  const double hi = (box.max() / voxel_size_m).array().floor().maxCoeff();
  if (lo >= -kOctoMapKeyOffset && hi < kOctoMapKeyOffset) {
    return std::nullopt;
  }
  const double reach_m = std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  return "the map reaches " + shortestNumber(std::round(reach_m)) +
         " m from its origin, beyond OctoMap's keys (+-" + std::to_string(kOctoMapKeyOffset) +
         " voxels: +-" + shortestNumber(kOctoMapKeyOffset * voxel_size_m) + " m at " +
         shortestNumber(voxel_size_m) + " m voxels)";
}

void writeOccupancyBt(const VoxelMap& map, const std::filesystem::path& path,
                      const Eigen::Vector3d& origin_ned_m, const std::string& crs) {
  if (const auto problem = octoMapKeyProblem(map.bounds(), map.voxelSize())) {
    throw Error(path.string(), "", "cannot write an OctoMap file: " + *problem);
  }
  std::vector<OccupancyBlock> blocks;
  for (std::size_t page = 0; page < map.pageCount(); ++page) {
    collectOccupancyBlocks(map, page, blocks);
  }
  writeOccupancyBt(std::move(blocks), map.voxelSize(), path, origin_ned_m, crs);
}

void writeOccupancyBt(std::vector<OccupancyBlock> blocks, double voxel_size_m,
                      const std::filesystem::path& path, const Eigen::Vector3d& origin_ned_m,
                      const std::string& crs) {
  std::sort(blocks.begin(), blocks.end(),
            [](const OccupancyBlock& a, const OccupancyBlock& b) { return a.morton < b.morton; });
  SortedOccupancy sorted;
  sorted.mortons.reserve(blocks.size());
  for (const OccupancyBlock& b : blocks) {
    sorted.mortons.push_back(b.morton);
  }
  sorted.read = [&blocks](std::size_t n, OccupancyBlock& out) { out = blocks[n]; };
  writeOccupancyBt(sorted, voxel_size_m, path, origin_ned_m, crs);
}

void writeOccupancyBt(const SortedOccupancy& blocks, double voxel_size_m,
                      const std::filesystem::path& path, const Eigen::Vector3d& origin_ned_m,
                      const std::string& crs) {
  BtWriter writer(blocks);
  std::string data;
  if (!blocks.mortons.empty()) {
    writer.node(kTreeDepth, 0, 0, blocks.mortons.size(), data);
    ++writer.nodes;  // the root
  }
  std::ostringstream header;
  header << "# Octomap OcTree binary file\n"
         << "# (feel free to add / change comments, but leave the first line as it is!)\n#\n";
  if (!origin_ned_m.isZero()) {
    header << "# " << originComment(origin_ned_m) << "\n";
  }
  if (!crs.empty()) {
    header << "# " << crsComment(crs) << "\n";
  }
  header << "id OcTree\nsize " << writer.nodes << "\nres " << voxel_size_m << "\ndata\n";
  data.insert(0, header.str());
  writeFileAtomically(path, data);
}

}  // namespace sonarcarve
