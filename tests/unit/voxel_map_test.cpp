// The block map's storage: each block kept in the cheapest form that holds its values
// (unknown, free, a mask of carved voxels, or its 512 values), and read back the same.
#include <gtest/gtest.h>

#include <array>

#include "carve/voxel_map.h"

namespace sonarcarve {
namespace {

using Values = std::array<float, VoxelMap::kBlockVoxels>;

Values readBack(const VoxelMap& map, std::size_t b) {
  Values out{};
  map.copyValues(b, out.data());
  return out;
}

TEST(VoxelMapStorage, CarvedAndUnknownVoxelsOnlyAreKeptAsAMaskAndReadBackTheSame) {
  VoxelMap map(0.02, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)));
  const std::size_t b = map.blockIndex({3, 4, 5});
  Values edge{};  // the edge of a view: half carved, half never seen
  for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
    edge[i] = i % 3 == 0 ? VoxelMap::kUnknown : 0.0f;
  }
  map.storeBlock(b, edge.data(), 1);
  EXPECT_EQ(map.state(b), VoxelMap::BlockState::Partial);
  EXPECT_EQ(map.values(b), nullptr);
  EXPECT_EQ(readBack(map, b), edge);
  for (int i : {0, 1, 2, 300, 511}) {
    EXPECT_EQ(map.value(map.voxelIndex(b, i)), edge[i]);
  }
  // A lit voxel makes it a block of values; carving it makes it a mask again, then free.
  Values lit = edge;
  lit[0] = 42.0f;
  map.storeBlock(b, lit.data(), 2);
  EXPECT_EQ(map.state(b), VoxelMap::BlockState::Mixed);
  EXPECT_EQ(readBack(map, b), lit);
  EXPECT_EQ(map.occupiedCount(), 1u);
  lit[0] = 0.0f;
  map.storeBlock(b, lit.data(), 3);
  EXPECT_EQ(map.state(b), VoxelMap::BlockState::Partial);
  EXPECT_EQ(readBack(map, b), lit);
  Values carved{};
  map.storeBlock(b, carved.data(), 4);
  EXPECT_EQ(map.state(b), VoxelMap::BlockState::Free);
  EXPECT_EQ(map.stamp(b), 4u);
}

TEST(VoxelMapStorage, MasksCostAThirtySecondOfValues) {
  VoxelMap masks(0.02, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)));
  VoxelMap values(0.02, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)));
  // The block table's pages first: what is measured is the blocks' contents.
  for (VoxelMap* map : {&masks, &values}) {
    map->holdPages(Eigen::Vector3i::Zero(), map->blockDims() - Eigen::Vector3i::Ones());
  }
  const std::size_t empty_bytes = masks.memoryBytes();
  Values edge{}, lit{};
  edge.fill(VoxelMap::kUnknown);
  edge[7] = 0.0f;
  lit = edge;
  lit[8] = 5.0f;
  for (std::size_t b = 0; b < 2048; ++b) {
    masks.storeBlock(b, edge.data(), 1);
    values.storeBlock(b, lit.data(), 1);
  }
  EXPECT_EQ(masks.blockCount(VoxelMap::BlockState::Partial), 2048u);
  EXPECT_EQ(values.blockCount(VoxelMap::BlockState::Mixed), 2048u);
  EXPECT_EQ(masks.memoryBytes() - empty_bytes, 2048u * 64u);
  EXPECT_EQ(values.memoryBytes() - empty_bytes, 2048u * VoxelMap::kBlockVoxels * sizeof(float));
}

