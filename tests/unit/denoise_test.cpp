// Detectors and noise models: false-alarm rates against theory, CFAR on a point target of
// known SNR, geometry checks, files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "common/angles.h"
#include "common/error.h"
#include "denoise/detector.h"
#include "denoise/noise_model.h"
#include "io/mission/mission_writer.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

SonarModel smallSonar(int bins = 400, int beams = 100) {
  return SonarModel("s", RangeBins{0.0, 0.02, bins}, BearingTable::uniform(degToRad(60), beams),
                    degToRad(20));
}

// A model of unit-free Gaussian noise: mean 100, stddev 10 everywhere.
std::shared_ptr<const NoiseModel> gaussianModel(const SonarModel& sonar) {
  const cv::Size size(sonar.cols(), sonar.rows());
  return std::make_shared<const NoiseModel>(cv::Mat(size, CV_32F, cv::Scalar(100.0f)),
                                            cv::Mat(size, CV_32F, cv::Scalar(10.0f)),
                                            cv::Mat(size, CV_32F, cv::Scalar(70.0f)), sonar, 100);
}

double fractionKept(const cv::Mat& detected) {
  return static_cast<double>(cv::countNonZero(detected)) / static_cast<double>(detected.total());
}

TEST(ZTest, FalseAlarmRateOnGaussianNoiseMatchesTheNormalTail) {
  const SonarModel sonar = smallSonar();
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(100.0f, 10.0f);
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F);
  for (auto it = image.begin<float>(); it != image.end<float>(); ++it) {
    *it = noise(rng);
  }
  for (double z : {1.0, 2.0, 3.0}) {
    DetectorParams params;
    params.mode = DetectorMode::ZTest;
    params.z = z;
    params.smoothing = 1;
    const Detector detector(params, gaussianModel(sonar), sonar);
    const double expected = 0.5 * std::erfc(z / std::sqrt(2.0));
    // 40,000 pixels: the binomial standard error is sqrt(p (1 - p) / n); allow 4 of them.
    const double tolerance = 4.0 * std::sqrt(expected * (1.0 - expected) / image.total());
    EXPECT_NEAR(fractionKept(detector.apply(image)), expected, tolerance) << "z " << z;
  }
}

// A kept pixel reads its return's estimate: the median over its beam and the two beside it,
// less the noise's mean (100 counts here, standard deviation 10: z = 2 keeps above 120).
TEST(ZTest, KeptPixelsCarryTheirReturnAboveTheNoise) {
  const SonarModel sonar = smallSonar();
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(100.0f));
  // A return of 250 counts over five beams with one speckle dip to 130 in its middle.
  image(cv::Rect(18, 10, 5, 1)).setTo(250.0f);
  image.at<float>(10, 20) = 130.0f;
  // A faint pixel (130) beside a very bright one (5000) on the same range bin.
  image.at<float>(40, 10) = 130.0f;
  image.at<float>(40, 11) = 5000.0f;
  // A lone bright pixel with nothing beside it.
  image.at<float>(30, 5) = 250.0f;
  DetectorParams params;
  params.mode = DetectorMode::ZTest;
  params.smoothing = 1;
  const cv::Mat out = Detector(params, gaussianModel(sonar), sonar).apply(image);
  for (int col = 18; col <= 22; ++col) {
    EXPECT_EQ(out.at<float>(10, col), 150.0f) << "the dip reads as its neighbours, col " << col;
  }
  EXPECT_EQ(out.at<float>(40, 10), 30.0f) << "a bright neighbour does not spread into it";
  EXPECT_EQ(out.at<float>(40, 11), 30.0f) << "a return in one beam alone reads as its neighbours";
  EXPECT_EQ(out.at<float>(30, 5), 1.0f) << "detected, with no return across its beams";
  EXPECT_EQ(cv::countNonZero(out), 8);
}

TEST(Cfar, DetectsAPointTargetOfKnownSnrAndHoldsItsFalseAlarmRate) {
  const SonarModel sonar = smallSonar();
  std::mt19937 rng(5);
  const float sigma = 50.0f;  // Rayleigh amplitude: power is exponential, mean 2 sigma^2
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F);
  for (auto it = image.begin<float>(); it != image.end<float>(); ++it) {
    *it = sigma * std::sqrt(-2.0f * std::log(1.0f - u(rng)));
  }
  DetectorParams params;
  params.mode = DetectorMode::Cfar;
  params.smoothing = 1;
  params.cfar_pfa = 1e-3;
  const Detector detector(params, nullptr, sonar);
  const double rate = fractionKept(detector.apply(image));
  // Away from the beam ends the training window is full and the rate is the design Pfa.
  EXPECT_NEAR(rate, 1e-3, 4.0 * std::sqrt(1e-3 / image.total()) + 2e-4);
  // A target 20 dB above the mean noise power, in every beam at bin 200.
  const float amplitude = std::sqrt(100.0f * 2.0f * sigma * sigma);
  image.row(200).setTo(amplitude);
  const cv::Mat out = detector.apply(image);
  EXPECT_EQ(cv::countNonZero(out.row(200)), sonar.cols());
  EXPECT_NEAR(detector.cfarAlpha(), 24.0 * (std::pow(1e-3, -1.0 / 24.0) - 1.0), 1e-12);
}

