// Seabed-aware carving (carve/seabed_model.h, CarveParams::seabed_aware): the predicted image
// of a flat seabed against the simulator's, the plane fitted to a frame, a frame with no seabed,
// and what carving over a seabed keeps and carves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "carve/carver.h"
#include "carve/seabed_model.h"
#include "carve/voxel_map.h"
#include "common/angles.h"
#include "common/thread_pool.h"
#include "sim/noise.h"
#include "sim/ray_caster.h"
#include "sim/scene_shapes.h"
#include "sim/sonar_simulator.h"

namespace sonarcarve {
namespace {

ThreadPool& pool() {
  static ThreadPool instance(2);
  return instance;
}

constexpr double kSeabed_m = 20.0;
constexpr double kBin_m = 0.02;
constexpr double kVoxel_m = CarveParams::kDefaultVoxelSize_m;

// 2 cm bins from 0.5 m to 10.5 m, `beams` beams over 64 degrees, 20 degree aperture (sinc^2
// beam).
SonarModel surveySonar(int beams = 65) {
  return SonarModel("survey", RangeBins{0.5, kBin_m, 500},
                    BearingTable::uniform(degToRad(64), beams), degToRad(20));
}

// A sonar at `position` facing north, pitched 30 degrees down: a seabed survey's geometry.
Eigen::Isometry3d surveyPose(const Eigen::Vector3d& position) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(degToRad(-30.0), Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = position;
  return T;
}

// The simulator's realistic frame of `scene`, in whole counts as missions hold them.
cv::Mat render(const Scene& scene, const SonarModel& sonar, const Eigen::Isometry3d& T) {
  const RayCaster caster(scene);
  const SonarSimulator sim(caster, sonar, ImagingSettings{}, pool());
  cv::Mat counts;
  sim.render(T).convertTo(counts, CV_16U);  // rounds to whole counts
  cv::Mat image;
  counts.convertTo(image, CV_32F);
  return image;
}

double slopeNorth(const SeabedPlane& plane) {
  return plane.normal.x() / -plane.normal.z();
}

// The simulator and the prediction share the beam's sinc^2 power and Lambert's law, so the
// frame of a flat seabed is the prediction times one scale, wherever the prediction is strong
// enough for whole counts to hold it (at least 10 counts: rounding then moves a ratio by at
// most 5 %).
TEST(SeabedModel, PredictedImageIsTheSimulatorsUpToOneScale) {
  const SonarModel sonar = surveySonar();
  const Eigen::Isometry3d T = surveyPose({0.0, 0.0, kSeabed_m - 3.0});
  const cv::Mat frame = render(seabedSquare({0, 0, kSeabed_m}, 30.0, 0.0, 48, 0.3f), sonar, T);
  const cv::Mat predicted = predictSeabedImage(SeabedPlane::level(kSeabed_m), T, sonar);
  std::vector<double> ratios;
  for (int r = 0; r < frame.rows; ++r) {
    for (int c = 0; c < frame.cols; ++c) {
      if (frame.at<float>(r, c) >= 10.0f && predicted.at<float>(r, c) > 0.0f) {
        ratios.push_back(frame.at<float>(r, c) / predicted.at<float>(r, c));
      }
    }
  }
  ASSERT_GT(ratios.size(), 1000u);
  std::sort(ratios.begin(), ratios.end());
  const double median = ratios[ratios.size() / 2];
  EXPECT_NEAR(ratios[ratios.size() / 20] / median, 1.0, 0.1);
  EXPECT_NEAR(ratios[ratios.size() * 19 / 20] / median, 1.0, 0.1);
}

// A fitted plane places the seabed within half a range bin where the frame images it, on a
// level seabed and on one sloping 3 degrees (seabed-objects), from no prior.
TEST(SeabedModel, FitFindsTheSeabedWithinHalfARangeBin) {
  const SonarModel sonar = surveySonar();
  for (const double slope_deg : {0.0, 3.0}) {
    SCOPED_TRACE(slope_deg);
    const Eigen::Isometry3d T = surveyPose({0.0, 0.0, kSeabed_m - 3.0});
    const cv::Mat frame =
        render(seabedSquare({0, 0, kSeabed_m}, 30.0, slope_deg, 48, 0.3f), sonar, T);
    const SeabedFit fit = fitSeabed(frame, T, sonar, nullptr);
    EXPECT_GE(fit.correlation, SeabedTracker::kMinCorrelation);
    // The beam's axis meets the seabed about 5 m ahead: the depth there, and the slope.
    const double ahead = 5.0;
    const double truth = kSeabed_m + ahead * std::tan(degToRad(slope_deg));
    EXPECT_NEAR(fit.plane.depthAt(ahead, 0.0), truth, 0.5 * kBin_m);
    EXPECT_NEAR(std::atan(slopeNorth(fit.plane)), degToRad(slope_deg), degToRad(0.5));
  }
}

// A frame of a level seabed under the simulator's default background, as the pipeline hands it
// to seabed-aware carving behind a detector: less the background's mean, with the background's
// deviation per pixel (Rayleigh: 0.523 times its mean).
struct NoisySeabed {
  SonarModel sonar = surveySonar(256);
  Eigen::Isometry3d T = surveyPose({0.0, 0.0, kSeabed_m - 3.0});
  cv::Mat seabed = render(seabedSquare({0, 0, kSeabed_m}, 30.0, 0.0, 48, 0.3f), sonar, T);
  NoiseSpec noise;
  FrameNoise background{noise, sonar};
  cv::Mat mean = [&] {
    cv::Mat m(sonar.rows(), sonar.cols(), CV_32F);
    for (int r = 0; r < m.rows; ++r) {
      for (int c = 0; c < m.cols; ++c) {
        m.at<float>(r, c) = static_cast<float>(backgroundMean(noise, sonar, r, c));
      }
    }
    return m;
  }();
  cv::Mat sigma = mean * std::sqrt(4.0 / std::numbers::pi - 1.0);

