// Pages set aside (carve/page_spill.h): a page of the block map written to the temporary file
// and held again reads back exactly as it was (every block state, values, counts, stamps and
// the views' visits), the file's room is reused, and bytes that are not a page are refused.
#include <gtest/gtest.h>

#include <array>

#include "carve/page_spill.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

using Values = std::array<float, VoxelMap::kBlockVoxels>;

// 4 x 4 x 4 m at 2 cm: 4^3 pages of 8^3 blocks.
const Eigen::AlignedBox3d kBox(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3.99, 3.99, 3.99));

// Fills page `page` with blocks of every kind, different for each `seed`.
void fillPage(VoxelMap& map, std::size_t page, int seed) {
  const std::size_t first = page * VoxelMap::kPageBlocks;
  Values edge{}, lit{};
  for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
    edge[i] = (i + seed) % 3 == 0 ? VoxelMap::kUnknown : 0.0f;
    lit[i] = (i + seed) % 5 == 0 ? 1.5f * static_cast<float>(i + seed) : edge[i];
  }
  map.storeBlock(first + 1, edge.data(), 11 + seed);            // Partial
  map.storeBlock(first + 2, nullptr, 12 + seed);                // Free
  map.storeBlock(first + 3 + seed, lit.data(), 13);             // Mixed
  map.storeBlock(first + 100, lit.data(), 14, nullptr, false);  // Mixed, kept as floats
  if (std::uint8_t* counts = map.counts(first + 100)) {
    for (int i = 0; i < VoxelMap::kCountBytes; ++i) {
      counts[i] = static_cast<std::uint8_t>(i * 7 + seed);
    }
  }
  map.markVisited(first + 1, 900 + seed);
}

struct BlockCopy {
  VoxelMap::BlockState state;
  std::uint32_t stamp;
  Values values;
  std::vector<std::uint8_t> counts;
};

std::vector<BlockCopy> copyPage(const VoxelMap& map, std::size_t page) {
  std::vector<BlockCopy> out;
  for (std::size_t b = page * VoxelMap::kPageBlocks; b < (page + 1) * VoxelMap::kPageBlocks; ++b) {
    BlockCopy c{map.state(b), map.stamp(b), {}, {}};
    map.copyValues(b, c.values.data());
    if (const std::uint8_t* v = map.views(b)) {
      c.counts.assign(v, v + VoxelMap::kCountBytes);
    }
    out.push_back(c);
  }
  return out;
}

void expectSamePage(const std::vector<BlockCopy>& a, const std::vector<BlockCopy>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].state, b[i].state) << "block " << i;
    EXPECT_EQ(a[i].stamp, b[i].stamp) << "block " << i;
    EXPECT_EQ(a[i].values, b[i].values) << "block " << i;
    EXPECT_EQ(a[i].counts, b[i].counts) << "block " << i;
  }
}

TEST(PageSpill, APageSetAsideIsHeldAgainExactlyAsItWas) {
  for (bool counts : {false, true}) {
    VoxelMap map(0.02, kBox, counts);
    PageSpill spill;
    const std::vector<std::size_t> pages{0, 5, 21, 63};
    std::vector<std::vector<BlockCopy>> before;
    for (std::size_t n = 0; n < pages.size(); ++n) {
      fillPage(map, pages[n], static_cast<int>(n));
      before.push_back(copyPage(map, pages[n]));
    }
    const std::size_t held_bytes = map.memoryBytes();
    for (std::size_t page : pages) {
      spill.setAside(map, page);
      EXPECT_FALSE(map.pageHeld(page));
      EXPECT_TRUE(spill.isAside(page));
    }
    EXPECT_EQ(map.pagesHeld(), 0u);
    EXPECT_EQ(map.occupiedCount(), 0u);
    // Held again in another order, each reads back as it was, and the map's storage is
    // reused (no more chunks than before).
    for (std::size_t n : {2u, 0u, 3u, 1u}) {
      spill.holdAgain(map, pages[n]);
      EXPECT_FALSE(spill.isAside(pages[n]));
      expectSamePage(copyPage(map, pages[n]), before[n]);
    }
    EXPECT_EQ(map.memoryBytes(), held_bytes);
    // The views' visits came back too: a block visited at 900 is not cold at 905.
    map.compactColdBlocks(905, 8);
    expectSamePage(copyPage(map, pages[0]), before[0]);
    EXPECT_EQ(spill.pagesSetAside(), 4u);
    EXPECT_EQ(spill.pagesAside(), 0u);
  }
}

TEST(PageSpill, TheFileReusesTheRoomOfPagesHeldAgain) {
  VoxelMap map(0.02, kBox);
  PageSpill spill;
  for (std::size_t page = 0; page < 8; ++page) {
    fillPage(map, page, static_cast<int>(page % 3));
  }
  for (std::size_t page = 0; page < 8; ++page) {
    spill.setAside(map, page);
  }
  const std::uint64_t eight_pages = spill.fileBytes();
  EXPECT_GT(eight_pages, 0u);
  // Cycling pages through the file, as a survey's lines do, does not grow it.
  for (int round = 0; round < 20; ++round) {
    for (std::size_t page : {std::size_t{1}, std::size_t{6}, std::size_t{3}}) {
      spill.holdAgain(map, page);
    }
    for (std::size_t page : {std::size_t{6}, std::size_t{3}, std::size_t{1}}) {
      spill.setAside(map, page);
    }
  }
  EXPECT_LE(spill.fileBytes(), eight_pages);
  for (std::size_t page = 0; page < 8; ++page) {
    spill.holdAgain(map, page);
  }
  EXPECT_EQ(spill.fileBytes(), 0u);  // all room given back and joined
  // A page not set aside, or not held, is left as it is.
  const auto before = copyPage(map, 2);
  spill.holdAgain(map, 2);
  expectSamePage(copyPage(map, 2), before);
  spill.setAside(map, 40);
  EXPECT_FALSE(spill.isAside(40));
}

TEST(PageSpill, BytesThatAreNotAPageAreRefused) {
  VoxelMap map(0.02, kBox);
  fillPage(map, 7, 1);
  const std::vector<std::uint8_t> bytes = map.packPage(7);
  EXPECT_THROW(map.unpackPage(7, bytes), Error);  // held already
  map.releasePage(7);
  std::vector<std::uint8_t> truncated(bytes.begin(), bytes.end() - 3);
  EXPECT_THROW(map.unpackPage(7, truncated), Error);
  EXPECT_FALSE(map.pageHeld(7));
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_THROW(map.unpackPage(7, longer), Error);
  EXPECT_FALSE(map.pageHeld(7));
  std::vector<std::uint8_t> bad_state = bytes;
  bad_state[0] = 9;
  EXPECT_THROW(map.unpackPage(7, bad_state), Error);
  EXPECT_THROW(map.unpackPage(7, {}), Error);
  EXPECT_THROW((void)map.packPage(8), Error);  // not held
  map.unpackPage(7, bytes);
  EXPECT_EQ(map.state(7 * VoxelMap::kPageBlocks + 2), VoxelMap::BlockState::Free);
}

}  // namespace
}  // namespace sonarcarve
