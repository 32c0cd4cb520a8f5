// `shadow_aware_carving: auto` (pipeline/shadow_carving.h): on where the views look at the
// scene from headings far apart, off along one pass.
#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "pipeline/shadow_carving.h"

namespace sonarcarve {
namespace {

// A frame whose sonar looks along compass heading `heading_deg`, pitched `pitch_deg` (NED:
// yaw about down, then pitch; negative pitch looks down).
PosedFrame looking(double heading_deg, double pitch_deg = 0.0) {
  PosedFrame f;
  f.T_world_sonar.linear() = (Eigen::AngleAxisd(degToRad(heading_deg), Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(degToRad(pitch_deg), Eigen::Vector3d::UnitY()))
                                 .toRotationMatrix();
  return f;
}

TEST(ShadowCarvingChoice, HeadingSpreadIsTheSmallestArcHoldingEveryHeading) {
  EXPECT_NEAR(headingSpreadDeg({looking(0), looking(0), looking(0)}), 0.0, 1e-9);
  EXPECT_NEAR(headingSpreadDeg({looking(0), looking(90)}), 90.0, 1e-9);
  // Across north: 350 and 10 degrees are 20 apart, not 340.
  EXPECT_NEAR(headingSpreadDeg({looking(350), looking(10)}), 20.0, 1e-9);
  // A lawnmower's lines go both ways.
  EXPECT_NEAR(headingSpreadDeg({looking(0), looking(180), looking(0)}), 180.0, 1e-9);
  // An orbit: every heading, 10 degrees apart.
  std::vector<PosedFrame> orbit;
  for (int h = 0; h < 360; h += 10) {
    orbit.push_back(looking(h));
  }
  EXPECT_NEAR(headingSpreadDeg(orbit), 350.0, 1e-9);
}

TEST(ShadowCarvingChoice, FramesLookingStraightDownHaveNoHeading) {
  // Pitched 85 degrees down, the sonar's axis is 5 degrees off the vertical: no heading.
  EXPECT_NEAR(headingSpreadDeg({looking(0), looking(120, -85.0)}), 0.0, 1e-9);
  EXPECT_NEAR(headingSpreadDeg({looking(0), looking(120, -30.0)}), 120.0, 1e-9);
  EXPECT_EQ(headingSpreadDeg({}), 0.0);
}

TEST(ShadowCarvingChoice, AutoIsOnForSeveralSidesAndOffAlongOnePass) {
  const std::vector<PosedFrame> one_pass{looking(0), looking(2), looking(-3)};
  const std::vector<PosedFrame> two_sides{looking(0), looking(90)};
  EXPECT_FALSE(chooseShadowCarving(ShadowCarving::Auto, one_pass).on);
  EXPECT_TRUE(chooseShadowCarving(ShadowCarving::Auto, two_sides).on);
  EXPECT_NE(chooseShadowCarving(ShadowCarving::Auto, two_sides).choice.detail.find("90 degrees"),
            std::string::npos);
  // The user's choice stands either way.
  EXPECT_TRUE(chooseShadowCarving(ShadowCarving::On, one_pass).on);
  EXPECT_FALSE(chooseShadowCarving(ShadowCarving::Off, two_sides).on);
}

}  // namespace
}  // namespace sonarcarve