  /// `image` (the seabed's, or none) with the background of frame `index`.
  BeforeDetection before(const cv::Mat& image, std::uint64_t index) const {
    cv::Mat noisy = image.clone();
    background.add(noisy, index);
    return {noisy - mean, sigma};
  }
  cv::Mat none() const { return cv::Mat::zeros(seabed.size(), CV_32F); }
};

// Behind a detector: a frame of a level seabed under the simulator's default background, less
// the background's mean, with the background's deviation per pixel (Rayleigh: 0.523 times its
// mean). The seabed returns a fraction of that deviation pixel by pixel, the frame as a whole
// far more. From no prior, in one frame, the plane ahead is found within what the carving
// allows a fit behind a detector: a voxel's half diagonal (the seabed's band, 3.5 cm at 2 cm
// voxels) and the 3 cm of doubt over it, 3 range bins here. It explains the frame; the
// background alone is not explained.
TEST(SeabedModel, FitFindsTheSeabedUnderTheBackground) {
  const NoisySeabed f;
  // The seabed is under the background's deviation in most of its pixels.
  double under_deviation = 0.0, lit = 0.0;
  for (int r = 0; r < f.seabed.rows; ++r) {
    for (int c = 0; c < f.seabed.cols; ++c) {
      if (f.seabed.at<float>(r, c) > 0.0f) {
        lit += 1.0;
        under_deviation += f.seabed.at<float>(r, c) < f.sigma.at<float>(r, c) ? 1.0 : 0.0;
      }
    }
  }
  ASSERT_GT(under_deviation, 0.9 * lit);
  for (const std::uint64_t index : {1u, 2u, 3u}) {
    SCOPED_TRACE(index);
    const SeabedFit found = fitSeabedInNoise(f.before(f.seabed, index), f.T, f.sonar, nullptr);
    EXPECT_TRUE(found.explains) << found.significance;
    EXPECT_NEAR(found.plane.depthAt(5.0, 0.0), kSeabed_m, 3.0 * kBin_m);
    const SeabedFit none = fitSeabedInNoise(f.before(f.none(), index), f.T, f.sonar, nullptr);
    EXPECT_FALSE(none.explains) << none.significance;
  }
}

// Behind a detector a frame without the seabed's evidence (here, background alone) between two
// with it does not lose the seabed: the next frame is fitted from the last plane at once. A
// lost seabed is scanned for only every kScanEvery frames, and a scan is where a plane can
// lock onto structure (the noisy manifold: a metre over the seabed, on its template).
TEST(SeabedModel, BehindADetectorOneWeakFrameKeepsTheSeabed) {
  const NoisySeabed f;
  SeabedTracker tracker;
  const auto track = [&](const cv::Mat& image, std::uint64_t index) {
    const BeforeDetection before = f.before(image, index);
    return tracker.track(f.none(), f.T, f.sonar, nullptr, &before);
  };
  ASSERT_TRUE(track(f.seabed, 1).has_value());
  EXPECT_FALSE(track(f.none(), 2).has_value());
  const auto again = track(f.seabed, 3);
  ASSERT_TRUE(again.has_value());
  EXPECT_NEAR(again->depthAt(5.0, 0.0), kSeabed_m, 3.0 * kBin_m);
  EXPECT_EQ(tracker.framesFound(), 2u);
}

// A frame of a vertical pipe, level sonar, no seabed in range: no plane explains it.
TEST(SeabedModel, NoSeabedInViewIsNotExplained) {
  const SonarModel sonar = surveySonar();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(-5.0, 0.0, 10.0);
  const cv::Mat frame = render(tubeShape({0, 0, 5.0}, {0, 0, 15.0}, 0.2, 32, 0.8f), sonar, T);
  EXPECT_LT(fitSeabed(frame, T, sonar, nullptr).correlation, SeabedTracker::kMinCorrelation);
  SeabedTracker tracker;
  EXPECT_FALSE(tracker.track(frame, T, sonar).has_value());
  EXPECT_EQ(tracker.framesFound(), 0u);
}

// A short survey line 3 m over a flat seabed with a box on it. Seabed-aware, the water 10 and
// 20 cm over the seabed is carved and the seabed and the box's face are kept; without, that
// water is never carved: the seabed lights its pixel in every view that could carve it.
class SeabedAwareCarving : public ::testing::Test {
 protected:
  static Scene scene() {
    Scene s = seabedSquare({0, 0, kSeabed_m}, 30.0, 0.0, 48, 0.3f);
    s.append(boxShape({6.0, 1.5, kSeabed_m - 0.25}, {1.0, 1.0, 0.5}, 0.0, 0.8f));
    return s;
  }

