// ActiveCells (model/active_cells.h) lets a ray march jump over cells whose samples cannot
// reach min_alpha: the march must keep exactly the samples it keeps without them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/active_cells.h"
#include "model/ray_march.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;

// Blocks of empty voxels with a wall of occupied ones across them and a few faint ones
// scattered, some on the blocks' faces, so that rays cross cells and blocks of every kind.
BlockGrid sparseGrid(std::mt19937& rng) {
  BlockGrid grid(kVoxel, -12.0f);
  for (int x = 0; x < 4; ++x) {
    for (int y = -2; y < 2; ++y) {
      for (int z = -2; z < 2; ++z) {
        if ((x + y + z) % 3 != 0) {  // holes: absent blocks between present ones
          grid.addBlock({x, y, z});
        }
      }
    }
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < grid.voxelCount(); ++i) {
    const Eigen::Vector3i voxel = grid.voxelAt(static_cast<std::int64_t>(i));
    const double r = u(rng);
    grid.logits()[i] = voxel.x() == 20 ? 2.0f : (r < 0.002 ? -5.0f : -12.0f);
  }
  return grid;
}

TEST(ActiveCells, MarchJumpsOverInactiveCellsAndKeepsEverySample) {
  std::mt19937 rng(7);
  const BlockGrid grid = sparseGrid(rng);
  const MarchLimits limits{RangeBins{0.2, 0.01, 200}, 2, 1e-3, 0.0};
  const ActiveCells active = ActiveCells::reaching(grid, limits.min_alpha);
  // Some cells are left out, not all.
  EXPECT_GT(active.activeShare(), 0.05);
  EXPECT_LT(active.activeShare(), 0.95);
  StencilReader every(grid);
  StencilReader skipping(grid, &active);
  std::uniform_real_distribution<double> angle(-0.6, 0.6);
  std::vector<RaySample> all;
  std::vector<RaySample> some;
  std::size_t kept = 0;
  for (int ray = 0; ray < 2000; ++ray) {
    const Eigen::Vector3d origin(-0.3, angle(rng) * 0.2, angle(rng) * 0.2);
    const Eigen::Vector3d d =
        Eigen::Vector3d(1.0, std::tan(angle(rng)), std::tan(angle(rng))).normalized();
    marchRay(every, kVoxel, origin, d, d, limits, all);
    marchRay(skipping, kVoxel, origin, d, d, limits, some);
    ASSERT_EQ(all.size(), some.size()) << ray;
    for (std::size_t i = 0; i < all.size(); ++i) {
      EXPECT_EQ(all[i].range_m, some[i].range_m);
      EXPECT_EQ(all[i].alpha, some[i].alpha);
      EXPECT_EQ(all[i].transmittance, some[i].transmittance);
    }
    kept += all.size();
  }
  EXPECT_GT(kept, 1000u);
}

TEST(ActiveCells, EveryCellIsActiveWhenEmptyVoxelsReachTheThreshold) {
  BlockGrid grid(kVoxel, -2.0f);
  grid.addBlock({0, 0, 0});
  EXPECT_EQ(ActiveCells(grid, -3.0).activeShare(), 1.0);
  EXPECT_EQ(ActiveCells(grid, -1.0).activeShare(), 0.0);
  EXPECT_EQ(ActiveCells::reaching(grid, 0.0).activeShare(), 1.0);
}

}  // namespace
}  // namespace sonarcarve