// A mission of 60 frames of Gaussian noise, mean 200 and standard deviation 20, in `dir`.
void writeEmptyWater(const std::filesystem::path& dir, const SonarModel& sonar, unsigned seed) {
  MissionWriter writer(dir, "empty", sonar, Mounting{});
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(200.0f, 20.0f);
  std::vector<NavSample> nav;
  for (int i = 0; i < 60; ++i) {
    Frame frame{static_cast<double>(i), "s", cv::Mat(sonar.rows(), sonar.cols(), CV_32F)};
    for (auto it = frame.image.begin<float>(); it != frame.image.end<float>(); ++it) {
      *it = noise(rng);
    }
    writer.addFrame(frame);
    NavSample s;
    s.time_s = i;
    nav.push_back(s);
  }
  writer.finish(NavTrack(nav));
}

TEST(NoiseModel, LearnsTheBackgroundOfEmptyWaterFrames) {
  test::ScratchDir dir;
  const SonarModel sonar = smallSonar(50, 20);
  writeEmptyWater(dir.path() / "empty", sonar, 9);
  SilentProgress progress;
  const NoiseModel model =
      NoiseModel::learn(readMission(dir.path() / "empty"), progress, nullptr, 1);
  EXPECT_EQ(model.frames(), 60);
  // Per pixel, 60 samples: the mean is known to 20 / sqrt(60) = 2.6 counts.
  EXPECT_NEAR(cv::mean(model.mean())[0], 200.0, 1.0);
  EXPECT_NEAR(cv::mean(model.stddev())[0], 20.0, 1.0);
  model.save(dir.path() / "noise.yaml");
  const NoiseModel back = NoiseModel::load(dir.path() / "noise.yaml");
  EXPECT_EQ(cv::norm(back.mean(), model.mean(), cv::NORM_INF), 0.0);
  EXPECT_EQ(back.smoothing(), 1);
}

// The Z-test's model holds the box-filtered background; the raw background's standard
// deviation is w times the model's for a w x w box over independent pixels.
TEST(ZTest, GivesTheRawBackgroundsStandardDeviationBehindItsBoxFilter) {
  test::ScratchDir dir;
  const SonarModel sonar = smallSonar(50, 20);
  writeEmptyWater(dir.path() / "empty", sonar, 5);
  SilentProgress progress;
  const auto model = std::make_shared<const NoiseModel>(
      NoiseModel::learn(readMission(dir.path() / "empty"), progress, nullptr, 3));
  DetectorParams params;
  params.mode = DetectorMode::ZTest;
  params.smoothing = 3;
  const cv::Mat sigma = Detector(params, model, sonar).backgroundSigma();
  ASSERT_EQ(sigma.size(), cv::Size(sonar.cols(), sonar.rows()));
  // Away from the borders, where the box holds nine distinct pixels: each pixel's deviation is
  // known from 60 frames to about 1 / sqrt(2 * 59) = 9 %, their mean over 48 x 18 pixels (each
  // box shares pixels with its neighbours) to well under 1 count of 20.
  EXPECT_NEAR(cv::mean(sigma(cv::Rect(1, 1, sonar.cols() - 2, sonar.rows() - 2)))[0], 20.0, 1.0);
  params.mode = DetectorMode::Cfar;
  EXPECT_TRUE(Detector(params, nullptr, sonar).backgroundSigma().empty());
}

TEST(NoiseModel, AModelOfAnotherGeometryIsRefusedWithAClearMessage) {
  const SonarModel sonar = smallSonar();
  DetectorParams params;
  params.mode = DetectorMode::ZTest;
  params.smoothing = 1;
  try {
    Detector(params, gaussianModel(smallSonar(300, 100)), sonar);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("another sonar geometry"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("300 x 100"), std::string::npos) << e.what();
  }
  const SonarModel wider("s", RangeBins{0.0, 0.02, 400}, BearingTable::uniform(degToRad(90), 100),
                         degToRad(20));
  EXPECT_THROW(Detector(params, gaussianModel(wider), sonar), Error);
  params.smoothing = 3;  // the model was learned without smoothing
  EXPECT_THROW(Detector(params, gaussianModel(sonar), sonar), Error);
  params.mode = DetectorMode::ZTest;
  EXPECT_THROW(Detector(params, nullptr, sonar), Error);  // no model at all
}

