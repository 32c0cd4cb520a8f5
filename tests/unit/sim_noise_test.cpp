#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "common/error.h"
#include "sim/noise.h"
#include "sonar/beam_pattern.h"
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

// A frame of returns of 1000 counts everywhere under 4-look speckle, without background.
cv::Mat speckledReturns(const SonarModel& sonar) {
  NoiseSpec spec;
  spec.background_mean = 1e-9;
  spec.speckle_looks = 4.0;
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(1000.0f));
  addNoise(image, spec, sonar, 3);
  return image;
}

TEST(SimNoise, SpeckleOnReturnsHasUnitMeanAndGammaSpread) {
  const cv::Mat image = speckledReturns(test::paperSonar());
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev);
  EXPECT_NEAR(mean[0], 1000.0, 3.0);
  EXPECT_NEAR(stddev[0], 1000.0 / 2.0, 5.0);  // Gamma(L, 1/L): 1 / sqrt(L)
}

// The correlation coefficient of v^2 between pixels `dr` rows and `dc` beams apart, v the
// pixel over its expected background mean.
double powerCorrelation(const cv::Mat& image, const NoiseSpec& spec, const SonarModel& sonar,
                        int dr, int dc) {
  double sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0, n = 0.0;
  for (int r = 0; r + dr < image.rows; ++r) {
    for (int c = 0; c + dc < image.cols; ++c) {
      const double a = std::pow(image.at<float>(r, c) / backgroundMean(spec, sonar, r, c), 2);
      const double b = std::pow(
          image.at<float>(r + dr, c + dc) / backgroundMean(spec, sonar, r + dr, c + dc), 2);
      sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b, n += 1.0;
    }
  }
  const double cov = sab / n - (sa / n) * (sb / n);
  return cov / std::sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
}

TEST(SimNoise, BeamsWiderThanTheirSpacingCorrelateTheBackgroundAcrossBearing) {
  // The background is the beams' field: two beams' powers correlate as the square of their
  // amplitude patterns' overlap. For a sinc amplitude pattern that overlap at an offset D is
  // sinc(k D) itself (k: the -3 dB point of sinc^2 at half the width), so 1 degree beams
  // correlate 0.90 at 0.2 degree and 0.016 at 1 degree. Each pixel stays Rayleigh, and range
  // bins stay independent.
  const SonarModel sonar = test::paperSonar().withHorizontalBeamWidth(degToRad(1.0));
  NoiseSpec spec;
  spec.background_mean = 200.0;
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f));
  addNoise(image, spec, sonar, 0);
  const auto [mean, stddev] = normalisedMeanAndStd(image, spec, sonar);
  // About 5 beams share each independent sample: the +-0.1 % of white noise becomes +-0.25 %.
  EXPECT_NEAR(mean, 1.0, 0.01);
  EXPECT_NEAR(stddev, std::sqrt(4.0 / std::numbers::pi - 1.0), 0.01);
  const double k = sincSquaredMinus3dBArgument() / degToRad(0.5);
  const auto sinc = [](double x) { return std::sin(x) / x; };
  // Sampled over each beam's interval, the pattern overlaps a little less than continuous.
  EXPECT_NEAR(powerCorrelation(image, spec, sonar, 0, 1), std::pow(sinc(k * degToRad(0.2)), 2),
              0.05);
  EXPECT_NEAR(powerCorrelation(image, spec, sonar, 0, 5), std::pow(sinc(k * degToRad(1.0)), 2),
              0.03);
  EXPECT_NEAR(powerCorrelation(image, spec, sonar, 1, 0), 0.0, 0.02);
  // Beams that do not declare a width: white.
  cv::Mat white(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f));
  addNoise(white, spec, test::paperSonar(), 0);
  EXPECT_NEAR(powerCorrelation(white, spec, sonar, 0, 1), 0.0, 0.02);
}

TEST(SimNoise, BeamsWiderThanTheirSpacingCorrelateTheSpeckleAcrossBearing) {
  const cv::Mat image = speckledReturns(test::paperSonar().withHorizontalBeamWidth(degToRad(1.0)));
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev);
  // Gamma(L, 1/L) in each pixel, from about a fifth as many independent samples as pixels.
  EXPECT_NEAR(mean[0], 1000.0, 6.0);
  EXPECT_NEAR(stddev[0], 1000.0 / 2.0, 10.0);
  // Each look's power correlates as the background's (0.90 at 0.2 degree); their mean too.
  cv::Mat a = image.colRange(0, image.cols - 1), b = image.colRange(1, image.cols);
  cv::Mat da = a - mean[0], db = b - mean[0];
  EXPECT_GT(cv::sum(da.mul(db))[0] / (stddev[0] * stddev[0] * static_cast<double>(a.total())), 0.8);
}

TEST(SimNoise, ASingleBeamGivenAWidthHasNoNeighboursToShareItsNoise) {
  const SonarModel one = SonarModel("s", RangeBins{1.0, 0.02, 50},
                                    BearingTable::uniform(degToRad(10.0), 1), degToRad(20.0))
                             .withHorizontalBeamWidth(degToRad(1.0));
  cv::Mat image(one.rows(), one.cols(), CV_32F, cv::Scalar(0.0f));
  addNoise(image, NoiseSpec{}, one, 0);
  EXPECT_GT(cv::countNonZero(image), 40);  // Rayleigh background, white
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
