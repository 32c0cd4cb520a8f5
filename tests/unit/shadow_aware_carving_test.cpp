// Shadow-aware carving (CarveParams::shadow_aware, fast engine): the dark pixels of a
// structure's acoustic shadow do not carve what other views saw behind it, while the water in
// front of the structure and beside it is carved as before.
#include <gtest/gtest.h>

#include <cmath>

#include "carve/carver.h"
#include "carve/voxel_map.h"
#include "common/angles.h"

namespace sonarcarve {
namespace {

constexpr double kAperture = degToRad(20.0);
constexpr double kVoxel = CarveParams::kDefaultVoxelSize_m;
constexpr float kBright = 10000.0f;  // counts on the beam's axis

// 2 cm bins from 1 m to 6 m, 1-degree beams over 21 degrees, 20 degree aperture, real beam.
SonarModel realBeamSonar() {
  return SonarModel("real", RangeBins{1.0, 0.02, 250}, BearingTable::uniform(degToRad(21), 21),
                    kAperture);
}

Eigen::Vector3i voxelOf(const Eigen::Vector3d& p) {
  return (p / kVoxel).array().floor().cast<int>();
}

// A level sonar at `position` facing `yaw_deg` (0: north, 90: east).
Eigen::Isometry3d levelSonar(const Eigen::Vector3d& position, double yaw_deg) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(degToRad(yaw_deg), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = position;
  return T;
}

class ShadowAwareCarving : public ::testing::Test {
 protected:
  // A target 4 m north of the origin, and a wall 1 m in front of it as the origin sees it.
  const Eigen::Vector3d target_{4.0, 0.0, 0.0};
  const double wall_range_m_ = 3.0;

  std::unique_ptr<Carver> make(bool shadow_aware,
                               CarveParams::DarkPixels dark = CarveParams::DarkPixels::Exact) {
    CarveParams params;
    params.beam_aware = true;
    params.dark_pixels = dark;
    params.keep_level = 0.01 * kBright;  // 20 dB under the bright returns
    params.shadow_aware = shadow_aware;
    params.region =
        Eigen::AlignedBox3d(Eigen::Vector3d(1.5, -1.0, -1.0), Eigen::Vector3d(4.6, 1.0, 1.0));
    return makeCarver(CarverEngine::Fast, CarverSetup{sonar_, params, pool_});
  }

  cv::Mat dark() const { return cv::Mat(sonar_.rows(), sonar_.cols(), CV_32F, cv::Scalar(0.0f)); }

  // The target seen from 3 m to its west, facing east, on the beam's axis.
  void seeTargetFromTheWest(Carver& carver) {
    const Eigen::Isometry3d T = levelSonar(target_ - Eigen::Vector3d(0.0, 3.0, 0.0), 90.0);
    cv::Mat image = dark();
    image.at<float>(*sonar_.range().binOf(3.0), *sonar_.bearings().beamOf(0.0)) = kBright;
    carver.integrate(image, T, ++stamp_);
  }

  // From the origin facing north: the wall lights the middle beam at 3 m across the whole
  // elevation fan (a wall as tall as the main lobe); everything else is dark, the target too.
  void seeWallFromTheSouth(Carver& carver) {
    const Eigen::Isometry3d T = levelSonar(Eigen::Vector3d::Zero(), 0.0);
    cv::Mat image = dark();
    image.at<float>(*sonar_.range().binOf(wall_range_m_), *sonar_.bearings().beamOf(0.0)) = kBright;
    carver.integrate(image, T, ++stamp_);
  }

  // The wall's voxel on the target's ray (3 m north of the origin), seen lit from 3 m to its
  // west, facing east; the target lies 18 degrees off that view's bearings, unseen.
  void seeWallFromTheWest(Carver& carver) {
    const Eigen::Isometry3d T = levelSonar({wall_range_m_, -3.0, 0.0}, 90.0);
    cv::Mat image = dark();
    image.at<float>(*sonar_.range().binOf(3.0), *sonar_.bearings().beamOf(0.0)) = kBright;
    carver.integrate(image, T, ++stamp_);
  }

