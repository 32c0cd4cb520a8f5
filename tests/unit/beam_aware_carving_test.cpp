// Beam-aware carving (CarveParams::beam_aware) of a real beam's main lobe, in the fast engine:
// off-axis energy carves instead of leaving ghosts, a dark view does not carve what it could
// not have seen, and the keep level weighs a pixel by the beam's gain.
#include <gtest/gtest.h>

#include <cmath>

#include "carve/carver.h"
#include "carve/voxel_map.h"
#include "common/angles.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

constexpr double kAperture = degToRad(20.0);
constexpr float kTargetBrightness = 10000.0f;  // counts on the beam's axis
// 20 dB below the target, as the pipeline's keep level puts it below the bright returns.
constexpr double kKeepLevel = 0.01 * kTargetBrightness;

// 2 cm bins from 1 m to 6 m, 1-degree beams over 21 degrees, 20 degree aperture, real beam.
SonarModel realBeamSonar() {
  return SonarModel("real", RangeBins{1.0, 0.02, 250}, BearingTable::uniform(degToRad(21), 21),
                    kAperture);
}

Eigen::Vector3i voxelOf(const Eigen::Vector3d& p) {
  return (p / CarveParams::kDefaultVoxelSize_m).array().floor().cast<int>();
}

// Sonar level and facing north, `down_m` deep (NED: elevation is positive upwards).
Eigen::Isometry3d levelSonarAt(double down_m) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(0.0, 0.0, down_m);
  return T;
}

class BeamAwareCarving : public ::testing::Test {
 protected:
  const Eigen::Vector3d target_{4.0, 0.0, 0.0};
  const Eigen::Vector3d below_target_ = target_ + Eigen::Vector3d(0.0, 0.0, 0.55);

  std::unique_ptr<Carver> make(bool beam_aware,
                               CarveParams::DarkPixels dark = CarveParams::DarkPixels::Exact,
                               double keep_level = kKeepLevel, double dark_level = 0.5) {
    CarveParams params;
    params.beam_aware = beam_aware;
    params.keep_level = keep_level;
    params.dark_pixel_level = dark_level;
    params.dark_pixels = dark;
    params.region = Eigen::AlignedBox3d(target_ - Eigen::Vector3d::Constant(0.6),
                                        target_ + Eigen::Vector3d::Constant(0.6));
    return makeCarver(CarverEngine::Fast, CarverSetup{sonar_, params, pool_});
  }

  // What a real beam images of a point target of kTargetBrightness: its pixel holds the
  // target's return weighed by the sinc^2 gain at the target's elevation; the rest is dark.
  cv::Mat imageOfTarget(const Eigen::Isometry3d& T_world_sonar) const {
    cv::Mat image(sonar_.rows(), sonar_.cols(), CV_32F, cv::Scalar(0.0f));
    const Polar polar = polarFromPoint(T_world_sonar.inverse() * target_);
    const auto bin = sonar_.range().binOf(polar.range_m);
    const auto beam = sonar_.bearings().beamOf(polar.bearing_rad);
    if (bin && beam) {
      image.at<float>(*bin, *beam) = static_cast<float>(
          kTargetBrightness * SincSquaredBeam(kAperture).power(polar.elevation_rad));
    }
    return image;
  }

  // Sonars stacked below the target, which each sees at `elevation_deg` above its axis.
  void viewFromBelow(Carver& carver, std::initializer_list<double> elevations_deg) {
    for (const double elevation : elevations_deg) {
      const Eigen::Isometry3d T = levelSonarAt(target_.x() * std::tan(degToRad(elevation)));
      carver.integrate(imageOfTarget(T), T, ++stamp_);
    }
  }

  // A view of nothing from below the target, which it sees at `elevation_deg` up.
  void darkViewFromBelow(Carver& carver, double elevation_deg) {
    const Eigen::Isometry3d T = levelSonarAt(target_.x() * std::tan(degToRad(elevation_deg)));
    carver.integrate(cv::Mat(sonar_.rows(), sonar_.cols(), CV_32F, cv::Scalar(0.0f)), T, ++stamp_);
  }

