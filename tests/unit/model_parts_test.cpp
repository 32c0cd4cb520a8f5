// The forward model's parts: the block grid's keys and indices (model/block_grid.h) and the
// elevation profile's spline (model/elevation_profile.h).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "common/angles.h"
#include "common/error.h"
#include "model/block_grid.h"
#include "model/elevation_profile.h"

namespace sonarcarve {
namespace {

TEST(ModelBlockGrid, KeysAreDistinctAcrossSignsAndLimitsAndNeverWrap) {
  const int limit = 1 << 20;
  std::set<std::int64_t> keys;
  for (const int a : {-limit, -1, 0, 1, limit - 1}) {
    for (const int b : {-limit, -1, 0, 1, limit - 1}) {
      for (const int c : {-limit, -1, 0, 1, limit - 1}) {
        keys.insert(BlockGrid::blockKey({a, b, c}));
      }
    }
  }
  EXPECT_EQ(keys.size(), 125u);
  EXPECT_THROW(BlockGrid::blockKey({limit, 0, 0}), Error);
  EXPECT_THROW(BlockGrid::blockKey({0, -limit - 1, 0}), Error);
  BlockGrid grid(0.02);
  Eigen::Vector3i voxel;
  EXPECT_FALSE(grid.voxelOf({1e9, 0.0, 0.0}, voxel));  // beyond +-2^23 voxels
  EXPECT_FALSE(grid.voxelOf({std::nan(""), 0.0, 0.0}, voxel));
  EXPECT_EQ(grid.findBlock({limit, 0, 0}), -1);
}

TEST(ModelBlockGrid, VoxelsOnBothSidesOfZeroRoundTrip) {
  BlockGrid grid(0.05);
  for (const Eigen::Vector3i& v : {Eigen::Vector3i(-1, -1, -1), Eigen::Vector3i(0, 0, 0),
                                   Eigen::Vector3i(-9, 7, 8), Eigen::Vector3i(123, -456, 789)}) {
    const std::int64_t index = grid.addVoxel(v);
    EXPECT_EQ(grid.voxelIndex(v), index);
    EXPECT_EQ(grid.voxelAt(index), v);
    Eigen::Vector3i back;
    ASSERT_TRUE(grid.voxelOf(grid.voxelCentre(v), back));
    EXPECT_EQ(back, v);
    EXPECT_EQ(grid.logits()[static_cast<std::size_t>(index)], grid.emptyLogit());
  }
  EXPECT_EQ(grid.voxelIndex({-17, 0, 0}), -1);  // block (-3, 0, 0) was never added
  EXPECT_EQ(grid.blockCount(), 4);
  EXPECT_TRUE(grid.bounds().contains(grid.voxelCentre({123, -456, 789})));
}

TEST(ModelElevationProfile, ReproducesAGaussianAndIsSymmetric) {
  // A gaussian is a parabola in dB; a Catmull-Rom spline reproduces it but in its last segment,
  // where the profile continues linearly.
  const double theta_max = degToRad(40);
  const int knots = 9;
  const auto gaussian = [](double t) { return -3.0 * std::pow(t / degToRad(10), 2); };
  std::vector<double> db;
  for (int m = 0; m < knots; ++m) {
    db.push_back(gaussian(theta_max * m / (knots - 1)));
  }
  const ElevationProfile profile(theta_max, db);
  const double last_knot = theta_max * (knots - 2) / (knots - 1);
  for (double t = 0.0; t < last_knot; t += degToRad(0.37)) {
    EXPECT_NEAR(profile.levelDb(t), gaussian(t), 1e-9) << radToDeg(t);
    EXPECT_EQ(profile.levelDb(-t), profile.levelDb(t));
  }
  // The weights sum to one: a constant profile stays constant.
  const ElevationProfile flat(theta_max, std::vector<double>(knots, -7.0));
  for (double t = 0.0; t <= theta_max; t += degToRad(0.9)) {
    EXPECT_NEAR(flat.levelDb(t), -7.0, 1e-12);
  }
}

TEST(ModelElevationProfile, StartsFromTheDeclaredPatterns) {
  const double aperture = degToRad(20);
  const SincSquaredBeam beam(aperture);
  const ElevationProfile sinc2 = ElevationProfile::sincSquared(aperture, beam.null(2), 13);
  for (int m = 0; m < 13; ++m) {
    const double t = sinc2.knotAngle(m);
    EXPECT_NEAR(sinc2.power(t), std::max(beam.power(t), 1e-4), 1e-9) << m;
  }
  EXPECT_NEAR(sinc2.levelDb(0.5 * aperture), -3.0, 0.1);  // between knots: the spline
  const BeamPattern clipped_pattern(aperture);
  const ElevationProfile clipped = ElevationProfile::clipped(clipped_pattern, degToRad(30), 7);
  EXPECT_NEAR(clipped.power(0.0), 1.0, 1e-12);
  EXPECT_NEAR(clipped.levelDb(degToRad(30)), -40.0, 1e-9);  // past the first null: the floor
  EXPECT_THROW(ElevationProfile(degToRad(10), {0.0, -1.0}), Error);
}

}  // namespace
}  // namespace sonarcarve
