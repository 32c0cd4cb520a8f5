// The seabed under the demo scenes: flat as it always was by default; with a relief, a
// heightfield levelled where the structure stands, which the ray caster meets where downAt()
// says (so the ground truth and the seen points follow it) and which what rests on the seabed
// touches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/error.h"
#include "sim/demo_scenes.h"
#include "sim/ray_caster.h"
#include "sim/scene_seabed.h"
#include "sim/scene_shapes.h"

namespace sonarcarve {
namespace {

SeabedReliefSpec relief(double amplitude_m) {
  SeabedReliefSpec spec;
  spec.relief_m = amplitude_m;
  return spec;
}

TEST(SceneSeabed, WithoutReliefItIsTheFlatSquareAsBefore) {
  const SceneSeabed seabed(20.0, 3.0, SeabedReliefSpec{});
  EXPECT_TRUE(seabed.flat());
  const Scene mesh = seabed.mesh(24.0, 48, 0.3f);
  const Scene square = seabedSquare({0, 0, 20.0}, 24.0, 3.0, 48, 0.3f);
  EXPECT_EQ(mesh.vertices, square.vertices);
  EXPECT_EQ(mesh.triangles, square.triangles);
  EXPECT_DOUBLE_EQ(seabed.downAt(2.0, 5.0), 20.0 + 2.0 * std::tan(3.0 * std::numbers::pi / 180));
}

TEST(SceneSeabed, ReliefIsLevelledAtTheSiteAndUndulatesAroundIt) {
  const SceneSeabed seabed(20.0, 0.0, relief(0.3), {1.0, -2.0}, 2.5);
  EXPECT_FALSE(seabed.flat());
  for (const double r : {0.0, 1.0, 2.4}) {
    EXPECT_DOUBLE_EQ(seabed.downAt(1.0 + r, -2.0), 20.0) << r;
  }
  double lo = 20.0;
  double hi = 20.0;
  for (double n = -14.0; n <= 14.0; n += 0.25) {
    for (double e = -14.0; e <= 14.0; e += 0.25) {
      lo = std::min(lo, seabed.downAt(n, e));
      hi = std::max(hi, seabed.downAt(n, e));
    }
  }
  // The waves' offset from the site's is within twice the amplitude; three waves of 6 to 12 m
  // over 28 m reach a good part of it.
  EXPECT_GE(lo, 20.0 - 0.6);
  EXPECT_LE(hi, 20.0 + 0.6);
  EXPECT_GT(hi - lo, 0.3);
  SeabedReliefSpec bad = relief(-1.0);
  EXPECT_THROW(SceneSeabed(20.0, 0.0, bad), Error);
}

// Rays cast straight down meet the relief's mesh where downAt() says, within the sag of a
// quarter-metre grid on the relief's curvature (a few millimetres) and float rounding.
TEST(SceneSeabed, TracedSeabedFollowsTheRelief) {
  for (const std::string name : {"riser", "manifold", "seabed-objects", "jacket-node"}) {
    const Scene scene = makeDemoScene(name, relief(0.3));
    const RayCaster caster(scene);
    const SceneSeabed seabed(20.0, name == "seabed-objects" ? 3.0 : 0.0, relief(0.3), {0, 0},
                             name == "manifold" ? 2.5 : (name == "seabed-objects" ? 0.0 : 1.0));
    int checked = 0;
    for (double n = -9.0; n <= 9.0; n += 0.7) {
      for (const double e : {-9.1, -7.3, 6.7, 8.9}) {  // clear of the structures and objects
        RayHit hit;
        ASSERT_TRUE(
            caster.intersect(Eigen::Vector3f(static_cast<float>(n), static_cast<float>(e), 15.0f),
                             Eigen::Vector3f::UnitZ(), 10.0f, hit))
            << name;
        EXPECT_NEAR(15.0 + hit.distance, seabed.downAt(n, e), 0.005)
            << name << " " << n << " " << e;
        ++checked;
      }
    }
    EXPECT_GT(checked, 100) << name;
  }
}

TEST(SceneSeabed, StructuresStandOnTheRelief) {
  // The jacket node gets a seabed at 20 m to stand on, and its target says so.
  EXPECT_DOUBLE_EQ(makeDemoScene("jacket-node").target.seabed_down_m, 0.0);
  EXPECT_DOUBLE_EQ(makeDemoScene("jacket-node", relief(0.3)).target.seabed_down_m, 20.0);
  // The riser's cables end on the seabed: their lowest points lie on it, wherever it rises.
  const Scene riser = makeDemoScene("riser", relief(0.3));
  const SceneSeabed seabed(20.0, 0.0, relief(0.3), {0, 0}, 1.0);
  for (const double east : {5.2, -5.2}) {
    const double floor = seabed.downAt(-3.0, east);
    EXPECT_GT(std::abs(floor - 20.0), 1e-3);  // the relief is there
    float deepest_cable = 0.0f;
    for (const Eigen::Vector3f& v : riser.vertices) {
      if ((v.head<2>() - Eigen::Vector2f(-3.0f, static_cast<float>(east))).norm() < 0.1f) {
        deepest_cable = std::max(deepest_cable, v.z());
      }
    }
    // The cable's end cap (0.05 m radius, tilted) reaches within its radius of the seabed.
    EXPECT_NEAR(deepest_cable, floor, 0.06) << east;
  }
}

}  // namespace
}  // namespace sonarcarve