// Loading `file` fails with an error that says `fragment`.
void expectLoadError(const std::filesystem::path& file, const std::string& fragment) {
  try {
    NoiseModel::load(file);
    ADD_FAILURE() << "accepted " << file;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// The model learned from three empty-water frames of `sonar` (power 200 +- 20, stored in its
// counts), and that model saved in `dir` and loaded back.
std::pair<NoiseModel, NoiseModel> learnedAndReloaded(const SonarModel& sonar,
                                                     const std::filesystem::path& dir) {
  writeEmptyWater(dir / "empty", sonar, 3);
  SilentProgress progress;
  NoiseModel model = NoiseModel::learn(readMission(dir / "empty"), progress);
  model.save(dir / "noise.yaml");
  return {std::move(model), NoiseModel::load(dir / "noise.yaml")};
}

// A model's statistics are of power read on its sonar's intensity scale: it keeps that scale
// through its file and refuses a sonar whose counts mean something else.
TEST(NoiseModel, KeepsItsIntensityScaleAndRefusesAnother) {
  // The frames are stored in the sonar's counts and read back as power, every sample within
  // half a count: decibel bytes near 73, 10^(4/255) - 1 = 3.7 %; gamma 0.5 counts near 3,620 of
  // 65,535, 0.03 % (1 % taken: the mean of 3,000 samples of deviation 20 is itself 200 +- 0.4).
  const std::pair<IntensityScale, double> scales[] = {{IntensityScale::decibel(80.0, 255.0), 0.037},
                                                      {IntensityScale::gamma(0.5, 65535.0), 0.01}};
  for (const auto& [scale, tolerance] : scales) {
    test::ScratchDir dir;
    const SonarModel sonar = smallSonar(50, 20).withIntensityScale(scale);
    const auto [model, back] = learnedAndReloaded(sonar, dir.path());
    EXPECT_NEAR(cv::mean(model.mean())[0], 200.0, 200.0 * tolerance) << scale.describe();
    EXPECT_NO_THROW(back.checkGeometry(sonar, "the same sonar"));
    try {
      back.checkGeometry(smallSonar(50, 20), "linear sonar");
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(scale.describe() + ", this sonar's is linear"),
                std::string::npos)
          << e.what();
    }
    // A file with the decibels or gamma but not their full scale names the key it lacks.
    std::string text = test::readText(dir.path() / "noise.yaml");
    const auto at = text.find("intensity_full_scale_count");
    ASSERT_NE(at, std::string::npos);
    text.erase(at, text.find('\n', at) - at);
    test::writeText(dir.path() / "broken.yaml", text);
    expectLoadError(dir.path() / "broken.yaml", "broken.yaml: intensity_full_scale_count: missing");
  }
}

TEST(NoiseModel, BrokenFilesGetClearErrors) {
  test::ScratchDir dir;
  EXPECT_THROW(NoiseModel::load(dir.path() / "missing.yaml"), Error);
  test::writeText(dir.path() / "empty.yaml", "");
  EXPECT_THROW(NoiseModel::load(dir.path() / "empty.yaml"), Error);
  test::writeText(dir.path() / "other.yaml", "%YAML:1.0\n---\nformat: something\n");
  EXPECT_THROW(NoiseModel::load(dir.path() / "other.yaml"), Error);
  const SonarModel sonar = smallSonar(20, 10);
  gaussianModel(sonar)->save(dir.path() / "good.yaml");
  const std::string text = test::readText(dir.path() / "good.yaml");
  test::writeText(dir.path() / "cut.yaml", text.substr(0, text.size() / 2));
  EXPECT_THROW(NoiseModel::load(dir.path() / "cut.yaml"), Error);
  // A scale both decibel and gamma is refused, not read as either.
  std::string both = text;
  const std::string key = "intensity_full_scale_db: 0.";
  const auto at = both.find(key);
  ASSERT_NE(at, std::string::npos) << text.substr(0, 800);
  both.replace(at, key.size(), "intensity_gamma: 0.5\nintensity_full_scale_db: 80.");
  test::writeText(dir.path() / "both.yaml", both);
  expectLoadError(dir.path() / "both.yaml", "both.yaml: intensity_gamma: expected either");
}

}  // namespace
}  // namespace sonarcarve
