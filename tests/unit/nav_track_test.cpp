#include <gtest/gtest.h>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/attitude.h"
#include "sonar/nav_track.h"

namespace sonarcarve {
namespace {

NavTrack twoSampleTrack() {
  return NavTrack({NavSample{10.0, {0, 0, 0}, quaternionFromRollPitchYaw({0, 0, 0})},
                   NavSample{12.0, {2, -4, 6}, quaternionFromRollPitchYaw({0, 0, degToRad(90)})},
                   NavSample{13.0, {2, -4, 7}, quaternionFromRollPitchYaw({0, 0, degToRad(90)})}});
}

TEST(NavTrack, ReturnsTheSampleExactlyAtSampleTimes) {
  const NavTrack track = twoSampleTrack();
  for (const NavSample& s : track.samples()) {
    const Eigen::Isometry3d pose = track.T_world_vehicle(s.time_s);
    EXPECT_LT((pose.translation() - s.position_m).norm(), 1e-12);
    EXPECT_TRUE(Eigen::Quaterniond(pose.linear()).isApprox(s.q_world_vehicle, 1e-12));
  }
}

TEST(NavTrack, InterpolatesPositionLinearlyAndAttitudeBySlerp) {
  const NavTrack track = twoSampleTrack();
  const Eigen::Isometry3d quarter = track.T_world_vehicle(10.5);
  EXPECT_TRUE(quarter.translation().isApprox(Eigen::Vector3d(0.5, -1.0, 1.5), 1e-12));
  const RollPitchYaw rpy = rollPitchYawFromQuaternion(Eigen::Quaterniond(quarter.linear()));
  EXPECT_NEAR(rpy.yaw_rad, degToRad(22.5), 1e-12);  // slerp is uniform in angle
  EXPECT_NEAR(rpy.roll_rad, 0.0, 1e-12);
  EXPECT_NEAR(rpy.pitch_rad, 0.0, 1e-12);
  EXPECT_TRUE(track.T_world_vehicle(12.5).translation().isApprox(Eigen::Vector3d(2, -4, 6.5)));
}

TEST(NavTrack, TimeOutsideTheTrackIsAnErrorNotAGuess) {
  const NavTrack track = twoSampleTrack();
  EXPECT_THROW(track.T_world_vehicle(9.999), Error);
  EXPECT_THROW(track.T_world_vehicle(13.001), Error);
  EXPECT_NO_THROW(track.T_world_vehicle(10.0));
  EXPECT_NO_THROW(track.T_world_vehicle(13.0));
  try {
    track.T_world_vehicle(20.0);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("outside the navigation track"), std::string::npos);
  }
}

TEST(NavTrack, RejectsEmptyUnorderedOrNonFiniteSamples) {
  const auto at = [](double t) {
    NavSample s;
    s.time_s = t;
    return s;
  };
  EXPECT_THROW(NavTrack({}), Error);
  EXPECT_THROW(NavTrack({at(1.0), at(1.0)}), Error);
  EXPECT_THROW(NavTrack({at(2.0), at(1.0)}), Error);
  EXPECT_THROW(NavTrack({at(NAN)}), Error);
  NavSample nan_position = at(0.0);
  nan_position.position_m.x() = NAN;
  EXPECT_THROW(NavTrack({nan_position}), Error);
  NavSample zero_attitude = at(0.0);
  zero_attitude.q_world_vehicle.coeffs().setZero();
  EXPECT_THROW(NavTrack({zero_attitude}), Error);
}

}  // namespace
}  // namespace sonarcarve
