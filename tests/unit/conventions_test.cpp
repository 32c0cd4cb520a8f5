// Checks every convention of docs/conventions.md by round trips and named directions.
#include <gtest/gtest.h>

#include <random>

#include "common/angles.h"
#include "sonar/attitude.h"
#include "sonar/mounting.h"
#include "sonar/nav_track.h"
#include "sonar/sonar_model.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

const Eigen::Vector3d kForward = Eigen::Vector3d::UnitX();
const Eigen::Vector3d kStarboard = Eigen::Vector3d::UnitY();
const Eigen::Vector3d kDown = Eigen::Vector3d::UnitZ();

TEST(Conventions, BearingIsPositiveToStarboard) {
  const Polar p = polarFromPoint(Eigen::Vector3d(1.0, 1.0, 0.0));
  EXPECT_NEAR(p.bearing_rad, degToRad(45), 1e-12);
  EXPECT_NEAR(polarFromPoint(Eigen::Vector3d(1.0, -1.0, 0.0)).bearing_rad, -degToRad(45), 1e-12);
  // Column 0 is the most port beam, the last column the most starboard.
  const SonarModel sonar = test::paperSonar();
  EXPECT_LT(sonar.bearings().centre(0), 0.0);
  EXPECT_EQ(sonar.pixelOf(Eigen::Vector3d(3.0, 0.5, 0.0))->col > sonar.cols() / 2, true);
}

TEST(Conventions, ElevationIsPositiveUpwardsWhichIsMinusZ) {
  EXPECT_NEAR(polarFromPoint(Eigen::Vector3d(1.0, 0.0, -1.0)).elevation_rad, degToRad(45), 1e-12);
  const Eigen::Vector3d up = pointFromPolar({2.0, 0.0, degToRad(10)});
  EXPECT_LT(up.z(), 0.0);
}

TEST(Conventions, RowsRunFromNearToFar) {
  const SonarModel sonar = test::paperSonar();
  EXPECT_EQ(sonar.pixelOf(Eigen::Vector3d(0.01, 0.0, 0.0))->row, 0);
  EXPECT_EQ(sonar.pixelOf(Eigen::Vector3d(9.99, 0.0, 0.0))->row, sonar.rows() - 1);
}

TEST(Conventions, PolarToPointToPolarRoundTrips) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> range(0.1, 50.0), bearing(-3.1, 3.1), elev(-1.5, 1.5);
  for (int i = 0; i < 1000; ++i) {
    const Polar in{range(rng), bearing(rng), elev(rng)};
    const Polar out = polarFromPoint(pointFromPolar(in));
    ASSERT_NEAR(out.range_m, in.range_m, 1e-9);
    ASSERT_NEAR(out.bearing_rad, in.bearing_rad, 1e-9);
    ASSERT_NEAR(out.elevation_rad, in.elevation_rad, 1e-9);
  }
}

TEST(Conventions, YawTurnsTheBowFromNorthToEast) {
  const auto r = quaternionFromRollPitchYaw({0, 0, degToRad(90)});
  EXPECT_TRUE((r * kForward).isApprox(Eigen::Vector3d::UnitY(), 1e-12));  // east
}

TEST(Conventions, PositivePitchRaisesTheBow) {
  const auto r = quaternionFromRollPitchYaw({0, degToRad(10), 0});
  const Eigen::Vector3d bow = r * kForward;
  EXPECT_LT(bow.z(), 0.0);  // up is -down
  EXPECT_NEAR(bow.z(), -std::sin(degToRad(10)), 1e-12);
}

TEST(Conventions, PositiveRollLowersStarboard) {
  const auto r = quaternionFromRollPitchYaw({degToRad(10), 0, 0});
  EXPECT_GT((r * kStarboard).z(), 0.0);
  EXPECT_NEAR((r * kDown).y(), -std::sin(degToRad(10)), 1e-12);
}

TEST(Conventions, RollPitchYawRoundTripsThroughQuaternions) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-3.1, 3.1), pitch(-1.5, 1.5);
  for (int i = 0; i < 1000; ++i) {
    const RollPitchYaw in{angle(rng), pitch(rng), angle(rng)};
    const RollPitchYaw out = rollPitchYawFromQuaternion(quaternionFromRollPitchYaw(in));
    ASSERT_NEAR(out.roll_rad, in.roll_rad, 1e-9);
    ASSERT_NEAR(out.pitch_rad, in.pitch_rad, 1e-9);
    ASSERT_NEAR(out.yaw_rad, in.yaw_rad, 1e-9);
  }
}

TEST(Conventions, MountingComposesVehicleThenSonar) {
  // Vehicle at (10, 20, 30) heading east; sonar 1 m forward of its origin, tilted 30 deg down.
  NavTrack track({NavSample{0.0, {10, 20, 30}, quaternionFromRollPitchYaw({0, 0, degToRad(90)})},
                  NavSample{1.0, {10, 20, 30}, quaternionFromRollPitchYaw({0, 0, degToRad(90)})}});
  const Mounting mounting{{1.0, 0.0, 0.0}, {0.0, degToRad(-30), 0.0}};
  const Eigen::Isometry3d T_world_sonar = track.T_world_sonar(0.5, mounting.T_vehicle_sonar());
  EXPECT_TRUE(T_world_sonar.translation().isApprox(Eigen::Vector3d(10, 21, 30), 1e-12));
  // A target on the sonar's boresight at 4 m is east and below the sonar.
  const Eigen::Vector3d target = T_world_sonar * pointFromPolar({4.0, 0.0, 0.0});
  EXPECT_NEAR(target.x(), 10.0, 1e-12);
  EXPECT_NEAR(target.y(), 21.0 + 4.0 * std::cos(degToRad(30)), 1e-12);
  EXPECT_NEAR(target.z(), 30.0 + 4.0 * std::sin(degToRad(30)), 1e-12);
}

TEST(Conventions, WorldPointToPixelAndBackStaysWithinOnePixel) {
  // The full chain the carving relies on: world -> sonar -> pixel -> sonar -> world.
  const SonarModel sonar = test::paperSonar();
  NavTrack track({NavSample{0.0, {0, 0, 5}, quaternionFromRollPitchYaw({0.05, -0.1, 0.7})},
                  NavSample{2.0, {1, 0.5, 6}, quaternionFromRollPitchYaw({-0.05, 0.1, 0.9})}});
  const Mounting mounting{{0.4, -0.1, 0.2}, {0.0, degToRad(-15), degToRad(5)}};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double t = 2.0 * u(rng);
    const Eigen::Isometry3d T_world_sonar = track.T_world_sonar(t, mounting.T_vehicle_sonar());
    const Polar truth{0.5 + 9.0 * u(rng), degToRad(-60 + 120 * u(rng)), degToRad(-9 + 18 * u(rng))};
    const Eigen::Vector3d p_world = T_world_sonar * pointFromPolar(truth);
    const auto pixel = sonar.pixelOf(T_world_sonar.inverse() * p_world);
    ASSERT_TRUE(pixel);
    Polar back = sonar.pixelCentre(*pixel);
    back.elevation_rad = truth.elevation_rad;
    ASSERT_NEAR(back.range_m, truth.range_m, 0.5 * sonar.range().resolution_m + 1e-9);
    ASSERT_NEAR(back.bearing_rad, truth.bearing_rad, degToRad(0.1) + 1e-9);
  }
}

}  // namespace
}  // namespace sonarcarve