  std::unique_ptr<Carver> carve(bool seabed_aware) {
    const Scene world = scene();
    CarveParams params;
    params.beam_aware = true;
    params.dark_pixels = CarveParams::DarkPixels::Exact;
    params.seabed_aware = seabed_aware;
    params.region = Eigen::AlignedBox3d(Eigen::Vector3d(3.0, -2.0, kSeabed_m - 1.5),
                                        Eigen::Vector3d(8.0, 2.0, kSeabed_m + 0.2));
    std::vector<cv::Mat> frames;
    std::vector<Eigen::Isometry3d> poses;
    double bright = 0.0;
    for (int i = 0; i < 20; ++i) {
      poses.push_back(surveyPose({0.1 * i, 0.0, kSeabed_m - 3.0}));
      frames.push_back(render(world, sonar_, poses.back()));
      double peak = 0.0;
      cv::minMaxLoc(frames.back(), nullptr, &peak);
      bright = std::max(bright, peak);
    }
    keep_level_ = 0.01 * bright;  // 20 dB under the bright returns
    params.keep_level = keep_level_;
    auto carver = makeCarver(CarverEngine::Fast, CarverSetup{sonar_, params, pool()});
    for (std::size_t i = 0; i < frames.size(); ++i) {
      carver->integrate(frames[i], poses[i], static_cast<std::uint32_t>(i + 1));
    }
    return carver;
  }

  static float valueAt(const Carver& carver, const Eigen::Vector3d& p) {
    return carver.value((p / kVoxel_m).array().floor().cast<int>());
  }

  const SonarModel sonar_ = surveySonar();
  double keep_level_ = 0.0;
};

TEST_F(SeabedAwareCarving, CarvesTheWaterOverTheSeabedAndKeepsTheSeabed) {
  const auto aware = carve(true);
  const auto plain = carve(false);
  EXPECT_EQ(aware->stats().seabed_frames, 20u);
  EXPECT_EQ(plain->stats().seabed_frames, 0u);
  // A patch of the seabed 4 to 5 m ahead of the line, where every view's main lobe meets it.
  // The seabed's band spans the voxels within a half diagonal (3.5 cm) of the plane: water
  // from 10 cm up lies clear of it.
  int points = 0, carved_aware = 0, carved_plain = 0, seabed_kept = 0;
  for (double north = 4.0; north <= 5.0; north += 0.1) {
    for (double east = -1.0; east <= 0.0; east += 0.1) {
      for (const double height : {0.1, 0.2}) {
        ++points;
        const Eigen::Vector3d water(north, east, kSeabed_m - height);
        carved_aware += valueAt(*aware, water) == 0.0f;
        carved_plain += valueAt(*plain, water) == 0.0f;
      }
      // The voxel holding the seabed's surface (its centre half a voxel over it).
      const float seabed = valueAt(*aware, {north, east, kSeabed_m - 0.5 * kVoxel_m});
      seabed_kept += seabed > 0.0f && seabed != VoxelMap::kUnknown;
    }
  }
  EXPECT_EQ(carved_aware, points);
  EXPECT_EQ(carved_plain, 0);
  EXPECT_EQ(seabed_kept, points / 2);
  // The box's face towards the line (bright: it is not the seabed's) is kept.
  const Eigen::Vector3d front(5.5 + 0.5 * kVoxel_m, 1.5, kSeabed_m - 0.25);
  EXPECT_GT(valueAt(*aware, front), static_cast<float>(keep_level_));
  EXPECT_NE(valueAt(*aware, front), VoxelMap::kUnknown);
}

}  // namespace
}  // namespace sonarcarve
