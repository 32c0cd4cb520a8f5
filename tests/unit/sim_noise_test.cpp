#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/error.h"
#include "sim/noise.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

// Per-pixel values divided by the pixel's expected background mean, over one empty frame.
std::pair<double, double> normalisedMeanAndStd(const cv::Mat& image, const NoiseSpec& spec,
                                               const SonarModel& sonar) {
  double sum = 0.0, sum2 = 0.0;
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      const double v = image.at<float>(r, c) / backgroundMean(spec, sonar, r, c);
      sum += v;
      sum2 += v * v;
    }
  }
  const double n = static_cast<double>(image.total());
  const double mean = sum / n;
  return {mean, std::sqrt(sum2 / n - mean * mean)};
}

TEST(SimNoise, EmptyWaterBackgroundIsRayleighWithTheSetMean) {
  const SonarModel sonar = test::paperSonar();
  NoiseSpec spec;
  spec.background_mean = 200.0;  // well above the 0.5-count rounding of stored frames
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f));
  addNoise(image, spec, sonar, 0);
  const auto [mean, stddev] = normalisedMeanAndStd(image, spec, sonar);
  // 325,000 samples: the mean of a unit-mean Rayleigh variable is known to +-0.1 % (1 sigma).
  EXPECT_NEAR(mean, 1.0, 0.005);
  EXPECT_NEAR(stddev, std::sqrt(4.0 / std::numbers::pi - 1.0), 0.005);  // Rayleigh std/mean
}

TEST(SimNoise, BackgroundIsStrongerNearTheSonarAndAtTheFanEdges) {
  const SonarModel sonar = test::paperSonar();
  const NoiseSpec spec;
  const int centre = sonar.cols() / 2;
  EXPECT_GT(backgroundMean(spec, sonar, 0, centre), backgroundMean(spec, sonar, 400, centre));
  EXPECT_GT(backgroundMean(spec, sonar, 400, 0), backgroundMean(spec, sonar, 400, centre));
  EXPECT_NEAR(backgroundMean(spec, sonar, 499, centre),
              spec.background_mean *
                  (1.0 + spec.near_range_boost * std::exp(-9.99 / spec.near_range_scale_m)),
              1e-3 * spec.background_mean);
}

TEST(SimNoise, SpeckleOnReturnsHasUnitMeanAndGammaSpread) {
  const SonarModel sonar = test::paperSonar();
  NoiseSpec spec;
  spec.background_mean = 1e-9;  // returns only
  spec.speckle_looks = 4.0;
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(1000.0f));
  addNoise(image, spec, sonar, 3);
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev);
  EXPECT_NEAR(mean[0], 1000.0, 3.0);
  EXPECT_NEAR(stddev[0], 1000.0 / std::sqrt(spec.speckle_looks), 5.0);  // Gamma(L, 1/L)
}

