// The demo scenes as built: every name builds a scene with its inspection target,
// and the manifold holds what it is for (large faces that look up, beside pipes, on a seabed).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "common/error.h"
#include "sim/demo_scenes.h"
#include "sim/trajectory.h"

namespace sonarcarve {
namespace {

// Area of the horizontal faces (normal within 30 degrees of vertical, the evaluator's split) whose
// triangles' centres lie in the box [lo, hi].
double horizontalArea(const Scene& scene, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  double area = 0.0;
  for (const auto& t : scene.triangles) {
    const Eigen::Vector3f a = scene.vertices[t[0]], b = scene.vertices[t[1]],
                          c = scene.vertices[t[2]];
    const Eigen::Vector3f centre = (a + b + c) / 3.0f;
    if ((centre.array() < lo.array()).any() || (centre.array() > hi.array()).any()) {
      continue;
    }
    const Eigen::Vector3f n = (b - a).cross(c - a);
    if (std::abs(n.z()) >= std::cos(30.0f * 3.14159265f / 180.0f) * n.norm()) {
      area += 0.5 * n.norm();
    }
  }
  return area;
}

TEST(DemoScenes, EveryNameBuildsASceneWithItsTrajectory) {
  for (const std::string& name : demoSceneNames()) {
    const Scene scene = makeDemoScene(name);
    EXPECT_EQ(scene.name, name);
    EXPECT_FALSE(scene.triangles.empty()) << name;
    EXPECT_EQ(scene.reflectivity.size(), scene.triangles.size()) << name;
    TrajectorySpec spec;
    spec.kind = usualTrajectory(name);
    EXPECT_GT(makeTrajectory(spec, scene.target).poses.size(), 50u) << name;
  }
  EXPECT_THROW(makeDemoScene("nothing"), Error);
}

TEST(DemoScenes, TheManifoldHasLargeHorizontalFacesAboveTheSeabed) {
  const Scene scene = makeDemoScene("manifold");
  // Above the seabed (20 m) by more than 5 cm: the mud mat's top (3.6 x 2.8 m, 10 square
  // metres), the body's roof (2.4 x 1.6 m) and the valve deck, at least 13 square metres.
  const Eigen::Vector3f lo(-5.0f, -5.0f, 17.0f), hi(5.0f, 5.0f, 19.95f);
  EXPECT_GT(horizontalArea(scene, lo, hi), 13.0);
  EXPECT_NEAR(scene.target.seabed_down_m, 20.0, 1e-9);
  EXPECT_GT(scene.target.bottom_down_m, scene.target.top_down_m);
}

}  // namespace
}  // namespace sonarcarve
