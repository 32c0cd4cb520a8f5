#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "common/error.h"
#include "io/mission/nav_csv.h"
#include "sim/trajectory.h"
#include "sonar/attitude.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

InspectionTarget riserLike() {
  return {Eigen::Vector3d(1.0, 2.0, 15.0), 10.0, 20.0, 20.0};
}

TEST(Trajectory, VerticalInspectionFacesTheAxisAtTheStandoffInEvenSteps) {
  TrajectorySpec spec;
  const Trajectory t = makeTrajectory(spec, riserLike());
  // From 1 m above the top (9 m) to 1.8 m above the seabed (18.2 m), every 10 cm.
  ASSERT_EQ(t.poses.size(), 93u);
  for (std::size_t i = 0; i < t.poses.size(); ++i) {
    const Eigen::Isometry3d T = t.T_world_sonar(i);
    EXPECT_NEAR(T.translation().z(), 9.0 + 0.1 * static_cast<double>(i), 1e-9);
    const Eigen::Vector3d to_axis(1.0 - T.translation().x(), 2.0 - T.translation().y(), 0.0);
    EXPECT_NEAR(to_axis.norm(), spec.standoff_m, 1e-9);
    EXPECT_GT((T.linear() * Eigen::Vector3d::UnitX()).dot(to_axis.normalized()), 0.9999);
    if (i > 0) {
      EXPECT_NEAR(t.poses[i].time_s - t.poses[i - 1].time_s, spec.step_m / spec.speed_mps, 1e-9);
    }
  }
}

TEST(Trajectory, OrbitCirclesTheAxisFacingIt) {
  TrajectorySpec spec;
  spec.kind = "orbit";
  const Trajectory t = makeTrajectory(spec, riserLike());
  ASSERT_GT(t.poses.size(), 200u);
  for (std::size_t i = 0; i < t.poses.size(); i += 17) {
    const Eigen::Isometry3d T = t.T_world_sonar(i);
    const Eigen::Vector3d to_axis(1.0 - T.translation().x(), 2.0 - T.translation().y(), 0.0);
    EXPECT_NEAR(to_axis.norm(), spec.standoff_m, 1e-6);
    EXPECT_GT((T.linear() * Eigen::Vector3d::UnitX()).dot(to_axis.normalized()), 0.9999);
  }
}

// Where the sonar's axis passes the structure's vertical axis through (1, 2): the depth there
// and how far from it the axis passes.
struct AxisCrossing {
  double depth_m = 0.0;
  double miss_m = 0.0;
};
AxisCrossing crossingOfAxis(const Eigen::Isometry3d& T_world_sonar) {
  const Eigen::Vector3d p = T_world_sonar.translation();
  const Eigen::Vector3d b = T_world_sonar.linear() * Eigen::Vector3d::UnitX();
  const Eigen::Vector2d to_axis = Eigen::Vector2d(1.0, 2.0) - p.head<2>();
  const double t = to_axis.dot(b.head<2>()) / b.head<2>().squaredNorm();
  const Eigen::Vector3d nearest = p + t * b;
  return {nearest.z(), (nearest.head<2>() - Eigen::Vector2d(1.0, 2.0)).norm()};
}

