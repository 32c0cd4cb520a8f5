// HoloOcean / NeuSIS datasets (io/holoocean/): the frames' conventions against HoloOcean's own
// (docs/conventions.md, "HoloOcean / NeuSIS datasets"), a small dataset of the test writer's
// read back through openMission frame for frame and pose for pose, and one written by Python's
// pickle and numpy itself (tests/data/holoocean/).
#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "io/frame_source.h"
#include "io/holoocean/holoocean_frames.h"
#include "sonar/attitude.h"
#include "support/pickle_writer.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

// float32's rounding of a pose of metres and unit vectors.
constexpr double kFloat32 = 1e-6;

Eigen::Matrix4d holoPose(double yaw_deg, const Eigen::Vector3d& p) {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(degToRad(yaw_deg), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.topRightCorner<3, 1>() = p;
  return T;
}

TEST(HoloOceanFrames, XForwardYLeftZUpBecomesNorthEastDown) {
  // HoloOcean's x is north, its y (left) west, its z up.
  const Eigen::Isometry3d T = nedPoseFromHoloOcean(holoPose(0.0, {1.0, 2.0, -3.0}));
  EXPECT_TRUE(T.translation().isApprox(Eigen::Vector3d(1.0, -2.0, 3.0)));
  EXPECT_TRUE(T.linear().isIdentity(1e-12));
  // A yaw of +90 degrees in HoloOcean turns x (forward) towards y (left, west): heading west,
  // our yaw -90 (ours turns north towards east).
  const Eigen::Isometry3d west = nedPoseFromHoloOcean(holoPose(90.0, Eigen::Vector3d::Zero()));
  const RollPitchYaw rpy = rollPitchYawFromQuaternion(Eigen::Quaterniond(west.linear()));
  EXPECT_NEAR(radToDeg(rpy.yaw_rad), -90.0, 1e-9);
  // The sonar's forward axis points west, its starboard (our y) north.
  EXPECT_TRUE((west.linear() * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitY()));
  EXPECT_TRUE((west.linear() * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitX()));
}

TEST(HoloOceanFrames, TheConversionRoundTrips) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = quaternionFromRollPitchYaw({0.1, -0.3, 2.0}).toRotationMatrix();
  T.translation() = Eigen::Vector3d(-5.0, 7.0, 12.0);
  const Eigen::Isometry3d back = nedPoseFromHoloOcean(holoOceanPoseFromNed(T));
  EXPECT_TRUE(back.matrix().isApprox(T.matrix(), 1e-12));
}

TEST(HoloOceanDataset, ADatasetOpensFrameForFrameAndPoseForPose) {
  test::ScratchDir dir;
  const SonarModel sonar("any", RangeBins{1.0, 0.05, 6}, BearingTable::uniform(degToRad(60.0), 4),
                         degToRad(12.0));
  test::writeText(dir.path() / "Config.json", test::neusisConfigJson(sonar));
  std::filesystem::create_directories(dir.path() / "Data");
  for (int k = 0; k < 3; ++k) {
    cv::Mat holo(6, 4, CV_32F, cv::Scalar(0.0F));
    holo.at<float>(2 + k, 0) = 0.75F;  // HoloOcean's column 0: the starboard edge
    const std::string name = "frame_" + std::to_string(k * 5) + ".pkl";  // 0, 5, 10: natural order
    test::writeText(
        dir.path() / "Data" / name,
        test::holoOceanFramePickle(holo, holoPose(30.0 * k, {k * 1.0, 0.5, -4.0}), 2 + k));
  }
  const Mission mission = openMission(dir.path());
  EXPECT_EQ(mission.source->kind(), "HoloOcean / NeuSIS dataset");
  ASSERT_EQ(mission.frames.size(), 3U);
  EXPECT_EQ(mission.sonar.rows(), 6);
  EXPECT_EQ(mission.sonar.cols(), 4);
  EXPECT_NEAR(mission.sonar.range().min_m, 1.0, 1e-12);
  EXPECT_NEAR(mission.sonar.range().resolution_m, 0.05, 1e-12);
  EXPECT_NEAR(radToDeg(mission.sonar.bearings().fieldOfView()), 60.0, 1e-9);
  EXPECT_EQ(mission.sonar.elevationBeam(), ElevationBeam::Clipped);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(mission.frames[k].file, "Data/frame_" + std::to_string(k * 5) + ".pkl");
    const Frame frame = loadFrame(mission, k);
    EXPECT_EQ(frame.image.at<float>(2 + static_cast<int>(k), 3), 0.75F) << "starboard is last";
    EXPECT_EQ(cv::sum(frame.image)[0], 0.75);
    const Eigen::Isometry3d T = worldTrack(mission).T_world_sonar(
        mission.frames[k].time_s, mission.mounting.T_vehicle_sonar());
    EXPECT_TRUE(T.translation().isApprox(Eigen::Vector3d(k * 1.0, -0.5, 4.0), kFloat32))
        << T.translation().transpose();
    const RollPitchYaw rpy = rollPitchYawFromQuaternion(Eigen::Quaterniond(T.linear()));
    EXPECT_NEAR(radToDeg(rpy.yaw_rad), -30.0 * static_cast<double>(k), 1e-4);
  }
}

TEST(HoloOceanDataset, PicklesWrittenByNumpyReadBack) {
  // tests/data/holoocean/make_numpy_pickles.py: frame k in protocol 2 + k, its image's bright
  // pixel at row k + 1 of HoloOcean's column 0 (0.5 + k), its pose a yaw of 30 k degrees at
  // (k, 0.5, -4); frame 1's image in Fortran order, frame 2's pose big-endian float64.
  const Mission mission = openMission(test::testData("holoocean"));
  ASSERT_EQ(mission.frames.size(), 4U);
  EXPECT_TRUE(mission.warnings.empty()) << mission.warnings.front();
  EXPECT_NEAR(mission.sonar.range().resolution_m, 1.0, 1e-12);
  EXPECT_EQ(mission.sonar.cols(), 6);
  const NavTrack world = worldTrack(mission);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(mission.frames[k].file, "Data/" + std::to_string(5 * k) + ".pkl");
    EXPECT_NEAR(mission.frames[k].time_s, 0.2 * static_cast<double>(k), 1e-12) << "5 Hz";
    const Frame frame = loadFrame(mission, k);
    EXPECT_EQ(frame.image.at<float>(static_cast<int>(k) + 1, 5), 0.5F + static_cast<float>(k));
    EXPECT_EQ(cv::sum(frame.image)[0], 0.5 + static_cast<double>(k));
    const Eigen::Isometry3d T =
        world.T_world_sonar(mission.frames[k].time_s, mission.mounting.T_vehicle_sonar());
    EXPECT_TRUE(
        T.translation().isApprox(Eigen::Vector3d(static_cast<double>(k), -0.5, 4.0), kFloat32));
    const RollPitchYaw rpy = rollPitchYawFromQuaternion(Eigen::Quaterniond(T.linear()));
    EXPECT_NEAR(radToDeg(rpy.yaw_rad), -30.0 * static_cast<double>(k), 1e-4);
  }
}

}  // namespace
}  // namespace sonarcarve
