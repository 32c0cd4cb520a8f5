#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "io/nav_csv.h"
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

}  // namespace
}  // namespace sonarcarve
