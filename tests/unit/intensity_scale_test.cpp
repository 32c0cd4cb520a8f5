// IntensityScale: a decibel sonar's counts become the echo's power and back, exactly at whole
// counts; a linear sonar's counts are its power.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/error.h"
#include "sonar/intensity_scale.h"

namespace sonarcarve {
namespace {

cv::Mat everyByte() {
  cv::Mat counts(1, 256, CV_32F);
  for (int c = 0; c < 256; ++c) {
    counts.at<float>(0, c) = static_cast<float>(c);
  }
  return counts;
}

TEST(IntensityScale, ArisBytesSpanEightyDecibelsOfPower) {
  const IntensityScale aris = IntensityScale::decibel(80.0, 255.0);
  cv::Mat power = everyByte();
  aris.countsToPower(power, "bytes");
  EXPECT_EQ(power.at<float>(0, 0), 0.0f);  // the bottom of the scale: no echo
  EXPECT_NEAR(power.at<float>(0, 1), std::pow(10.0, 80.0 / 2550.0), 1e-6);
  EXPECT_NEAR(power.at<float>(0, 255), 1e8, 1e8 * 1e-6);
  // Every byte is 80/255 dB over the one before it: a power ratio of 10^(80/2550).
  const double step = std::pow(10.0, 80.0 / 2550.0);
  for (int c = 2; c < 256; ++c) {
    ASSERT_NEAR(power.at<float>(0, c) / power.at<float>(0, c - 1), step, 1e-5) << c;
  }
}

TEST(IntensityScale, WholeCountsComeBackFromTheirPower) {
  const IntensityScale aris = IntensityScale::decibel(80.0, 255.0);
  cv::Mat power = everyByte();
  aris.countsToPower(power, "bytes");
  const cv::Mat back = aris.powerToCounts(power);
  // Far under half a count: rounding on writing gives the byte again.
  EXPECT_LT(cv::norm(back, everyByte(), cv::NORM_INF), 1e-3);
}

TEST(IntensityScale, PowersUnderCountZeroAreCountZero) {
  const IntensityScale scale = IntensityScale::decibel(60.0, 1000.0);
  const cv::Mat power = (cv::Mat_<float>(1, 3) << 0.0f, 0.5f, 1000.0f);
  const cv::Mat counts = scale.powerToCounts(power);
  EXPECT_EQ(counts.at<float>(0, 0), 0.0f);  // a detector's cleared pixel
  EXPECT_EQ(counts.at<float>(0, 1), 0.0f);
  EXPECT_NEAR(counts.at<float>(0, 2), 500.0f, 1e-3);  // 30 dB of 60
}

TEST(IntensityScale, LinearCountsAreThePower) {
  const IntensityScale linear = IntensityScale::linear();
  EXPECT_TRUE(linear.isLinear());
  cv::Mat image = everyByte() * 100.0f;
  const cv::Mat before = image.clone();
  linear.countsToPower(image, "image");
  EXPECT_EQ(cv::norm(image, before, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(linear.powerToCounts(image), before, cv::NORM_INF), 0.0);
  EXPECT_EQ(linear.describe(), "linear");
  EXPECT_EQ(IntensityScale::decibel(80.0, 255.0).describe(), "decibel (255 counts = 80 dB)");
}

TEST(IntensityScale, CountsOverFullScaleAreRefusedNamingThePixel) {
  // 1228 bytes of 80/255 dB would be 385 dB: infinite as a float.
  cv::Mat image = cv::Mat::zeros(4, 3, CV_32F);
  image.at<float>(2, 1) = 1228.0f;
  try {
    IntensityScale::decibel(80.0, 255.0).countsToPower(image, "f.png");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("f.png: range bin 2, beam 1: count 1228 is over the "
                                         "sonar's full scale (decibel (255 counts = 80 dB))"),
              std::string::npos)
        << e.what();
  }
  image.at<float>(2, 1) = 255.0f;  // full scale itself is a count
  EXPECT_NO_THROW(IntensityScale::decibel(80.0, 255.0).countsToPower(image, "f.png"));
}

TEST(IntensityScale, GammaCountsAreTheLinearScaleRaisedToTheGamma) {
  // An Oculus asked for gamma 0.5 sends bytes of 255 (x / X)^0.5.
  const IntensityScale oculus = IntensityScale::gamma(0.5, 255.0);
  EXPECT_FALSE(oculus.isLinear());
  EXPECT_FALSE(oculus.isDecibel());
  EXPECT_EQ(oculus.describe(), "gamma 0.5 (255 counts full scale)");
  cv::Mat power = everyByte();
  oculus.countsToPower(power, "bytes");
  for (int c = 0; c < 256; ++c) {
    const double expected = 255.0 * (c / 255.0) * (c / 255.0);
    ASSERT_NEAR(power.at<float>(0, c), expected, 1e-5 * 255.0) << c;
  }
  // Half the counts are a quarter of the scale: 10 dB of counts span 20 dB of the echo.
  EXPECT_NEAR(power.at<float>(0, 255) / power.at<float>(0, 25), 104.0, 0.05);
  // Far under half a count back: rounding on writing gives the byte again.
  EXPECT_LT(cv::norm(oculus.powerToCounts(power), everyByte(), cv::NORM_INF), 1e-3);
  // Counts over full scale are refused, as on a decibel scale.
  cv::Mat over = (cv::Mat_<float>(1, 1) << 256.0f);
  EXPECT_THROW(oculus.countsToPower(over, "f.png"), Error);
  // Gamma 1 is linear.
  EXPECT_TRUE(IntensityScale::gamma(1.0, 255.0).isLinear());
  EXPECT_THROW(IntensityScale::gamma(0.0, 255.0), Error);
  EXPECT_THROW(IntensityScale::gamma(-0.5, 255.0), Error);
  EXPECT_THROW(IntensityScale::gamma(10.5, 255.0), Error);
  EXPECT_THROW(IntensityScale::gamma(NAN, 255.0), Error);
  EXPECT_THROW(IntensityScale::gamma(0.5, 0.0), Error);
  // Half a count of 16 bits at gamma 0.1 would be 65535 (0.5 / 65535)^10, 1e-47: under a
  // float's smallest normal, so dark pixels would hold nothing at all.
  EXPECT_THROW(IntensityScale::gamma(0.1, 65535.0), Error);
  EXPECT_GT(IntensityScale::gamma(0.125, 65535.0).darkPower(), std::numeric_limits<float>::min());
  EXPECT_NO_THROW(IntensityScale::gamma(0.1, 255.0));  // 8 bits: 255 (0.5 / 255)^10, 4e-25
  EXPECT_DOUBLE_EQ(oculus.fullScalePower(), 255.0);
  EXPECT_DOUBLE_EQ(IntensityScale::decibel(80.0, 255.0).fullScalePower(), 1e8);
  EXPECT_EQ(IntensityScale::linear().fullScalePower(), 0.0);
}

TEST(IntensityScale, ADarkPixelHoldsUnderHalfACountsPower) {
  // A noise-free image's count 0 says the echo read under half a count, on the sonar's scale.
  EXPECT_DOUBLE_EQ(IntensityScale::linear().darkPower(), 0.5);
  EXPECT_NEAR(IntensityScale::decibel(80.0, 255.0).darkPower(), std::pow(10.0, 40.0 / 2550.0),
              1e-12);  // 0.16 dB: 1.037, not 0.5
  EXPECT_NEAR(IntensityScale::gamma(0.5, 255.0).darkPower(), 255.0 / 510.0 / 510.0, 1e-12);
  for (const IntensityScale& scale :
       {IntensityScale::decibel(80.0, 255.0), IntensityScale::gamma(0.5, 255.0)}) {
    cv::Mat half = (cv::Mat_<float>(1, 1) << 0.5f);
    scale.countsToPower(half, "half a count");
    EXPECT_NEAR(half.at<float>(0, 0), scale.darkPower(), 1e-6 * scale.darkPower())
        << scale.describe();
  }
}

TEST(IntensityScale, NonPositiveOrInfiniteScalesAreRefused) {
  EXPECT_THROW(IntensityScale::decibel(301.0, 255.0), Error);  // 10^30.1: too near a float's limit
  EXPECT_NO_THROW(IntensityScale::decibel(300.0, 255.0));
  EXPECT_THROW(IntensityScale::decibel(0.0, 255.0), Error);
  EXPECT_THROW(IntensityScale::decibel(80.0, -1.0), Error);
  EXPECT_THROW(IntensityScale::decibel(INFINITY, 255.0), Error);
  EXPECT_THROW(IntensityScale::decibel(80.0, NAN), Error);
}

}  // namespace
}  // namespace sonarcarve
