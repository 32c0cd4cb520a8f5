// The 3D view's level of detail (widgets/map_lod.h) against a model of what the map sent: the
// points held never pass the budget, every occupied block is held with all its voxels counted,
// a block sent empty is gone at whatever level it was held, and below the budget the view
// holds every voxel as sent. Also how a layer draws points that stand for several voxels.
#include <gtest/gtest.h>

#include <vtkPolyData.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

#include "carve/voxel_map.h"
#include "map_layers.h"
#include "map_lod.h"

namespace sonarcarve::widgets {
namespace {

constexpr double kVoxel_m = 0.02;
constexpr int kSide = VoxelMap::kBlockSide;

// Blocks of a 16 x 16 x 2 grid of blocks, numbered as a map's block table would be.
Eigen::Vector3i blockCoords(std::size_t id) {
  return {static_cast<int>(id % 16), static_cast<int>((id / 16) % 16), static_cast<int>(id / 256)};
}

// A block of `id` with `count` of its 512 voxels occupied (drawn at random), their values and
// errors made up, changed at frame `frames_done`.
MapViewBlock randomBlock(std::size_t id, int count, std::size_t frames_done, std::mt19937& rng) {
  std::vector<int> voxels(VoxelMap::kBlockVoxels);
  std::iota(voxels.begin(), voxels.end(), 0);
  std::shuffle(voxels.begin(), voxels.end(), rng);
  MapViewBlock b;
  b.block = id;
  b.frames_done = frames_done;
  std::uniform_real_distribution<float> value(100.0f, 3000.0f);
  for (int k = 0; k < count; ++k) {
    const int i = voxels[static_cast<std::size_t>(k)];
    const Eigen::Vector3i voxel =
        blockCoords(id) * kSide + Eigen::Vector3i(i % kSide, (i / kSide) % kSide, i / 64);
    b.points.push_back(((voxel.cast<double>().array() + 0.5) * kVoxel_m).matrix().cast<float>());
    b.values.push_back(value(rng));
    b.errors_m.push_back(value(rng) * 1e-5f);
  }
  return b;
}

// The map as last sent, block by block, and a random update of it (some blocks emptied).
struct SentMap {
  std::map<std::size_t, MapViewBlock> blocks;
  std::size_t frames = 0;

