// The mission origin (sonar/mission_origin.h) and the limits around it: a track far from zero
// gets an origin and is moved to it in double; one near zero keeps origin 0, to the bit; map
// keys refuse what they cannot hold, naming the limit; outputs carry the origin and export adds
// it back in double.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "carve/occupancy_export.h"
#include "carve/voxel_map.h"
#include "common/error.h"
#include "io/frame_source.h"
#include "io/mesh/point_cloud_ply.h"
#include "mesh/mesh_export.h"
#include "occlusion/surface_points.h"
#include "sonar/mission_origin.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

NavTrack trackAt(const Eigen::Vector3d& start_m) {
  std::vector<NavSample> samples;
  for (int k = 0; k < 5; ++k) {
    NavSample s;
    s.time_s = k;
    s.position_m = start_m + Eigen::Vector3d(0.0, 0.1 * k, 0.1 * k);
    samples.push_back(s);
  }
  return NavTrack(samples);
}

TEST(MissionOrigin, NearZeroKeepsOriginZero) {
  EXPECT_TRUE(chooseMissionOrigin(trackAt({-5.0, 0.0, 8.3})).isZero());
  EXPECT_TRUE(chooseMissionOrigin(trackAt({kNearZeroLimit_m - 1.0, 0.0, 0.0})).isZero());
}