  SonarModel sonar_ = realBeamSonar();
  ThreadPool pool_{2};
  std::uint32_t stamp_ = 0;
};

TEST_F(ShadowAwareCarving, AStructuresShadowDoesNotCarveWhatAnotherViewSawBehindIt) {
  const Eigen::Vector3i target = voxelOf(target_);
  auto aware = make(true);
  seeTargetFromTheWest(*aware);
  ASSERT_GT(aware->value(target), 0.0f);
  ASSERT_NE(aware->value(target), VoxelMap::kUnknown);
  seeWallFromTheSouth(*aware);
  EXPECT_NEAR(aware->value(target), kBright, 0.01 * kBright);

  // The seed paper's rule takes the shadow's dark pixel for empty water: what the test
  // guards against.
  auto paper = make(false);
  seeTargetFromTheWest(*paper);
  seeWallFromTheSouth(*paper);
  EXPECT_EQ(paper->value(target), 0.0f);
}

TEST_F(ShadowAwareCarving, WaterInFrontOfTheStructureAndBesideItIsCarved) {
  auto aware = make(true);
  seeWallFromTheSouth(*aware);
  // In front of the wall on the same beam, and beside it (4 degrees east, no return there)
  // at the target's range.
  EXPECT_EQ(aware->value(voxelOf({2.0, 0.0, 0.0})), 0.0f);
  const double side = degToRad(4.0);
  EXPECT_EQ(aware->value(voxelOf({4.0 * std::cos(side), 4.0 * std::sin(side), 0.0})), 0.0f);
  // Behind the wall nothing is carved: the wall may stand at any elevation of the fan.
  EXPECT_EQ(aware->value(voxelOf(target_)), VoxelMap::kUnknown);
  EXPECT_EQ(aware->value(voxelOf({3.5, 0.0, -0.2})), VoxelMap::kUnknown);
}

TEST_F(ShadowAwareCarving, ALitPixelWhoseVoxelOnTheRayIsCarvedHidesNothingThere) {
  // A dark view from 2 m west of the wall, facing east, finds the wall's plane empty (the
  // target lies 27 degrees off its bearings, unseen). Then the wall's return at 3 m came from
  // elsewhere on its arc than the target's ray, which the shadow no longer covers.
  auto aware = make(true);
  const Eigen::Vector3i on_ray = voxelOf({wall_range_m_, 0.0, 0.0});
  aware->integrate(dark(), levelSonar({wall_range_m_, -2.0, 0.0}, 90.0), ++stamp_);
  ASSERT_EQ(aware->value(on_ray), 0.0f);
  ASSERT_EQ(aware->value(voxelOf(target_)), VoxelMap::kUnknown);
  seeWallFromTheSouth(*aware);
  EXPECT_EQ(aware->value(voxelOf(target_)), 0.0f);
}

TEST_F(ShadowAwareCarving, BehindADetectorOnlyAVoxelThatAViewKeptHides) {
  // Behind a detector a lit pixel may be a false alarm: a wall no view has kept yet does not
  // shadow, a wall that another view kept does.
  const auto below = CarveParams::DarkPixels::BelowDetection;
  const Eigen::Vector3i target = voxelOf(target_);
  auto kept = make(true, below);
  seeTargetFromTheWest(*kept);
  seeWallFromTheWest(*kept);
  ASSERT_GT(kept->value(voxelOf({wall_range_m_, 0.0, 0.0})), 0.0f);
  seeWallFromTheSouth(*kept);
  EXPECT_NEAR(kept->value(target), kBright, 0.01 * kBright);

  auto unseen = make(true, below);
  seeTargetFromTheWest(*unseen);
  seeWallFromTheSouth(*unseen);
  EXPECT_EQ(unseen->value(target), 0.0f);
}

}  // namespace
}  // namespace sonarcarve