  // Occupied voxels farther from the target than its own voxel and range bin.
  int ghosts(const Carver& carver) const {
    const double voxel = CarveParams::kDefaultVoxelSize_m;
    const double tolerance = std::sqrt(3.0) * voxel + sonar_.range().resolution_m;
    const Eigen::Vector3i lo = (target_.array() / voxel - 30.0).floor().cast<int>();
    int count = 0;
    for (int i = 0; i < 60; ++i) {
      for (int j = 0; j < 60; ++j) {
        for (int k = 0; k < 60; ++k) {
          const Eigen::Vector3i v = lo + Eigen::Vector3i(i, j, k);
          const float value = carver.value(v);
          const Eigen::Vector3d centre = (v.cast<double>().array() + 0.5) * voxel;
          if (value > 0.0f && value != VoxelMap::kUnknown &&
              (centre - target_).norm() > tolerance) {
            ++count;
          }
        }
      }
    }
    return count;
  }

  SonarModel sonar_ = realBeamSonar();
  ThreadPool pool_{2};
  std::uint32_t stamp_ = 0;
};

TEST_F(BeamAwareCarving, ATargetOutsideTheApertureInsideTheMainLobeLeavesNoGhost) {
  // Seen from three poses at 12, 15 and 18 degrees: outside +-10, inside the main lobe.
  auto beam_aware = make(true);
  viewFromBelow(*beam_aware, {12.0, 15.0, 18.0});
  EXPECT_EQ(ghosts(*beam_aware), 0);
  // A view does not carve the target it images, however weakly.
  const Eigen::Vector3i target_voxel = voxelOf(target_);
  EXPECT_NE(beam_aware->value(target_voxel), 0.0f);

  // The seed paper's rule spreads the same pixels over +-aperture/2, where no view carves
  // them all: this is what the test guards against.
  auto paper = make(false);
  viewFromBelow(*paper, {12.0, 15.0, 18.0});
  EXPECT_GT(ghosts(*paper), 0);
}

TEST_F(BeamAwareCarving, APixelIsWeighedByTheBeamsGainAtTheVoxel) {
  auto carver = make(true);
  // One view with the target on its axis: the target's voxel keeps the target's brightness.
  const Eigen::Isometry3d on_axis = levelSonarAt(0.0);
  carver->integrate(imageOfTarget(on_axis), on_axis, ++stamp_);
  const Eigen::Vector3i target_voxel = voxelOf(target_);
  const float on_axis_value = carver->value(target_voxel);
  EXPECT_NEAR(on_axis_value, kTargetBrightness, 0.01 * kTargetBrightness);

  // A voxel 5 degrees up the same arc, at the same range and bearing, is bounded by the pixel
  // over the gain there: brighter than the pixel, as a return there must have been.
  const double r = target_.x();
  const Eigen::Vector3d up(r * std::cos(degToRad(5.0)), 0.0, -r * std::sin(degToRad(5.0)));
  const Eigen::Vector3i up_voxel = voxelOf(up);
  const Eigen::Vector3d up_centre = (up_voxel.cast<double>().array() + 0.5) * 0.02;
  const double up_elevation = polarFromPoint(up_centre).elevation_rad;
  const float pixel =
      kTargetBrightness *
      static_cast<float>(SincSquaredBeam(kAperture).power(polarFromPoint(target_).elevation_rad));
  ASSERT_EQ(sonar_.range().binOf(up_centre.norm()), sonar_.range().binOf(r));
  EXPECT_NEAR(carver->value(up_voxel), pixel / SincSquaredBeam(kAperture).power(up_elevation),
              0.01 * kTargetBrightness);

  // A pixel dimmer than the keep level allows on the axis carves the voxels it bounds.
  const float dim = 0.5f * static_cast<float>(kKeepLevel);
  cv::Mat faint(sonar_.rows(), sonar_.cols(), CV_32F, cv::Scalar(0.0f));
  faint.row(*sonar_.range().binOf(r)).setTo(dim);
  carver->integrate(faint, on_axis, ++stamp_);
  EXPECT_EQ(carver->value(target_voxel), 0.0f);
}

