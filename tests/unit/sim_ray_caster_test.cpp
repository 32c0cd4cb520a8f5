// RayCaster's fans of rays (sim/ray_caster.h) against the same rays cast one at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/error.h"
#include "sim/demo_scenes.h"
#include "sim/ray_caster.h"
#include "sim/trajectory.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {
namespace {

// The rays of one sub-ray of a sonar beam, spaced as the simulator's: 904 elevations 0.1 degree
// apart over +-45.2 degrees, at the middle of each step (never at 0).
std::vector<Eigen::Vector3f> elevationFan(const Eigen::Matrix3f& R, double bearing_rad) {
  std::vector<Eigen::Vector3f> fan;
  for (int k = 0; k < 904; ++k) {
    const double elevation_deg = -45.2 + (k + 0.5) * 0.1;
    fan.push_back(R * pointFromPolar({1.0, bearing_rad, degToRad(elevation_deg)}).cast<float>());
  }
  return fan;
}

TEST(SimRayCaster, FansHitWhatRaysCastOneAtATimeHit) {
  for (const std::string name : {"riser", "seabed-objects"}) {
    const Scene scene = makeDemoScene(name);
    const RayCaster caster(scene);
    TrajectorySpec spec;
    spec.kind = usualTrajectory(name);
    const Trajectory trajectory = makeTrajectory(spec, scene.target);
    std::size_t hits = 0;
    for (const std::size_t frame : {std::size_t{0}, trajectory.poses.size() / 2}) {
      const Eigen::Isometry3d T = trajectory.T_world_sonar(frame);
      const Eigen::Matrix3f R = T.linear().cast<float>();
      const Eigen::Vector3f origin = T.translation().cast<float>();
      // 904 rays: packets of 16 and a last, partial one. Bearings a quarter beam off the beam
      // edges and elevations half a step off 0, as the simulator's are: a ray at bearing 0 or
      // elevation 0 runs in the riser's seam plane or along a ring of its mesh at the sonar's
      // depth, through edges shared by two triangles, which Embree's fast (not watertight)
      // tests may pass on either side, differently in the two paths.
      for (double bearing_deg = -63.95; bearing_deg <= 64.0; bearing_deg += 8.0) {
        const std::vector<Eigen::Vector3f> fan = elevationFan(R, degToRad(bearing_deg));
        std::vector<RayHit> fan_hits(fan.size());
        caster.intersectFan(origin, fan, 10.0f, fan_hits);
        for (std::size_t i = 0; i < fan.size(); ++i) {
          RayHit one;
          const bool found = caster.intersect(origin, fan[i], 10.0f, one);
          ASSERT_EQ(fan_hits[i].found, found) << name << " ray " << i;
          if (!found) {
            continue;
          }
          ++hits;
          // Both are float computations of the same intersection: a few units of rounding.
          const float rounding = 8.0f * std::numeric_limits<float>::epsilon() * one.distance;
          EXPECT_NEAR(fan_hits[i].distance, one.distance, rounding) << name << " ray " << i;
          EXPECT_EQ(fan_hits[i].triangle, one.triangle) << name << " ray " << i;
          EXPECT_LT((fan_hits[i].normal - one.normal).norm(), 1e-5f) << name << " ray " << i;
        }
      }
    }
    EXPECT_GT(hits, 1000u) << name;  // the fans meet the scene
  }
}

TEST(SimRayCaster, RefusesAFanWithTooFewHitSlots) {
  const RayCaster caster(makeDemoScene("riser"));
  const std::vector<Eigen::Vector3f> fan(20, Eigen::Vector3f::UnitX());
  std::vector<RayHit> hits(19);
  EXPECT_THROW(caster.intersectFan(Eigen::Vector3f::Zero(), fan, 10.0f, hits), Error);
}

}  // namespace
}  // namespace sonarcarve
