// The simulator's frames stay bit-for-bit what they were before it was rebuilt on the shared
// forward-model pieces (core/model/): the checksums below were computed by the simulator as it
// was at commit 37b6e1e, before core/model/ existed, on this test's scenes and poses. A change
// that moves any bit of a frame changes them: if that change is meant (a fix of the imaging
// model), say why in the commit and update the numbers.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>

#include "common/angles.h"
#include "sim/ray_caster.h"
#include "sim/scene_shapes.h"
#include "sim/sonar_simulator.h"
#include "support/sim_scenes.h"

namespace sonarcarve {
namespace {

// FNV-1a over the frame's bytes, row by row.
std::uint64_t checksum(const cv::Mat& frame) {
  std::uint64_t hash = 1469598103934665603ULL;
  for (int row = 0; row < frame.rows; ++row) {
    const auto* bytes = frame.ptr<unsigned char>(row);
    for (std::size_t i = 0; i < frame.cols * frame.elemSize(); ++i) {
      hash = (hash ^ bytes[i]) * 1099511628211ULL;
    }
  }
  return hash;
}

// A wall, a tube in front of it and a sphere, seen by a pitched, yawed sonar.
std::uint64_t frameChecksum(SimulatedBeam beam, double spreading_exponent) {
  Scene scene = test::plate({6.0, 0.0, 0.0}, {-1.0, 0.0, 0.2}, 8.0, 0.7f);
  scene.append(tubeShape({4.0, -0.5, -2.0}, {4.2, -0.4, 2.0}, 0.3, 48, 0.9f));
  scene.append(sphereShape({3.0, 1.0, 0.5}, 0.4, 0.5f));
  const SonarModel sonar("identity", RangeBins{0.5, 0.02, 400},
                         BearingTable::uniform(degToRad(90), 96), degToRad(20));
  ImagingSettings settings;
  settings.beam = beam;
  settings.spreading_exponent = spreading_exponent;
  ThreadPool pool(2);
  const RayCaster caster(scene);
  const SonarSimulator simulator(caster, sonar, settings, pool);
  Eigen::Isometry3d T_world_sonar = Eigen::Isometry3d::Identity();
  T_world_sonar.translate(Eigen::Vector3d(0.1, -0.2, 0.3));
  T_world_sonar.rotate(Eigen::AngleAxisd(degToRad(7), Eigen::Vector3d::UnitZ()));
  T_world_sonar.rotate(Eigen::AngleAxisd(degToRad(-5), Eigen::Vector3d::UnitY()));
  const cv::Mat frame = simulator.render(T_world_sonar);
  EXPECT_GT(cv::sum(frame)[0], 0.0);
  return checksum(frame);
}

TEST(SimFrameIdentity, RealisticBeamFrameIsUnchanged) {
  EXPECT_EQ(frameChecksum(SimulatedBeam::Realistic, 0.0), 14167578767752698861ULL);
}

TEST(SimFrameIdentity, ClippedBeamFrameWithSpreadingIsUnchanged) {
  EXPECT_EQ(frameChecksum(SimulatedBeam::Clipped, 1.0), 1919254743664327564ULL);
}

}  // namespace
}  // namespace sonarcarve