TEST(SimNoise, SameSeedAndFrameGiveTheSameNoise) {
  const SonarModel sonar = test::paperSonar();
  NoiseSpec spec;
  const auto noisy = [&](std::uint64_t seed, std::uint64_t frame) {
    spec.seed = seed;
    cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f));
    image.at<float>(100, 100) = 500.0f;
    addNoise(image, spec, sonar, frame);
    return image;
  };
  EXPECT_EQ(cv::norm(noisy(7, 2), noisy(7, 2), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(noisy(7, 2), noisy(8, 2), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(noisy(7, 2), noisy(7, 3), cv::NORM_INF), 0.0);
}

TEST(SimNoise, FrameNoiseRefusesAnImageOfAnotherSonar) {
  const SonarModel sonar = test::paperSonar();
  const FrameNoise noise(NoiseSpec{}, sonar);
  cv::Mat image(sonar.rows(), sonar.cols() - 1, CV_32F, cv::Scalar(0.0f));
  EXPECT_THROW(noise.add(image, 0), Error);
}

TEST(SimNoise, NoiseSettingsRoundTripThroughYaml) {
  test::ScratchDir dir;
  NoiseSpec spec;
  spec.background_mean = 42.5;
  spec.speckle_looks = 2.0;
  spec.seed = 99;
  test::writeText(dir.path() / "noise.yaml", spec.toYaml());
  const NoiseSpec back = NoiseSpec::fromYamlFile((dir.path() / "noise.yaml").string());
  EXPECT_EQ(back.background_mean, 42.5);
  EXPECT_EQ(back.speckle_looks, 2.0);
  EXPECT_EQ(back.seed, 99u);
  EXPECT_EQ(back.near_range_boost, spec.near_range_boost);
  test::writeText(dir.path() / "bad.yaml", "speckle_looks: -1\n");
  EXPECT_THROW(NoiseSpec::fromYamlFile((dir.path() / "bad.yaml").string()), Error);
  EXPECT_EQ(back.combination, NoiseCombination::Added);
  test::writeText(dir.path() / "coherent.yaml", NoiseSpec::coherent().toYaml());
  EXPECT_EQ(NoiseSpec::fromYamlFile((dir.path() / "coherent.yaml").string()).combination,
            NoiseCombination::Coherent);
  test::writeText(dir.path() / "bad_sum.yaml", "combination: multiplied\n");
  try {
    NoiseSpec::fromYamlFile((dir.path() / "bad_sum.yaml").string());
    ADD_FAILURE() << "an unknown combination was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("expected added or coherent"), std::string::npos)
        << e.what();
  }
}

// Every pixel holds a return as strong as the background's mean there; the two noises are
// drawn with one seed. Returns the frame divided by the background's mean per pixel.
cv::Mat returnsAtTheBackgroundsLevel(const NoiseSpec& spec, const SonarModel& sonar) {
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F);
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      image.at<float>(r, c) = static_cast<float>(backgroundMean(spec, sonar, r, c));
    }
  }
  cv::Mat level = image.clone();
  addNoise(image, spec, sonar, 5);
  return image / level;
}

TEST(SimNoise, CoherentReturnsAndBackgroundFormARicianPixel) {
  const SonarModel sonar = test::paperSonar();
  NoiseSpec coherent = NoiseSpec::coherent();
  coherent.background_mean = 200.0;  // well above the counts' rounding
  NoiseSpec added = coherent;
  added.combination = NoiseCombination::Added;
  const cv::Mat c = returnsAtTheBackgroundsLevel(coherent, sonar);
  const cv::Mat a = returnsAtTheBackgroundsLevel(added, sonar);
  // Per unit of the background's mean m (Rayleigh scale sigma^2 = 2 m^2 / pi), a return of m
  // with Gamma speckle of L looks has E[(S g)^2] = 1 + 1 / L. Phasors: E[R^2] = E[(S g)^2] +
  // 2 sigma^2 whatever the phase (Rician); added amplitudes: E[R] = 1 + 1 (return + mean).
  const double looks = coherent.speckle_looks;
  const double expected_power = 1.0 + 1.0 / looks + 4.0 / std::numbers::pi;
  // 325,000 pixels; R^2 has a spread about its mean: the mean is known to under 0.5 %.
  EXPECT_NEAR(cv::mean(c.mul(c))[0], expected_power, 0.01 * expected_power);
  EXPECT_NEAR(cv::mean(a)[0], 2.0, 0.01);
  // So the return raises the coherent pixel's mean by much less than its own level: E[R] is
  // 1.405 (integrated numerically over the speckle, the background and the phase, 4e5 draws),
  // 0.405 over the background alone, where the added return raises it by 1.
  EXPECT_NEAR(cv::mean(c)[0], 1.405, 0.01);
}

TEST(SimNoise, EmptyWaterIsTheSameWhateverTheCombination) {
  const SonarModel sonar = test::paperSonar();
  const NoiseSpec added;
  const NoiseSpec coherent = NoiseSpec::coherent();
  cv::Mat a(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f));
  cv::Mat c = a.clone();
  addNoise(a, added, sonar, 2);
  addNoise(c, coherent, sonar, 2);
  EXPECT_EQ(cv::norm(a, c, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace sonarcarve
