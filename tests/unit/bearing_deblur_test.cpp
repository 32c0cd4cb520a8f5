// BearingDeblur takes the blur of beams wider than their spacing out of each image row. The
// levels asserted come from the keep level of beam-aware carving: what lies more than 20 dB
// under a return is carved, so a halo must fall under 1 % of its peak to stop being a ghost.
#include <gtest/gtest.h>

#include <numeric>

#include "common/angles.h"
#include "sonar/beam_pattern.h"
#include "sonar/bearing_deblur.h"

namespace sonarcarve {
namespace {

constexpr double kKeepShare = 0.01;  // 20 dB

// 0.2 degree beams over 130 degrees (the seed paper's sonar), one range bin.
SonarModel sonarWithBeams(double width_deg) {
  return SonarModel("s", RangeBins{1.0, 0.02, 1}, BearingTable::uniform(degToRad(130.0), 650),
                    degToRad(20.0))
      .withHorizontalBeamWidth(degToRad(width_deg));
}

// A row of true returns seen through the beams: each beam takes its neighbours' returns
// weighted by the kernel.
cv::Mat blurred(const std::vector<float>& truth, const BearingDeblur& deblur) {
  const std::vector<float>& k = deblur.kernel();
  const int h = deblur.half();
  const int n = static_cast<int>(truth.size());
  cv::Mat row(1, n, CV_32F, cv::Scalar(0.0f));
  for (int b = 0; b < n; ++b) {
    for (int d = -h; d <= h; ++d) {
      if (b + d >= 0 && b + d < n) {
        row.at<float>(0, b) +=
            k[static_cast<std::size_t>(d + h)] * truth[static_cast<std::size_t>(b + d)];
      }
    }
  }
  return row;
}

TEST(BearingDeblur, OnlyBeamsWiderThanTheirSpacingBlur) {
  EXPECT_FALSE(BearingDeblur(sonarWithBeams(0.0)).active());  // not given
  EXPECT_FALSE(BearingDeblur(sonarWithBeams(0.1)).active());  // half the spacing
  EXPECT_TRUE(BearingDeblur(sonarWithBeams(0.2)).active());   // as wide: 9 % next door
  const BearingDeblur wide(sonarWithBeams(1.0));
  ASSERT_TRUE(wide.active());
  // The sinc^2 pattern to its second null: 2.26 widths, 11 beams of 0.2 degree.
  EXPECT_EQ(wide.half(), 11);
  const std::vector<float>& k = wide.kernel();
  EXPECT_NEAR(std::accumulate(k.begin(), k.end(), 0.0), 1.0, 1e-5);
  for (int d = 1; d <= wide.half(); ++d) {
    EXPECT_FLOAT_EQ(k[static_cast<std::size_t>(wide.half() + d)],
                    k[static_cast<std::size_t>(wide.half() - d)]);
  }
  // Each tap is the pattern's mean over its beam's interval: 3 beams off, [0.5, 0.7] degree,
  // just past the -3 dB point (0.5 degree).
  const SincSquaredBeam beam(degToRad(1.0));
  double mean = 0.0;
  double centre = 0.0;
  for (int s = 0; s < 1000; ++s) {
    mean += beam.power(degToRad(0.5 + 0.2 * (s + 0.5) / 1000)) / 1000;
    centre += beam.power(degToRad(-0.1 + 0.2 * (s + 0.5) / 1000)) / 1000;
  }
  EXPECT_NEAR(
      k[static_cast<std::size_t>(wide.half() + 3)] / k[static_cast<std::size_t>(wide.half())],
      mean / centre, 1e-3);
  EXPECT_LT(mean, 0.5);
  EXPECT_GT(mean, 0.25);
  const cv::Mat image(3, 650, CV_32F, cv::Scalar(5.0f));
  EXPECT_EQ(cv::norm(BearingDeblur(sonarWithBeams(0.0)).apply(image, true), image), 0.0);
}

TEST(BearingDeblur, APointTargetComesBackToItsBeam) {
  const BearingDeblur deblur(sonarWithBeams(1.0));
  std::vector<float> truth(650, 0.0f);
  truth[300] = 1000.0f;
  const cv::Mat image = blurred(truth, deblur);
  // Blurred, the beams 3 off the target (0.6 degree) hold a third of its peak: ghosts.
  EXPECT_GT(image.at<float>(0, 303), 0.3f * image.at<float>(0, 300));
  const cv::Mat out = deblur.apply(image, true);
  const double total = cv::sum(out)[0];
  EXPECT_NEAR(total, 1000.0, 10.0);  // the target's energy is kept
  double near = 0.0;
  for (int b = 299; b <= 301; ++b) {
    near += out.at<float>(0, b);
  }
  EXPECT_GT(near, 0.9 * total);
  const float peak = out.at<float>(0, 300);
  for (int b = 0; b < 650; ++b) {
    if (std::abs(b - 300) > 2) {
      ASSERT_LT(out.at<float>(0, b), kKeepShare * peak) << "beam " << b;
    }
  }
}

TEST(BearingDeblur, AnExtendedSurfaceKeepsItsBrightnessAndLosesItsHalo) {
  const BearingDeblur deblur(sonarWithBeams(1.0));
  std::vector<float> truth(650, 0.0f);
  std::fill(truth.begin() + 200, truth.begin() + 300, 400.0f);
  const cv::Mat image = blurred(truth, deblur);
  EXPECT_GT(image.at<float>(0, 197), kKeepShare * 400.0f * 10.0f);  // a halo of 10 %
  const cv::Mat out = deblur.apply(image, true);
  for (int b = 200 + deblur.half(); b < 300 - deblur.half(); ++b) {
    ASSERT_NEAR(out.at<float>(0, b), 400.0f, 0.05f * 400.0f) << "beam " << b;
  }
  for (int b = 0; b < 650; ++b) {
    if (b < 197 || b > 302) {
      ASSERT_LT(out.at<float>(0, b), kKeepShare * 400.0f) << "beam " << b;
    }
  }
}

TEST(BearingDeblur, ReturnsFromBeyondTheFanStayBeyondIt) {
  // A target 3 beams past the fan's edge lights its edge beams; the deconvolution must not
  // gather its light into the edge beam as if it came from inside the fan.
  const BearingDeblur deblur(sonarWithBeams(1.0));
  std::vector<float> truth(650 + 3, 0.0f);  // the fan and 3 beams beyond its last
  truth[652] = 1000.0f;
  std::fill(truth.begin() + 100, truth.begin() + 120, 1000.0f);  // something inside it too
  const cv::Mat seen = blurred(truth, deblur).colRange(0, 650).clone();
  const cv::Mat out = deblur.apply(seen, true);
  for (int b = 640; b < 650; ++b) {
    ASSERT_LE(out.at<float>(0, b), seen.at<float>(0, b) + 1.0f) << "beam " << b;
  }
}

TEST(BearingDeblur, BehindADetectorDarkPixelsAreUnknownAndStayDark) {
  // A detector missed two beams of a surface: their pixels say nothing, so they must not
  // pull the surface's other beams down (as dark data would), and they stay dark.
  const BearingDeblur deblur(sonarWithBeams(1.0));
  std::vector<float> truth(650, 0.0f);
  std::fill(truth.begin() + 200, truth.begin() + 300, 400.0f);
  cv::Mat image = blurred(truth, deblur);
  image.at<float>(0, 250) = 0.0f;
  image.at<float>(0, 251) = 0.0f;
  const cv::Mat detected = deblur.apply(image, false);
  // Taken for data, the dark pixels would drag their neighbours down to an eighth.
  const cv::Mat exact = deblur.apply(image, true);
  EXPECT_LT(exact.at<float>(0, 249), 0.5f * 400.0f);
  EXPECT_LT(exact.at<float>(0, 252), 0.5f * 400.0f);
  EXPECT_EQ(detected.at<float>(0, 250), 0.0f);
  EXPECT_EQ(detected.at<float>(0, 251), 0.0f);
  for (const int b : {247, 248, 249, 252, 253, 254}) {
    EXPECT_NEAR(detected.at<float>(0, b), 400.0f, 0.2f * 400.0f) << "beam " << b;
  }
}

}  // namespace
}  // namespace sonarcarve
