// The noise model learned from a mission's own frames against the one learned from an
// empty-water recording of the same sonar and noise: on a vertical inspection the riser
// stays at the same pixels in every frame, so this also checks that structure is kept out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/quantile.h"
#include "denoise/mission_noise_model.h"
#include "pipeline/frame_stage.h"
#include "sim/demo_scenes.h"
#include "sim/simulation_run.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr int kFrames = 24;
constexpr int kSmoothing = 3;

ThreadPool& pool() {
  static ThreadPool instance(2);
  return instance;
}

class MissionNoise : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    for (const bool empty : {false, true}) {
      NoiseSpec noise;
      noise.seed = empty ? 7 : 1;  // independent draws: the two models' errors are independent
      SimulationRequest request{makeDemoScene("riser"),
                                "riser",
                                paperSonar(),
                                TrajectorySpec{},
                                {},
                                noise,
                                NavErrorSpec{},
                                empty,
                                kFrames,
                                dir_->path() / (empty ? "empty" : "riser")};
      SilentProgress progress;
      runSimulation(request, progress, pool());
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static Mission mission(const char* name) { return readMission(dir_->path() / name); }
  static std::vector<std::size_t> all() {
    std::vector<std::size_t> v(kFrames);
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = i;
    return v;
  }
  static test::ScratchDir* dir_;
};
test::ScratchDir* MissionNoise::dir_ = nullptr;

TEST_F(MissionNoise, MatchesTheEmptyWaterModelWithinSamplingError) {
  SilentProgress progress;
  const NoiseModel reference = NoiseModel::learn(mission("empty"), progress, nullptr, kSmoothing);
  MissionNoiseStats stats;
  const NoiseModel learned =
      learnNoiseFromMission(mission("riser"), all(), kSmoothing, progress, &stats);
  ASSERT_EQ(stats.frames_used, static_cast<std::size_t>(kFrames));
  EXPECT_TRUE(stats.has_background());
  EXPECT_EQ(learned.smoothing(), kSmoothing);

  // Each model's per-pixel mean is an average of 24 frames: the two differ by a sampling
  // error of standard deviation stddev * sqrt(1/24 + 1/24); their standard deviations by a
  // relative error of about sqrt(1/(2*24) + 1/(2*24)).
  const double mean_error = std::sqrt(2.0 / kFrames);
  const double stddev_error = std::sqrt(1.0 / kFrames);
  std::vector<double> z_mean, z_stddev;
  for (int r = 0; r < reference.mean().rows; ++r) {
    for (int c = 0; c < reference.mean().cols; ++c) {
      const double s = reference.stddev().at<float>(r, c);
      ASSERT_GT(s, 0.0);
      z_mean.push_back(std::abs(learned.mean().at<float>(r, c) - reference.mean().at<float>(r, c)) /
                       (s * mean_error));
      z_stddev.push_back(std::abs(learned.stddev().at<float>(r, c) / s - 1.0) / stddev_error);
    }
  }
  // |N(0, 1)|: median 0.674, 99.9th percentile 3.29. Margins: 25 % on the median for the
  // clipping of the sample's tails; the tail bound allows one pixel in a thousand beyond 5
  // sampling errors, far fewer than the riser's pixels (which a contaminated model would move
  // by tens of errors).
  EXPECT_LT(quantile(z_mean, 0.5), 0.674 * 1.25);
  EXPECT_LT(quantile(z_mean, 0.999), 5.0);
  EXPECT_LT(quantile(z_stddev, 0.5), 0.674 * 1.25);
  EXPECT_LT(quantile(z_stddev, 0.999), 5.0);
}

TEST_F(MissionNoise, AutoLearnsFromTheMissionAndNeverChoosesNoneOnSpeckle) {
  SilentProgress progress;
  const Mission riser = mission("riser");
  std::vector<PosedFrame> frames;
  for (std::size_t i : all())
    frames.push_back({i, Eigen::Isometry3d::Identity()});
  DetectorParams detector;  // auto
  const NoiseChoice choice = chooseNoiseModel(riser, frames, detector, "", nullptr, progress);
  EXPECT_EQ(choice.detector.mode, DetectorMode::ZTest);
  ASSERT_TRUE(choice.model);
  EXPECT_NE(choice.choice.detail.find("learned from 24 of the mission's own frames"),
            std::string::npos)
      << choice.choice.detail;
}