TEST(VoxelMapStorage, BlocksTheViewsHaveLeftAreMaskedAndTheOthersKeepTheirFloats) {
  VoxelMap map(0.02, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)));
  Values edge{}, lit{};
  edge.fill(VoxelMap::kUnknown);
  edge[9] = 0.0f;
  lit = edge;
  lit[10] = 7.0f;
  // As the carver stores them: floats while views reach them.
  map.storeBlock(0, edge.data(), 1, nullptr, false);
  map.storeBlock(1, edge.data(), 1, nullptr, false);
  map.storeBlock(2, lit.data(), 1, nullptr, false);
  for (std::size_t b = 0; b < 3; ++b) {
    map.markVisited(b, 1);
    EXPECT_EQ(map.state(b), VoxelMap::BlockState::Mixed);
  }
  map.compactColdBlocks(8, 8);  // nothing has been left for more than 8 frames
  EXPECT_EQ(map.state(0), VoxelMap::BlockState::Mixed);
  map.markVisited(1, 12);  // still in view at 12
  map.compactColdBlocks(16, 8);
  EXPECT_EQ(map.state(0), VoxelMap::BlockState::Partial);  // left at 1
  EXPECT_EQ(map.state(1), VoxelMap::BlockState::Mixed);    // reached at 12
  EXPECT_EQ(map.state(2), VoxelMap::BlockState::Mixed);    // holds an occupied voxel
  EXPECT_EQ(readBack(map, 0), edge);
  EXPECT_EQ(readBack(map, 2), lit);
}

TEST(VoxelMapStorage, AMapWithCountsKeepsValuesForItsCounts) {
  VoxelMap map(0.02, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)),
               true);
  Values edge{};
  edge.fill(VoxelMap::kUnknown);
  edge[3] = 0.0f;
  map.storeBlock(0, edge.data(), 1);
  EXPECT_EQ(map.state(0), VoxelMap::BlockState::Mixed);
  ASSERT_NE(map.views(0), nullptr);
}

TEST(VoxelMapPages, AnEmptyRegionCostsNoPageAndAReleasedPageReadsUnknown) {
  // 4 x 4 x 4 m at 2 cm: 25^3 blocks, 4^3 pages of 8^3 blocks.
  VoxelMap map(0.02,
               Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3.99, 3.99, 3.99)));
  ASSERT_EQ(map.pageDims(), Eigen::Vector3i(4, 4, 4));
  const std::size_t empty_bytes = map.memoryBytes();
  EXPECT_EQ(map.pagesHeld(), 0u);
  Values lit{};
  lit.fill(VoxelMap::kUnknown);
  lit[3] = 7.0f;
  const std::size_t b = map.blockIndex({20, 9, 1});  // page (2, 1, 0)
  map.storeBlock(b, lit.data(), 1);
  EXPECT_EQ(map.pagesHeld(), 1u);
  EXPECT_EQ(VoxelMap::pageOf(b), map.pageIndex({2, 1, 0}));
  EXPECT_EQ(map.blockCoords(b), Eigen::Vector3i(20, 9, 1));
  EXPECT_EQ(map.value(map.voxelIndex(b, 3)), 7.0f);
  const std::size_t one_block_bytes = map.memoryBytes();
  EXPECT_GT(one_block_bytes, empty_bytes);
  // The other 63 pages cost nothing, whatever their region.
  EXPECT_EQ(map.blockCount(VoxelMap::BlockState::Unknown), map.blockCount() - 1);
  map.releasePage(VoxelMap::pageOf(b));
  EXPECT_EQ(map.pagesHeld(), 0u);
  EXPECT_EQ(map.state(b), VoxelMap::BlockState::Unknown);
  EXPECT_EQ(map.value(map.voxelIndex(b, 3)), VoxelMap::kUnknown);
  // Its value slot is reused by the next block stored, in another page.
  map.storeBlock(map.blockIndex({0, 0, 0}), lit.data(), 2);
  EXPECT_EQ(map.memoryBytes(), one_block_bytes);
  EXPECT_EQ(map.blockCount(VoxelMap::BlockState::Mixed), 1u);
}

TEST(VoxelMapPages, RowOrderVisitsTheBoxsBlocksOnce) {
  VoxelMap map(0.02, Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.5, 0.7, 0.3)));
  std::vector<bool> seen(map.blockCount(), false);
  for (std::size_t n = 0; n < map.boxBlockCount(); ++n) {
    const std::size_t b = map.blockAtRowOrder(n);
    ASSERT_LT(b, map.blockCount());
    EXPECT_FALSE(seen[b]);
    seen[b] = true;
    EXPECT_EQ(map.rowOrderOf(b), n);
    const Eigen::Vector3i rel = map.blockCoords(b);
    EXPECT_TRUE((rel.array() >= 0).all() && (rel.array() < map.blockDims().array()).all());
  }
}

}  // namespace
}  // namespace sonarcarve