TEST_F(BeamAwareCarving, ADarkPixelNearTheNullDoesNotCarve) {
  // At 22 degrees the beam's gain is under -30 dB: a target 20 dB below the keep level's
  // reference would return under half a count there, so a dark pixel proves nothing.
  auto carver = make(true);
  darkViewFromBelow(*carver, 22.0);
  EXPECT_EQ(carver->value(voxelOf(target_)), VoxelMap::kUnknown);
  // The same dark view carves where the beam is strong enough: 15 degrees up (-8 dB).
  EXPECT_EQ(carver->value(voxelOf(below_target_)), 0.0f);
}

TEST_F(BeamAwareCarving, ADarkPixelBoundsWhatHalfACountHoldsOnTheSonarsScale) {
  // A sonar whose half count is a power of 20 (a coarse decibel or gamma scale): its dark pixel
  // at 15 degrees up (-8 dB) bounds the axis to 126, over the keep level (100), and does not
  // carve there, where a linear sonar's does (above); at 7.4 degrees up (-1.6 dB: 29) it does.
  auto carver = make(true, CarveParams::DarkPixels::Exact, kKeepLevel, 20.0);
  darkViewFromBelow(*carver, 15.0);
  EXPECT_EQ(carver->value(voxelOf(target_)), VoxelMap::kUnknown);
  EXPECT_EQ(carver->value(voxelOf(below_target_)), 0.0f);
}

TEST_F(BeamAwareCarving, BelowDetectionDarkPixelsCarveOnlyInsideTheAperture) {
  // A detector's dark pixel may hide a return up to its detection level: at 15 degrees up
  // (-8 dB) it does not carve, at 7.4 degrees up (inside the aperture) it does.
  auto carver = make(true, CarveParams::DarkPixels::BelowDetection);
  darkViewFromBelow(*carver, 15.0);
  EXPECT_EQ(carver->value(voxelOf(target_)), VoxelMap::kUnknown);
  EXPECT_EQ(carver->value(voxelOf(below_target_)), 0.0f);
}

TEST_F(BeamAwareCarving, ADarkPixelCarvesInsideTheApertureOnAMissionOfFaintReturns) {
  // A mission whose bright returns are 25 counts puts the keep level 20 dB below at a quarter
  // of a count, under what an image of whole counts can show. A dark pixel (under half a
  // count) still carves inside +-aperture/2, where the beam keeps at least half its power, as
  // in the seed paper: at 7.4 degrees up (inside) it carves, at 15 degrees up (-8 dB) not.
  auto carver = make(true, CarveParams::DarkPixels::Exact, 0.25);
  darkViewFromBelow(*carver, 15.0);
  EXPECT_EQ(carver->value(voxelOf(target_)), VoxelMap::kUnknown);
  EXPECT_EQ(carver->value(voxelOf(below_target_)), 0.0f);
  // A lit pixel of two counts on the axis is no dark pixel: it keeps its voxel.
  const Eigen::Isometry3d on_axis = levelSonarAt(target_.z());
  cv::Mat dim(sonar_.rows(), sonar_.cols(), CV_32F, cv::Scalar(0.0f));
  dim.at<float>(*sonar_.range().binOf(target_.x()), *sonar_.bearings().beamOf(0.0)) = 2.0f;
  auto lit = make(true, CarveParams::DarkPixels::Exact, 0.25);
  lit->integrate(dim, on_axis, ++stamp_);
  EXPECT_GT(lit->value(voxelOf(target_)), 1.0f);
}

}  // namespace
}  // namespace sonarcarve