// An analyst may turn the detector off: the run does as asked, and says that the frames carry
// speckle, which it will carve as structure.
TEST_F(MissionNoise, DetectorNoneOnSpeckleWarns) {
  SilentProgress progress;
  std::vector<PosedFrame> frames;
  for (std::size_t i : all())
    frames.push_back({i, Eigen::Isometry3d::Identity()});
  DetectorParams none;
  none.mode = DetectorMode::None;
  const NoiseChoice choice =
      chooseNoiseModel(mission("riser"), frames, none, "", nullptr, progress);
  EXPECT_EQ(choice.detector.mode, DetectorMode::None);
  EXPECT_FALSE(choice.model);
  EXPECT_NE(choice.choice.detail.find("warning: 8 frames checked carry background noise"),
            std::string::npos)
      << choice.choice.detail;
}

TEST_F(MissionNoise, TooFewFramesGiveNoDenoisingAndSayWhy) {
  SilentProgress progress;
  const std::vector<PosedFrame> two{{0, Eigen::Isometry3d::Identity()},
                                    {1, Eigen::Isometry3d::Identity()}};
  const NoiseChoice choice =
      chooseNoiseModel(mission("riser"), two, DetectorParams{}, "", nullptr, progress);
  EXPECT_EQ(choice.detector.mode, DetectorMode::None);
  EXPECT_NE(choice.choice.detail.find("at least 3"), std::string::npos) << choice.choice.detail;
  EXPECT_NE(choice.choice.detail.find("--noise-model"), std::string::npos) << choice.choice.detail;
}

TEST(MissionNoiseFree, NoiseFreeFramesAreNotDenoisedAndSaySo) {
  const test::ScratchDir dir;
  SimulationRequest request{
      makeDemoScene("riser"), "riser", paperSonar(), TrajectorySpec{}, {}, NoiseSpec::none(),
      NavErrorSpec{},         false,   10,           dir.path() / "m"};
  SilentProgress progress;
  runSimulation(request, progress, pool());
  const Mission m = readMission(dir.path() / "m");
  std::vector<PosedFrame> frames;
  for (std::size_t i = 0; i < 10; ++i)
    frames.push_back({i, Eigen::Isometry3d::Identity()});
  const NoiseChoice choice = chooseNoiseModel(m, frames, DetectorParams{}, "", nullptr, progress);
  EXPECT_EQ(choice.detector.mode, DetectorMode::None);
  EXPECT_FALSE(choice.model);
  EXPECT_NE(choice.choice.detail.find("noise-free"), std::string::npos) << choice.choice.detail;
  DetectorParams none;
  none.mode = DetectorMode::None;
  const NoiseChoice off = chooseNoiseModel(m, frames, none, "", nullptr, progress);
  EXPECT_EQ(off.choice.detail, "no denoising (detector none)");  // nothing to warn of
}

