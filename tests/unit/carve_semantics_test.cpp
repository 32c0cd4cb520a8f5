// Carving semantics on tiny hand-made cases, for both engines: the minimum over views,
// unknown versus carved, carved stays carved, and the sign of elevation.
#include <gtest/gtest.h>

#include "carve/fast_carver.h"
#include "carve/reference_carver.h"
#include "common/angles.h"

namespace sonarcarve {
namespace {

// A narrow sonar: 4 cm bins from 1 m to 3 m, 5 beams over 10 degrees, 10 degree aperture.
SonarModel tinySonar() {
  return SonarModel("tiny", RangeBins{1.0, 0.04, 50}, BearingTable::uniform(degToRad(10), 5),
                    degToRad(10));
}

// An image lit with `value` in the bins around `range_m` in every beam, dark elsewhere.
cv::Mat ringImage(const SonarModel& sonar, double range_m, float value) {
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f));
  if (const auto bin = sonar.range().binOf(range_m)) {
    image.row(*bin).setTo(value);
  }
  return image;
}

Eigen::Isometry3d sonarAt(double down_m, double pitch_rad = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(0, 0, down_m);
  return T;
}

class CarveSemantics : public ::testing::Test {
 protected:
  CarveSemantics()
      : sonar_(tinySonar()),
        map_(params_.voxel_size_m,
             Eigen::AlignedBox3d(Eigen::Vector3d(0.5, -0.5, -0.5), Eigen::Vector3d(3.5, 0.5, 0.5))),
        fast_(map_, sonar_, params_),
        reference_(sonar_, params_) {}

  void view(const cv::Mat& image, const Eigen::Isometry3d& T) {
    fast_.integrate(image, T, ++stamp_);
    reference_.integrate(image, T);
  }
  // The value both engines give the voxel containing `p`; they must agree.
  float valueAt(const Eigen::Vector3d& p) {
    const Eigen::Vector3i v = map_.voxelOf(p);
    const float fast = map_.value(v);
    EXPECT_EQ(fast, reference_.value(v)) << "engines disagree at " << p.transpose();
    return fast;
  }

  CarveParams params_;
  SonarModel sonar_;
  VoxelMap map_;
  FastCarver fast_;
  ReferenceCarver reference_;
  std::uint32_t stamp_ = 0;
};

TEST_F(CarveSemantics, EachVoxelKeepsTheMinimumOverViews) {
  const Eigen::Vector3d target(2.01, 0.0, 0.0);  // on the boresight, inside bin 25
  view(ringImage(sonar_, 2.01, 50.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(target), 50.0f);
  view(ringImage(sonar_, 2.01, 30.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(target), 30.0f);
  view(ringImage(sonar_, 2.01, 80.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(target), 30.0f);  // a brighter view does not raise it
}

TEST_F(CarveSemantics, UnseenVoxelsStayUnknownAndDarkPixelsCarve) {
  view(ringImage(sonar_, 2.01, 50.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt({1.51, 0.0, 0.0}), 0.0f);                // dark bin: carved
  EXPECT_EQ(valueAt({2.01, 0.0, 0.3}), VoxelMap::kUnknown);  // 8.5 deg below: outside
  EXPECT_EQ(valueAt({2.01, 0.3, 0.0}), VoxelMap::kUnknown);  // 8.5 deg starboard: outside
  EXPECT_EQ(valueAt({3.3, 0.0, 0.0}), VoxelMap::kUnknown);   // beyond 3 m
  // Blocks whose every voxel is carved are stored as Free.
  EXPECT_GT(map_.blockCount(VoxelMap::BlockState::Free), 0u);
}

TEST_F(CarveSemantics, ACarvedVoxelIsNeverRecreatedByALaterView) {
  const Eigen::Vector3d p(2.01, 0.0, 0.0);
  view(ringImage(sonar_, 1.5, 50.0f), sonarAt(0.0));  // p's bin is dark: carved
  ASSERT_EQ(valueAt(p), 0.0f);
  view(ringImage(sonar_, 2.01, 90.0f), sonarAt(0.0));  // now lit
  EXPECT_EQ(valueAt(p), 0.0f);
  view(ringImage(sonar_, 2.01, 90.0f), sonarAt(0.05));
  EXPECT_EQ(valueAt(p), 0.0f);
}

TEST_F(CarveSemantics, ElevationIsPositiveUpwards) {
  // A sonar pitched up by 4 degrees sees a voxel 6 degrees above the horizon (elevation +2)
  // but not one 6 degrees below it (elevation -10, outside the 10 degree aperture). At a bin
  // centre range and on the 0.2 degree elevation grid, the reference's arcs pass through.
  const double r = 2.02;
  const Eigen::Vector3d above(r * std::cos(degToRad(6)), 0.0, -r * std::sin(degToRad(6)));
  const Eigen::Vector3d below(r * std::cos(degToRad(6)), 0.0, r * std::sin(degToRad(6)));
  view(ringImage(sonar_, r, 40.0f), sonarAt(0.0, degToRad(4)));
  EXPECT_EQ(valueAt(above), 40.0f);
  EXPECT_EQ(valueAt(below), VoxelMap::kUnknown);
}

TEST_F(CarveSemantics, ThresholdTurnsWeakPixelsIntoEmptyWater) {
  CarveParams thresholded = params_;
  thresholded.intensity_threshold = 20.0;
  VoxelMap map(thresholded.voxel_size_m, Eigen::AlignedBox3d(Eigen::Vector3d(0.5, -0.5, -0.5),
                                                             Eigen::Vector3d(3.5, 0.5, 0.5)));
  FastCarver carver(map, sonar_, thresholded);
  carver.integrate(ringImage(sonar_, 2.01, 15.0f), sonarAt(0.0), 1);
  EXPECT_EQ(map.value(map.voxelOf({2.01, 0.0, 0.0})), 0.0f);
  EXPECT_EQ(map.occupiedCount(), 0u);
}

}  // namespace
}  // namespace sonarcarve
