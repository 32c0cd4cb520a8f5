// The .bt export written without an octree against OctoMap's own writer: the same bytes for
// maps of scattered blocks, on both sides of the origin, with carved, occupied and unknown
// voxels; and OctoMap reads the file back.
#include <gtest/gtest.h>

#include <octomap/OcTree.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <unordered_set>

#include "carve/occupancy_export.h"
#include "carve/occupancy_store.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

octomap::OcTreeKey keyOf(const Eigen::Vector3i& voxel) {
  return {static_cast<octomap::key_type>(voxel.x() + 32768),
          static_cast<octomap::key_type>(voxel.y() + 32768),
          static_cast<octomap::key_type>(voxel.z() + 32768)};
}

// What the export writes, built as an OcTree and written by OctoMap (the way the export was
// made before it streamed its blocks).
std::string octomapBytes(const VoxelMap& map) {
  octomap::OcTree tree(map.voxelSize());
  std::unordered_set<std::size_t> shell_blocks;
  map.forEachOccupiedOnShell([&](const Eigen::Vector3i& voxel, float) {
    tree.updateNode(keyOf(voxel), true, true);
    const Eigen::Vector3i block =
        (voxel.cast<double>() / VoxelMap::kBlockSide).array().floor().cast<int>().matrix();
    shell_blocks.insert(map.blockIndex(block - map.firstBlock()));
  });
  for (const std::size_t b : shell_blocks) {
    const float* v = map.values(b);
    for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
      if (v[i] == 0.0f) {
        tree.updateNode(keyOf(map.voxelIndex(b, i)), false, true);
      }
    }
  }
  tree.updateInnerOccupancy();
  tree.prune();
  std::ostringstream out;
  tree.writeBinary(out);
  return out.str();
}

// A map over a box astride the origin whose blocks, one in three, hold a wavy sheet of
// occupied voxels in carved water with unknown voxels here and there, and in some blocks a
// quarter of unknown space; a few blocks are all carved.
std::unique_ptr<VoxelMap> scatteredMap(unsigned seed) {
  auto owned = std::make_unique<VoxelMap>(
      0.02, Eigen::AlignedBox3d(Eigen::Vector3d(-0.6, -0.4, -0.3), Eigen::Vector3d(0.5, 0.7, 0.9)));
  VoxelMap& map = *owned;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (std::size_t b = 0; b < map.blockCount(); ++b) {
    const float kind = u(rng);
    if (kind < 0.6f) {
      continue;  // unknown
    }
    std::array<float, VoxelMap::kBlockVoxels> values{};
    if (kind > 0.9f) {
      map.storeBlock(b, nullptr, 1);  // all carved
      continue;
    }
    for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
      const Eigen::Vector3i v = map.voxelIndex(b, i);
      const float sheet = 3.0f * std::sin(0.3f * static_cast<float>(v.x())) +
                          2.0f * std::cos(0.2f * static_cast<float>(v.y()));
      const float depth = static_cast<float>(v.z() % 16) - sheet;
      values[i] = std::abs(depth) < 1.5f ? 10.0f + u(rng)
                  : u(rng) < 0.05f       ? VoxelMap::kUnknown
                                         : 0.0f;
    }
    map.storeBlock(b, values.data(), 1);
  }
  return owned;
}

TEST(OccupancyExport, WritesTheBytesOctoMapWrites) {
  test::ScratchDir dir;
  for (const unsigned seed : {1u, 2u, 3u}) {
    const auto owned = scatteredMap(seed);
    const VoxelMap& map = *owned;
    ASSERT_GT(map.occupiedCount(), 1000u);
    writeOccupancyBt(map, dir.path() / "map.bt");
    EXPECT_EQ(test::readText(dir.path() / "map.bt"), octomapBytes(map)) << "seed " << seed;
  }
}

TEST(OccupancyExport, BlocksKeptInATemporaryFileWriteTheSameBytes) {
  // An evicting run collects a page's blocks at a time, in no order, into an OccupancyStore.
  test::ScratchDir dir;
  const auto owned = scatteredMap(5);
  const VoxelMap& map = *owned;
  std::vector<std::size_t> pages(map.pageCount());
  std::iota(pages.begin(), pages.end(), std::size_t{0});
  std::shuffle(pages.begin(), pages.end(), std::mt19937(11));
  OccupancyStore store;
  std::vector<OccupancyBlock> all, page_blocks;
  for (std::size_t page : pages) {
    page_blocks.clear();
    collectOccupancyBlocks(map, page, page_blocks);
    store.add(page_blocks);
    all.insert(all.end(), page_blocks.begin(), page_blocks.end());
  }
  ASSERT_GT(store.size(), 50u);
  ASSERT_EQ(store.size(), all.size());
  // A copy shares the file: blocks it adds go after the others' and leave them as they were.
  OccupancyStore copy = store;
  copy.add({all.front()});
  EXPECT_EQ(copy.size(), store.size() + 1);
  const SortedOccupancy sorted = store.sorted();
  EXPECT_TRUE(std::is_sorted(sorted.mortons.begin(), sorted.mortons.end()));
  std::sort(all.begin(), all.end(),
            [](const OccupancyBlock& a, const OccupancyBlock& b) { return a.morton < b.morton; });
  OccupancyBlock read;
  for (std::size_t n = 0; n < all.size(); ++n) {
    EXPECT_EQ(sorted.mortons[n], all[n].morton);
    sorted.read(n, read);
    EXPECT_EQ(read.leaves, all[n].leaves) << "block " << n;
  }
  writeOccupancyBt(sorted, map.voxelSize(), dir.path() / "stored.bt");
  writeOccupancyBt(map, dir.path() / "map.bt");
  EXPECT_EQ(test::readText(dir.path() / "stored.bt"), test::readText(dir.path() / "map.bt"));
  // Nothing stored: the empty tree, and no file made.
  OccupancyStore none;
  none.add({});
  writeOccupancyBt(none.sorted(), map.voxelSize(), dir.path() / "none.bt");
  writeOccupancyBt(std::vector<OccupancyBlock>{}, map.voxelSize(), dir.path() / "empty.bt");
  EXPECT_EQ(test::readText(dir.path() / "none.bt"), test::readText(dir.path() / "empty.bt"));
}

TEST(OccupancyExport, OctoMapReadsTheFileBackWithTheShellOccupied) {
  test::ScratchDir dir;
  const auto owned = scatteredMap(7);
  const VoxelMap& map = *owned;
  writeOccupancyBt(map, dir.path() / "map.bt");
  octomap::OcTree tree(0.1);
  ASSERT_TRUE(tree.readBinary((dir.path() / "map.bt").string()));
  EXPECT_DOUBLE_EQ(tree.getResolution(), 0.02);
  std::size_t checked = 0;
  map.forEachOccupiedOnShell([&](const Eigen::Vector3i& voxel, float) {
    const octomap::OcTreeNode* node = tree.search(keyOf(voxel));
    ASSERT_NE(node, nullptr);
    EXPECT_TRUE(tree.isNodeOccupied(node));
    ++checked;
  });
  EXPECT_GT(checked, 100u);
}

TEST(OccupancyExport, AnEmptyMapGivesAnEmptyTree) {
  test::ScratchDir dir;
  const VoxelMap map(0.05, Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()));
  writeOccupancyBt(map, dir.path() / "map.bt");
  EXPECT_EQ(test::readText(dir.path() / "map.bt"), octomapBytes(map));
}

}  // namespace
}  // namespace sonarcarve