  std::vector<MapViewBlock> update(std::mt19937& rng, std::size_t block_range) {
    frames += 4;
    std::vector<MapViewBlock> changed;
    std::uniform_int_distribution<std::size_t> pick(0, block_range - 1);
    std::uniform_int_distribution<int> count(0, 200);
    for (int n = 0; n < 12; ++n) {
      MapViewBlock b = randomBlock(pick(rng), count(rng) < 30 ? 0 : count(rng), frames, rng);
      if (b.points.empty()) {
        blocks.erase(b.block);
      } else {
        blocks[b.block] = b;
      }
      changed.push_back(std::move(b));
    }
    return changed;
  }
  std::size_t voxels() const {
    std::size_t n = 0;
    for (const auto& [id, b] : blocks) {
      n += b.points.size();
    }
    return n;
  }
};

// Every voxel sent is in its block as held, within a cell of the block's level of a point held
// (the centroid of the cell's voxels lies in the cell).
void expectEveryVoxelRepresented(const SentMap& sent, const MapLod& lod) {
  ASSERT_EQ(lod.blocks().size(), sent.blocks.size());
  for (const auto& [id, b] : sent.blocks) {
    const auto held = lod.blocks().find(id);
    ASSERT_NE(held, lod.blocks().end()) << "block " << id;
    EXPECT_EQ(held->second.voxelCount(), b.points.size()) << "block " << id;
    const double cell_m = kVoxel_m * (1 << std::min(held->second.level, MapLod::kBlockLevel));
    for (const Eigen::Vector3f& voxel : b.points) {
      double nearest = 1e9;
      for (const Eigen::Vector3f& p : held->second.points) {
        nearest = std::min(nearest, static_cast<double>((p - voxel).norm()));
      }
      EXPECT_LE(nearest, std::sqrt(3.0) * cell_m + 1e-6) << "block " << id;
    }
  }
}

TEST(MapLod, HoldsEveryVoxelAsSentBelowTheBudget) {
  std::mt19937 rng(1);
  SentMap sent;
  MapLod lod(1000000, kVoxel_m);
  for (int u = 0; u < 60; ++u) {
    lod.apply(sent.update(rng, 512));
  }
  ASSERT_GT(sent.voxels(), 10000u);
  EXPECT_EQ(lod.pointCount(), sent.voxels());
  EXPECT_EQ(lod.voxelCount(), sent.voxels());
  ASSERT_EQ(lod.blocks().size(), sent.blocks.size());
  for (const auto& [id, b] : sent.blocks) {
    const MapViewBlock& held = lod.blocks().at(id);
    EXPECT_EQ(held.level, 0);
    EXPECT_EQ(held.points, b.points);
    EXPECT_EQ(held.values, b.values);
    EXPECT_EQ(held.errors_m, b.errors_m);
    EXPECT_TRUE(held.voxels.empty());
  }
}

TEST(MapLod, NeverHoldsMorePointsThanTheBudgetAndRepresentsEveryVoxel) {
  std::mt19937 rng(2);
  SentMap sent;
  constexpr std::size_t kBudget = 3000;
  MapLod lod(kBudget, kVoxel_m);
  int coarsest = 0;
  for (int u = 0; u < 120; ++u) {
    lod.apply(sent.update(rng, 512));
    ASSERT_LE(lod.pointCount(), kBudget) << "update " << u;
    ASSERT_EQ(lod.voxelCount(), sent.voxels()) << "update " << u;
    std::size_t points = 0;
    for (const auto& [id, b] : lod.blocks()) {
      points += b.points.size();
      coarsest = std::max(coarsest, b.level);
    }
    ASSERT_EQ(points, lod.pointCount());
  }
  EXPECT_GT(sent.voxels(), 4 * kBudget);  // the budget did bind
  EXPECT_GE(coarsest, 2);
  expectEveryVoxelRepresented(sent, lod);
}

TEST(MapLod, BlocksChangedLongestAgoAreTheCoarsest) {
  std::mt19937 rng(3);
  MapLod lod(4000, kVoxel_m);
  for (std::size_t id = 0; id < 200; ++id) {
    lod.apply({randomBlock(id, 100, 4 * id, rng)});
  }
  ASSERT_LE(lod.pointCount(), 4000u);
  int newer_level = 0;
  for (auto b = lod.blocks().rbegin(); b != lod.blocks().rend(); ++b) {
    EXPECT_GE(b->second.level, newer_level) << "block " << b->first;
    newer_level = b->second.level;
  }
  EXPECT_EQ(lod.blocks().rbegin()->second.level, 0);  // the newest keep every voxel
  EXPECT_GT(lod.blocks().begin()->second.level, 0);
}

TEST(MapLod, ABlockSentEmptyIsGoneAtEveryLevel) {
  std::mt19937 rng(4);
  MapLod lod(4000, kVoxel_m);
  for (std::size_t id = 0; id < 200; ++id) {
    lod.apply({randomBlock(id, 100, 4 * id, rng)});
  }
  std::map<int, std::size_t> one_per_level;  // a block held at each level
  for (const auto& [id, b] : lod.blocks()) {
    one_per_level.emplace(b.level, id);
  }
  ASSERT_GE(one_per_level.size(), 3u);
  for (const auto& [level, id] : one_per_level) {
    const std::size_t points = lod.pointCount() - lod.blocks().at(id).points.size();
    const std::size_t voxels = lod.voxelCount() - lod.blocks().at(id).voxelCount();
    MapViewBlock emptied;
    emptied.block = id;
    lod.apply({emptied});
    EXPECT_FALSE(lod.blocks().contains(id)) << "level " << level;
    EXPECT_EQ(lod.pointCount(), points) << "level " << level;
    EXPECT_EQ(lod.voxelCount(), voxels) << "level " << level;
    // No point held lies in the emptied block's box.
    const Eigen::Vector3d corner = blockCoords(id).cast<double>() * kSide * kVoxel_m;
    const Eigen::AlignedBox3d box(corner, corner + Eigen::Vector3d::Constant(kSide * kVoxel_m));
    for (const auto& [other, b] : lod.blocks()) {
      for (const Eigen::Vector3f& p : b.points) {
        EXPECT_FALSE(box.contains(p.cast<double>())) << "block " << other;
      }
    }
  }
}

TEST(MapLod, ABlockSentAgainIsHeldAtFullDetail) {
  std::mt19937 rng(5);
  MapLod lod(4000, kVoxel_m);
  for (std::size_t id = 0; id < 200; ++id) {
    lod.apply({randomBlock(id, 100, 4 * id, rng)});
  }
  ASSERT_GT(lod.blocks().at(0).level, 0);
  lod.setMaxPoints(lod.pointCount() + 50);  // room for it at full detail
  const MapViewBlock again = randomBlock(0, 50, 900, rng);
  lod.apply({again});
  EXPECT_EQ(lod.blocks().at(0).level, 0);
  EXPECT_EQ(lod.blocks().at(0).points, again.points);
}

TEST(MapLod, ACoarserPointIsTheMeanOfItsVoxels) {
  std::mt19937 rng(6);
  const MapViewBlock block = randomBlock(37, 300, 8, rng);
  for (int level = 1; level <= MapLod::kBlockLevel; ++level) {
    const MapViewBlock direct = coarsened(block, level, kVoxel_m);
    // Through the finer levels, each point weighing its voxels: the same means.
    MapViewBlock stepped = block;
    for (int l = 1; l <= level; ++l) {
      stepped = coarsened(stepped, l, kVoxel_m);
    }
    ASSERT_EQ(direct.points.size(), stepped.points.size());
    EXPECT_EQ(direct.voxels, stepped.voxels);
    EXPECT_EQ(direct.voxelCount(), block.points.size());
    for (std::size_t k = 0; k < direct.points.size(); ++k) {
      EXPECT_LT((direct.points[k] - stepped.points[k]).norm(), 1e-4 * kVoxel_m);
      EXPECT_NEAR(direct.values[k], stepped.values[k], 1e-3);
    }
  }
  const MapViewBlock whole = coarsened(block, MapLod::kBlockLevel, kVoxel_m);
  ASSERT_EQ(whole.points.size(), 1u);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double value = 0.0;
  for (std::size_t k = 0; k < block.points.size(); ++k) {
    centroid += block.points[k].cast<double>();
    value += block.values[k];
  }
  const auto n = static_cast<double>(block.points.size());
  EXPECT_LT((whole.points[0].cast<double>() - centroid / n).norm(), 1e-4 * kVoxel_m);
  EXPECT_NEAR(whole.values[0], value / n, 1e-3);
}

TEST(MapLayers, APointStandingForStrideVoxelsOrMoreIsAlwaysDrawn) {
  std::mt19937 rng(7);
  std::vector<MapViewBlock> blocks;
  for (std::size_t id = 0; id < 40; ++id) {
    const MapViewBlock b = randomBlock(id, 200, 0, rng);
    blocks.push_back(id % 2 == 0 ? b : coarsened(b, MapLod::kBlockLevel, kVoxel_m));
  }
  std::vector<const MapViewBlock*> all;
  for (const MapViewBlock& b : blocks) {
    all.push_back(&b);
  }
  const std::size_t voxels = voxelsInside(all, nullptr);
  ASSERT_EQ(voxels, 40u * 200u);
  const std::size_t stride = strideFor(voxels, 1000);
  const PreparedLayer layer = preparePoints(all, nullptr, stride, ColourBy::Intensity);
  const auto drawn = static_cast<std::size_t>(layer.poly->GetNumberOfPoints());
  EXPECT_LE(drawn, (voxels + stride - 1) / stride);
  // The 20 whole-block points (200 voxels each, more than the stride) are all drawn.
  std::size_t block_points_drawn = 0;
  for (vtkIdType i = 0; i < layer.poly->GetNumberOfPoints(); ++i) {
    double p[3];
    layer.poly->GetPoint(i, p);
    for (std::size_t id = 1; id < 40; id += 2) {
      block_points_drawn +=
          (Eigen::Vector3d(p[0], p[1], p[2]) - blocks[id].points[0].cast<double>()).norm() < 1e-6
              ? 1
              : 0;
    }
  }
  EXPECT_EQ(block_points_drawn, 20u);
  // At full detail, every stride-th voxel, as before levels of detail.
  const PreparedLayer full = preparePoints({&blocks[0]}, nullptr, 3, ColourBy::Intensity);
  ASSERT_EQ(full.poly->GetNumberOfPoints(), (200 + 2) / 3);
  for (vtkIdType i = 0; i < full.poly->GetNumberOfPoints(); ++i) {
    double p[3];
    full.poly->GetPoint(i, p);
    EXPECT_EQ(Eigen::Vector3d(p[0], p[1], p[2]).cast<float>(),
              blocks[0].points[static_cast<std::size_t>(3 * i)]);
  }
}

}  // namespace
}  // namespace sonarcarve::widgets