TEST(Trajectory, OneDescentIsTheVerticalPassAndMoreComeFromEvenHeadings) {
  TrajectorySpec spec;
  const Trajectory vertical = makeTrajectory(spec, riserLike());
  spec.kind = "descents";
  spec.descents = 1;
  const Trajectory one = makeTrajectory(spec, riserLike());
  ASSERT_EQ(one.poses.size(), vertical.poses.size());
  for (std::size_t i = 0; i < one.poses.size(); ++i) {
    EXPECT_EQ(one.T_world_sonar(i).matrix(), vertical.T_world_sonar(i).matrix()) << i;
  }
  spec.descents = 4;
  const Trajectory four = makeTrajectory(spec, riserLike());
  const std::size_t per = vertical.poses.size();
  ASSERT_EQ(four.poses.size(), 4 * per);
  for (std::size_t d = 0; d < 4; ++d) {
    const Eigen::Isometry3d T = four.T_world_sonar(d * per + 5);
    const Eigen::Vector3d to_axis(1.0 - T.translation().x(), 2.0 - T.translation().y(), 0.0);
    EXPECT_NEAR(to_axis.norm(), spec.standoff_m, 1e-9);
    // Heading d * 90 degrees: the direction the sonar looks in.
    const double heading = std::atan2(to_axis.y(), to_axis.x());
    EXPECT_NEAR(std::remainder(heading - d * std::numbers::pi / 2, 2 * std::numbers::pi), 0.0,
                1e-9);
    EXPECT_GT((T.linear() * Eigen::Vector3d::UnitX()).dot(to_axis.normalized()), 0.9999);
    EXPECT_NEAR(T.translation().z(), vertical.T_world_sonar(5).translation().z(), 1e-9);
    if (d > 0) {  // time goes on: the vehicle climbs back and moves round between descents
      EXPECT_GT(four.poses[d * per].time_s, four.poses[d * per - 1].time_s + 1.0);
    }
  }
}

TEST(Trajectory, TiltedDescentsAimTheSonarAxisAtTheDepthsTheLevelOnesInspect) {
  TrajectorySpec spec;
  const Trajectory level = makeTrajectory(spec, riserLike());
  spec.kind = "descents";
  spec.descents = 3;
  spec.view_tilt_deg = -25.0;
  const Trajectory tilted = makeTrajectory(spec, riserLike());
  ASSERT_EQ(tilted.poses.size(), 3 * level.poses.size());
  for (std::size_t i = 0; i < tilted.poses.size(); i += 7) {
    const Eigen::Isometry3d T = tilted.T_world_sonar(i);
    const Eigen::Vector3d boresight = T.linear() * Eigen::Vector3d::UnitX();
    EXPECT_NEAR(boresight.z(), std::sin(degToRad(25.0)), 1e-9);  // looking down
    const AxisCrossing crossing = crossingOfAxis(T);
    EXPECT_NEAR(crossing.miss_m, 0.0, 1e-9);
    const double inspected = level.T_world_sonar(i % level.poses.size()).translation().z();
    EXPECT_NEAR(crossing.depth_m, inspected, 1e-9);
    EXPECT_NEAR(T.translation().z(), inspected - spec.standoff_m * std::tan(degToRad(25.0)), 1e-9);
  }
}

TEST(Trajectory, OrbitLevelsAreLevelCirclesAimedAroundTheAxisPointStepApart) {
  TrajectorySpec spec;
  spec.kind = "orbit";
  spec.orbit_levels = 2;
  spec.level_spacing_m = 1.6;
  spec.view_tilt_deg = -20.0;
  const Trajectory t = makeTrajectory(spec, riserLike());
  const auto per_level =
      static_cast<std::size_t>(std::round(2 * std::numbers::pi * spec.standoff_m / spec.step_m));
  ASSERT_EQ(t.poses.size(), 2 * per_level);
  for (std::size_t i = 0; i < t.poses.size(); ++i) {
    const Eigen::Isometry3d T = t.T_world_sonar(i);
    const Eigen::Vector3d to_axis(1.0 - T.translation().x(), 2.0 - T.translation().y(), 0.0);
    EXPECT_NEAR(to_axis.norm(), spec.standoff_m, 1e-9);
    const AxisCrossing crossing = crossingOfAxis(T);
    EXPECT_NEAR(crossing.miss_m, 0.0, 1e-9);
    // The top level aims 0.8 m above the axis point (15 m), the other 0.8 m below.
    EXPECT_NEAR(crossing.depth_m, i < per_level ? 14.2 : 15.8, 1e-9);
    if (i % per_level != 0) {  // frames step_m apart along the circle (its chord)
      const double gap = (T.translation() - t.T_world_sonar(i - 1).translation()).norm();
      EXPECT_NEAR(gap, spec.step_m, 0.01 * spec.step_m);
    }
  }
  // Kept the seabed clearance above the seabed, whatever they aim at.
  spec.level_spacing_m = 10.0;
  spec.view_tilt_deg = 0.0;
  const Trajectory deep = makeTrajectory(spec, riserLike());
  EXPECT_NEAR(deep.T_world_sonar(deep.poses.size() - 1).translation().z(),
              20.0 - spec.seabed_clearance_m, 1e-9);
  spec.orbit_levels = -1;
  EXPECT_THROW(makeTrajectory(spec, riserLike()), Error);
}