TEST(MissionOrigin, UtmNavigationGetsTheCentreRoundedToWhole100m) {
  const Eigen::Vector3d origin = chooseMissionOrigin(trackAt({4'999'995.0, 500'012.3, 8.3}));
  EXPECT_EQ(origin, Eigen::Vector3d(5'000'000.0, 500'000.0, 0.0));
  // Beyond the limit on one axis only: that axis moves; the others round to 0.
  EXPECT_EQ(chooseMissionOrigin(trackAt({-5.0, 0.0, 1234.0})), Eigen::Vector3d(0.0, 0.0, 1200.0));
}

TEST(MissionOrigin, TranslationIsInDoubleAndAZeroOneChangesNothing) {
  const NavTrack utm = trackAt({4'999'995.0, 500'000.0, 8.3});
  const NavTrack local = translatedTrack(utm, -Eigen::Vector3d(5'000'000.0, 500'000.0, 0.0));
  // float32 would keep 0.5 m at 5e6 m; double keeps a nanometre.
  EXPECT_NEAR(local.samples()[3].position_m.y(), 0.3, 1e-9);
  EXPECT_NEAR(local.samples()[3].position_m.x(), -5.0, 1e-9);
  NavSample negative_zero;
  negative_zero.position_m = Eigen::Vector3d(-0.0, 1.0, 2.0);
  const NavTrack same = translatedTrack(NavTrack({negative_zero}), Eigen::Vector3d::Zero());
  EXPECT_TRUE(std::signbit(same.samples()[0].position_m.x()));
}

TEST(MissionOrigin, PositionsThatMakeNoSenseAreRefused) {
  test::expectError(
      [] {
        requirePlausiblePosition({1e15, 0.0, 0.0}, "nav.csv", "line 7");
      },
      {"nav.csv", "line 7", "within 1e8 m"});
  test::expectError(
      [] {
        requirePlausiblePosition({std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}, "nav.csv",
                                 "line 3");
      },
      {"nav.csv", "line 3", "finite"});
  EXPECT_NO_THROW(requirePlausiblePosition({5e6, 5e5, 30.0}, "nav.csv", "line 2"));
}

TEST(MissionOrigin, OpenedMissionIsMovedOnceAndRefusesAFarMounting) {
  Mission mission{"survey",
                  "survey",
                  test::paperSonar(),
                  Mounting{},
                  trackAt({4'999'995.0, 500'000.0, 8.3}),
                  {},
                  "",
                  "",
                  nullptr,
                  {},
                  {},
                  Eigen::Vector3d::Zero()};
  placeMissionNearOrigin(mission);
  EXPECT_EQ(mission.origin_ned_m, Eigen::Vector3d(5'000'000.0, 500'000.0, 0.0));
  EXPECT_NEAR(mission.nav.samples()[0].position_m.x(), -5.0, 1e-9);
  placeMissionNearOrigin(mission);  // again: near zero now, nothing changes
  EXPECT_EQ(mission.origin_ned_m, Eigen::Vector3d(5'000'000.0, 500'000.0, 0.0));
  EXPECT_NEAR(worldTrack(mission).samples()[0].position_m.x(), 4'999'995.0, 1e-9);

  mission.mounting.translation_m = Eigen::Vector3d(1e300, 0.0, 0.0);
  test::expectError([&] { placeMissionNearOrigin(mission); },
                    {"survey", "mounting", "within 1000 m"});
}

TEST(MapKeys, VoxelMapRefusesCoordinatesBeyondItsKeysNamingTheLimit) {
  const Eigen::AlignedBox3d utm(Eigen::Vector3d(5e6, 5e5, 0.0),
                                Eigen::Vector3d(5e6 + 1, 5e5 + 1, 1));
  test::expectError([&] { VoxelMap(0.02, utm); }, {"voxel map", "2^25", "671088.64 m"});
  const Eigen::AlignedBox3d near(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  test::expectError([&] { VoxelMap(1e-300, near); }, {"voxel map", "2^25"});
  EXPECT_NO_THROW(VoxelMap(0.02, near));
}

TEST(MapKeys, OctoMapReachIsPlusMinus32768Voxels) {
  const Eigen::AlignedBox3d inside(Eigen::Vector3d(-655.0, -10, 0), Eigen::Vector3d(655.0, 10, 20));
  EXPECT_FALSE(octoMapKeyProblem(inside, 0.02));
  const Eigen::AlignedBox3d beyond(Eigen::Vector3d(690.0, -10, 0), Eigen::Vector3d(710.0, 10, 20));
  const auto problem = octoMapKeyProblem(beyond, 0.02);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("+-655.36 m at 0.02 m voxels"), std::string::npos) << *problem;
  // Writing such a map is refused, never wrapped.
  test::ScratchDir dir;
  test::expectError([&] { writeOccupancyBt(VoxelMap(0.02, beyond), dir.path() / "map.bt"); },
                    {"map.bt", "OctoMap's keys"});
}

TEST(OriginInOutputs, SurfacePointsCarryTheOriginAndExportAddsItBackInDouble) {
  test::ScratchDir dir;
  const Eigen::Vector3d origin(5'000'000.0, 500'000.0, 0.0);
  const SurfacePoints local = {{Eigen::Vector3f(-0.123f, 4.567f, 8.9f), 1.0f, 2},
                               {Eigen::Vector3f(1.001f, -2.002f, 3.003f), 2.0f, 3}};
  writeSurfacePointsPly(local, dir.path() / "points.ply", origin);
  EXPECT_EQ(plyOrigin(dir.path() / "points.ply"), origin);
  writeSurfacePointsPly(local, dir.path() / "near.ply");
  EXPECT_TRUE(plyOrigin(dir.path() / "near.ply").isZero());
  EXPECT_EQ(test::readText(dir.path() / "near.ply").find("origin_ned_m"), std::string::npos);

  ExportOptions world;
  world.mission_origin_ned_m = origin;
  world.add_mission_origin = true;
  exportPoints(local, dir.path() / "world.ply", world);
  const std::string text = test::readText(dir.path() / "world.ply");
  EXPECT_NE(text.find("property double x"), std::string::npos);
  EXPECT_EQ(text.find("origin_ned_m"), std::string::npos) << "world coordinates need no origin";
  // Read back in double through the origin: local again, to the float's own precision.
  const PointCloud back = readPointCloudPly(dir.path() / "world.ply", origin);
  ASSERT_EQ(back.positions.size(), 2u);
  EXPECT_EQ(back.positions[0], local[0].position_m);
  EXPECT_EQ(back.positions[1], local[1].position_m);

  world.format = "stl";
  test::expectError([&] { world.validate(); }, {"STL", "float32", "5000000 500000 0"});
}

}  // namespace
}  // namespace sonarcarve
