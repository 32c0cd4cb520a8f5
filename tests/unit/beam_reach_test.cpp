// The elevation beam's reach (pipeline/beam_reach.h), from the fates of a first surface's
// points: a beam as declared whose views only carve ghosts keeps the declared first null; a
// beam cut short is found within a band of its cut; too few points tell nothing.
#include "pipeline/beam_reach.h"

#include <gtest/gtest.h>

#include <random>

#include "common/angles.h"
#include "pipeline/surface_kept.h"

namespace sonarcarve {
namespace {

constexpr double kHalf = 10.0;       // degrees: a 20 degree aperture
constexpr double kFirstNull = 22.6;  // its sinc^2 main lobe's first null

// `points` points, each seen at views every `spacing` degrees from the axis out to `widest`
// (uniform over points), a share `ghosts` of them carved at a uniform elevation (ghosts),
// and, past `cut`, every point carved at its first view there.
std::vector<PointFate> fates(std::size_t points, double ghosts, double cut, double spacing,
                             unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<PointFate> out(points);
  for (PointFate& fate : out) {
    fate.widest_view = degToRad(kHalf + unit(random) * (kFirstNull - kHalf));
    if (unit(random) < ghosts) {
      fate.carved_at = degToRad(kHalf + unit(random) * (kFirstNull - kHalf));
    }
    const double offset = unit(random) * spacing;  // this point's views: offset + k spacing
    for (double e = offset; degToRad(e) <= fate.widest_view; e += spacing) {
      if (e > cut) {
        fate.carved_at = std::min(fate.carved_at, degToRad(e));
        break;
      }
    }
  }
  return out;
}

TEST(BeamReach, ABeamAsDeclaredKeepsItsFirstNull) {
  // Ghosts carved across the tails: 30 % of the points over 12.6 degrees, about 1.2 % of those
  // standing a half degree, as the riser's pass measured as declared.
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const ElevationReach reach =
        reachFromFates(fates(4000, 0.3, 90.0, 0.6, seed), degToRad(kHalf), degToRad(kFirstNull));
    EXPECT_FALSE(reach.shortened()) << seed;
    EXPECT_DOUBLE_EQ(reach.reach_rad, degToRad(kFirstNull));
    EXPECT_EQ(reach.bands.size(), 26u);  // (22.6 - 10) / 0.5, rounded up
  }
}

TEST(BeamReach, ABeamCutShortIsFoundWithinABandOfItsCut) {
  for (double cut : {11.0, 13.6, 17.0, 20.0}) {
    const ElevationReach reach =
        reachFromFates(fates(4000, 0.3, cut, 0.6, 7), degToRad(kHalf), degToRad(kFirstNull));
    ASSERT_TRUE(reach.shortened()) << cut;
    // A point's first view past the cut lies up to a view's spacing (0.6 degree) past it, and
    // the reach is a band's inner edge (0.5 degree): within a band and a spacing of the cut.
    EXPECT_NEAR(radToDeg(reach.reach_rad), cut, 0.5 + 0.6) << cut;
    EXPECT_LE(radToDeg(reach.reach_rad), cut + 0.6) << cut;
  }
}

TEST(BeamReach, ViewsThatCarveManyPointsEverywhereLeaveTheBeamAsDeclared) {
  // A first surface of ghosts from a short mission: the tails carve 30 % of them a band from
  // the aperture's edge, as the declared beam's tails should.
  std::vector<PointFate> ghosts(4000);
  std::mt19937 random(5);
  std::exponential_distribution<double> carved(1.0 / degToRad(1.5));
  for (PointFate& fate : ghosts) {
    fate.widest_view = degToRad(kFirstNull);
    fate.carved_at = degToRad(kHalf) + carved(random);
  }
  const ElevationReach reach = reachFromFates(ghosts, degToRad(kHalf), degToRad(kFirstNull));
  EXPECT_GT(reach.bands[0].hazard(), kCliffHazard);  // the case the plateau rule is for
  EXPECT_FALSE(reach.shortened());
}

TEST(BeamReach, TooFewPointsTellNothing) {
  const ElevationReach reach =
      reachFromFates(fates(50, 0.3, 13.6, 0.6, 3), degToRad(kHalf), degToRad(kFirstNull));
  EXPECT_FALSE(reach.shortened());
}

TEST(BeamReach, TheChoiceWarnsOnlyWhenTheReachIsShortened) {
  const ElevationReach declared =
      reachFromFates(fates(4000, 0.3, 90.0, 0.6, 1), degToRad(kHalf), degToRad(kFirstNull));
  const ElevationReach cut =
      reachFromFates(fates(4000, 0.3, 13.6, 0.6, 1), degToRad(kHalf), degToRad(kFirstNull));
  EXPECT_FALSE(elevationReachChoice(declared).warning);
  const RunChoice choice = elevationReachChoice(cut);
  EXPECT_TRUE(choice.warning);
  EXPECT_NE(choice.reason.find("shorter than declared"), std::string::npos);
  EXPECT_FALSE(choice.action.empty());
}

}  // namespace
}  // namespace sonarcarve

namespace sonarcarve {
namespace {

TEST(FirstSurfaceKept, CountsThePointsWithASurfacePointWithinTwoVoxels) {
  const double voxel = 0.02;
  // 100 points 10 cm apart; the run's surface 1.5 voxels off the first `near` of them and 10
  // voxels off the next 30.
  const auto surfaceFor = [](int near) {
    std::vector<Eigen::Vector3f> surface;
    for (int i = 0; i < near + 30; ++i) {
      surface.emplace_back(0.1f * static_cast<float>(i), 5.0f + (i < near ? 0.03f : 0.2f), 2.0f);
    }
    return surface;
  };
  std::vector<Eigen::Vector3f> first;
  for (int i = 0; i < 100; ++i) {
    first.emplace_back(0.1f * static_cast<float>(i), 5.0f, 2.0f);
  }
  const FirstSurfaceKept lost = firstSurfaceKept(first, surfaceFor(20), voxel);
  EXPECT_EQ(lost.first_points, 100u);
  EXPECT_EQ(lost.kept, 20u);
  EXPECT_TRUE(firstSurfaceKeptChoice(lost).warning);
  const FirstSurfaceKept kept = firstSurfaceKept(first, surfaceFor(60), voxel);
  EXPECT_EQ(kept.kept, 60u);
  EXPECT_FALSE(firstSurfaceKeptChoice(kept).warning);
  EXPECT_EQ(firstSurfaceKeptChoice(kept).value, "60 %");
}

}  // namespace
}  // namespace sonarcarve