TEST(Trajectory, LawnmowerLooksDownAtTheSeabedFromItsAltitude) {
  TrajectorySpec spec;
  spec.kind = "lawnmower";
  const Trajectory t = makeTrajectory(spec, riserLike());
  ASSERT_GT(t.poses.size(), 100u);
  const Eigen::Isometry3d T = t.T_world_sonar(10);
  EXPECT_NEAR(T.translation().z(), 20.0 - spec.altitude_m, 1e-9);  // the sonar's altitude
  const Eigen::Vector3d boresight = T.linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(boresight.z(), std::sin(degToRad(30)), 1e-9);  // 30 degrees down (+z)
  EXPECT_THROW(makeTrajectory(spec, InspectionTarget{Eigen::Vector3d::Zero(), 1, 2, 0}), Error);
}

TEST(Trajectory, PosesFromACsvAndUnknownKinds) {
  test::ScratchDir dir;
  const auto csv = dir.path() / "poses.csv";
  test::writeText(csv,
                  "time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n0,1,2,3,0,0,90\n"
                  "1,1.5,2,3,0,0,90\n");
  TrajectorySpec spec;
  spec.kind = csv.string();
  const Trajectory t = makeTrajectory(spec, riserLike());
  ASSERT_EQ(t.poses.size(), 2u);
  EXPECT_TRUE(t.poses[1].position_m.isApprox(Eigen::Vector3d(1.5, 2, 3)));
  spec.kind = "zigzag";
  EXPECT_THROW(makeTrajectory(spec, riserLike()), Error);
}

TEST(Trajectory, NavigationErrorIsARandomWalkFromTheTruth) {
  const Trajectory t = makeTrajectory(TrajectorySpec{}, riserLike());
  EXPECT_EQ(withNavigationError(t.poses, {}).front().position_m, t.poses.front().position_m);
  const auto noisy = withNavigationError(t.poses, {0.01, 0.1, 5});
  ASSERT_EQ(noisy.size(), t.poses.size());
  double first = (noisy.front().position_m - t.poses.front().position_m).norm();
  double last = (noisy.back().position_m - t.poses.back().position_m).norm();
  EXPECT_GT(first, 0.0);
  EXPECT_LT(first, 0.1);
  // A random walk of 93 steps of 1 cm per axis drifts about 17 cm: much more than one step.
  EXPECT_GT(last, 0.02);
  EXPECT_EQ(noisy.back().time_s, t.poses.back().time_s);
  EXPECT_EQ(withNavigationError(t.poses, {0.01, 0.1, 5}).back().position_m,
            noisy.back().position_m);  // reproducible
}

TEST(Trajectory, NavigationBiasIsConstantAndWhiteNoiseIsIndependent) {
  const Trajectory t = makeTrajectory(TrajectorySpec{}, riserLike());
  const auto errorAt = [&](const std::vector<NavSample>& recorded, std::size_t i) {
    return Eigen::Vector3d(recorded[i].position_m - t.poses[i].position_m);
  };
  NavErrorSpec walk{0.01, 0.1, 7};
  NavErrorSpec walk_and_bias = walk;
  walk_and_bias.position_bias_m = 0.2;
  const auto a = withNavigationError(t.poses, walk);
  const auto b = withNavigationError(t.poses, walk_and_bias);
  // The bias is one offset for the whole track, added to the same random walk.
  const Eigen::Vector3d bias = errorAt(b, 0) - errorAt(a, 0);
  EXPECT_GT(bias.norm(), 0.0);
  for (std::size_t i = 0; i < t.poses.size(); ++i) {
    EXPECT_LT((errorAt(b, i) - errorAt(a, i) - bias).norm(), 1e-9) << i;
  }
  // White noise: zero mean, its standard deviation per axis, no memory from one sample to the
  // next (a walk's consecutive errors differ by one step; white noise's by sqrt(2) sigma).
  NavErrorSpec white;
  white.position_noise_m = 0.01;
  const auto w = withNavigationError(t.poses, white);
  double sum = 0.0, sum2 = 0.0, diff2 = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Eigen::Vector3d e = errorAt(w, i);
    sum += e.sum();
    sum2 += e.squaredNorm();
    if (i > 0) {
      diff2 += (e - errorAt(w, i - 1)).squaredNorm();
    }
  }
  const double n = 3.0 * static_cast<double>(w.size());
  // Tolerances: the sample statistics of about 280 normal draws (standard error of the
  // variance about 8 %, of the mean 0.06 sigma); 4 standard errors.
  EXPECT_NEAR(sum / n, 0.0, 4.0 * 0.01 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.01, 0.01 * 4.0 * std::sqrt(0.5 / n));
  EXPECT_NEAR(std::sqrt(diff2 / (n - 3.0)), std::sqrt(2.0) * 0.01,
              std::sqrt(2.0) * 0.01 * 4.0 * std::sqrt(1.0 / n));
}