// A pitched-down survey of the seabed on the realistic beam: the seabed lights most pixels of
// every frame (all ranges past its first return, across the fan), which is no background.
TEST(MissionNoiseFree, ASeabedInEveryFrameIsNotTakenForNoise) {
  const test::ScratchDir dir;
  TrajectorySpec survey;
  survey.kind = "lawnmower";
  ImagingSettings imaging;
  imaging.beam = SimulatedBeam::Realistic;
  SimulationRequest request{makeDemoScene("seabed-objects"),
                            "seabed-objects",
                            paperSonar(),
                            survey,
                            imaging,
                            NoiseSpec::none(),
                            NavErrorSpec{},
                            false,
                            6,
                            dir.path() / "m"};
  SilentProgress progress;
  runSimulation(request, progress, pool());
  const Mission m = readMission(dir.path() / "m");
  std::vector<std::size_t> indices{0, 1, 2, 3, 4, 5};
  MissionNoiseStats stats;
  learnNoiseFromMission(m, indices, kSmoothing, progress, &stats);
  EXPECT_GT(stats.background_median, 0.0) << "the seabed lights most pixels";
  EXPECT_FALSE(stats.has_background()) << "dark fraction " << stats.dark_fraction;
  std::vector<PosedFrame> frames;
  for (const std::size_t i : indices)
    frames.push_back({i, Eigen::Isometry3d::Identity()});
  const NoiseChoice choice = chooseNoiseModel(m, frames, DetectorParams{}, "", nullptr, progress);
  EXPECT_EQ(choice.detector.mode, DetectorMode::None) << choice.choice.detail;
  DetectorParams none;  // the detector turned off: no speckle to warn of either
  none.mode = DetectorMode::None;
  EXPECT_EQ(chooseNoiseModel(m, frames, none, "", nullptr, progress).choice.detail,
            "no denoising (detector none)");
}

// A noisy seabed survey (seabed-objects' lawnmower, realistic beam): the seabed returns in
// every range bin past its first return in every frame, a few per cent of the background, and
// passes the clipping. The learned mean must still be the background's: per block of 25 range
// bins (a metre), the median over the beams of learned / empty-water mean is 1 within the
// empty-water model's sampling error (0.52 / sqrt(frames) per pixel, over the block's median:
// under 0.5 %, so 1.5 %), where the seabed adds up to several per cent.
TEST(MissionNoiseSeabed, ASeabedInEveryFrameIsScaledOutOfTheLearnedMean) {
  const test::ScratchDir dir;
  const auto simulate = [&](bool empty, std::uint64_t seed, const char* name) {
    TrajectorySpec survey;
    survey.kind = "lawnmower";
    ImagingSettings imaging;
    imaging.beam = SimulatedBeam::Realistic;
    NoiseSpec noise;
    noise.seed = seed;
    SimulationRequest request{makeDemoScene("seabed-objects"),
                              "seabed-objects",
                              paperSonar(),
                              survey,
                              imaging,
                              noise,
                              NavErrorSpec{},
                              empty,
                              kFrames,
                              dir.path() / name};
    SilentProgress progress;
    runSimulation(request, progress, pool());
    return readMission(dir.path() / name);
  };
  const Mission survey = simulate(false, 1, "survey");
  const Mission empty = simulate(true, 7, "empty");
  SilentProgress progress;
  const NoiseModel reference = NoiseModel::learn(empty, progress, nullptr, kSmoothing);
  std::vector<std::size_t> indices(kFrames);
  for (std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  MissionNoiseStats stats;
  const NoiseModel learned = learnNoiseFromMission(survey, indices, kSmoothing, progress, &stats);
  EXPECT_GT(stats.full_row_bins, 100);
  const cv::Mat seabed_mean = [&] {
    cv::Mat sum = cv::Mat::zeros(reference.mean().size(), CV_32F);
    for (std::size_t i = 0; i < indices.size(); ++i) {
      sum += loadFrame(survey, i).image;
    }
    return cv::Mat(sum / static_cast<double>(kFrames) - reference.mean());
  }();
  double largest_seabed = 0.0;
  for (int r0 = 0; r0 + 25 <= learned.mean().rows; r0 += 25) {
    std::vector<double> ratio, seabed;
    for (int r = r0; r < r0 + 25; ++r) {
      for (int c = 0; c < learned.mean().cols; ++c) {
        const double ref = reference.mean().at<float>(r, c);
        ratio.push_back(learned.mean().at<float>(r, c) / ref);
        seabed.push_back(seabed_mean.at<float>(r, c) / ref);
      }
    }
    largest_seabed = std::max(largest_seabed, quantile(seabed, 0.5));
    EXPECT_NEAR(quantile(ratio, 0.5), 1.0, 0.015) << "range bins " << r0 << " to " << r0 + 24;
  }
  EXPECT_GT(largest_seabed, 0.03) << "the seabed adds several per cent to the mean somewhere";
}

}  // namespace
}  // namespace sonarcarve