TEST(Trajectory, NavigationErrorReachesOnlyTheChosenAxesWithTheDrawsOfAll) {
  const Trajectory t = makeTrajectory(TrajectorySpec{}, riserLike());
  NavErrorSpec all{0.01, 0.1, 7};
  all.position_bias_m = 0.05;
  all.attitude_noise_deg = 0.05;
  NavErrorSpec some = all;
  some.axes = navAxesFromNames("east,down,pitch");
  const auto a = withNavigationError(t.poses, all);
  const auto s = withNavigationError(t.poses, some);
  ASSERT_EQ(a.size(), s.size());
  double kept_east = 0.0, kept_pitch = 0.0;
  for (std::size_t i = 0; i < t.poses.size(); ++i) {
    const Eigen::Vector3d ea = a[i].position_m - t.poses[i].position_m;
    const Eigen::Vector3d es = s[i].position_m - t.poses[i].position_m;
    // North stays true; east and down carry exactly the error they carry with every axis.
    EXPECT_NEAR(es.x(), 0.0, 1e-12) << i;
    EXPECT_NEAR(es.y(), ea.y(), 1e-12) << i;
    EXPECT_NEAR(es.z(), ea.z(), 1e-12) << i;
    kept_east = std::max(kept_east, std::abs(es.y()));
    // Attitude: the error rotation (vehicle frame) turns about pitch alone: roll and yaw true.
    const RollPitchYaw rs =
        rollPitchYawFromQuaternion(t.poses[i].q_world_vehicle.conjugate() * s[i].q_world_vehicle);
    EXPECT_NEAR(rs.roll_rad, 0.0, 1e-9) << i;
    EXPECT_NEAR(rs.yaw_rad, 0.0, 1e-9) << i;
    kept_pitch = std::max(kept_pitch, std::abs(rs.pitch_rad));
  }
  // The kept axes do drift: a 1 cm, 0.1 degree walk over the track (tens of samples).
  EXPECT_GT(kept_east, 0.01);
  EXPECT_GT(kept_pitch, degToRad(0.1));
}

TEST(Trajectory, NavigationErrorAxesReadAndWriteTheirNames) {
  EXPECT_EQ(navAxesFromNames("all"), kAllNavAxes);
  EXPECT_EQ(navAxesFromNames("north,east,down,roll,pitch,yaw"), kAllNavAxes);
  EXPECT_EQ(navAxesFromNames("yaw,north"), kNavNorth | kNavYaw);
  EXPECT_EQ(navAxesNames(kNavNorth | kNavYaw), "north,yaw");
  EXPECT_EQ(navAxesNames(kAllNavAxes), "all");
  for (const unsigned axes : {unsigned{kNavDown}, kNavRoll | kNavPitch, kNavEast | kNavYaw}) {
    EXPECT_EQ(navAxesFromNames(navAxesNames(axes)), axes);
  }
  for (const char* bad : {"", "north,", "heave", "north;east", "North"}) {
    EXPECT_THROW(navAxesFromNames(bad), Error) << bad;
  }
}

}  // namespace
}  // namespace sonarcarve
