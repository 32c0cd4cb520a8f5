// The beams' width read from frames: rows blurred by beams of a known width must give that
// width back; rows that no beam wider than about 2.5 spacings blurred must give none, since
// deblurring them with a wide kernel would strip real detail (0.3 degree beams deblurred as
// 0.55 degree ones lose 0.08 of F-score on the riser, docs/validation.md).
//
// Tolerance: the cutoff is found to a frequency bin, 1 / n cycles per beam for n beams, and the
// width is the one whose kernel falls most steeply in the same bin, so it is known to half a
// bin of the cutoff (0.8845 / w cycles per beam for beams w spacings wide), plus the 1 % steps
// it is searched in: 2.4 % for 1 degree beams 0.2 degree apart, 9 % for beams 10 spacings
// wide on 64 beams.
#include <gtest/gtest.h>

#include <random>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/beam_width_estimate.h"
#include "sonar/bearing_deblur.h"

namespace sonarcarve {
namespace {

constexpr int kBeams = 650;  // 0.2 degree apart over 130 degrees, the seed paper's sonar
constexpr double kSpacingDeg = 0.2;

double widthTolerance(double width_in_spacings, int beams) {
  return (0.5 / beams) / (0.8845 / width_in_spacings) + 0.02;
}

// Rows of a scene: a few structures each, with sharp edges across bearing (from one beam to
// 40 wide, 100 to 5000 counts), seen through beams `width_deg` wide (none for 0) and
// `spacing_deg` apart, rounded to whole counts as frames store them.
cv::Mat sceneRows(double width_deg, unsigned seed, int beams = kBeams,
                  double spacing_deg = kSpacingDeg) {
  constexpr int kRows = 400;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> start(0, beams - 1), length(1, 40), count(1, 5);
  std::uniform_real_distribution<float> level(100.0f, 5000.0f);
  cv::Mat truth(kRows, beams, CV_32F, cv::Scalar(0.0f));
  for (int r = 0; r < kRows; ++r) {
    for (int k = count(rng); k > 0; --k) {
      const int from = start(rng);
      const int to = std::min(beams - 1, from + length(rng));
      truth.row(r).colRange(from, to + 1).setTo(level(rng));
    }
  }
  cv::Mat image = truth.clone();
  if (width_deg > 0.0) {
    const std::vector<float> k =
        bearingBlurKernel(degToRad(width_deg), degToRad(spacing_deg), beams - 1);
    const int h = static_cast<int>(k.size() / 2);
    image.setTo(0.0f);
    for (int r = 0; r < kRows; ++r) {
      for (int b = 0; b < beams; ++b) {
        for (int d = std::max(-h, -b); d <= std::min(h, beams - 1 - b); ++d) {
          image.at<float>(r, b) += k[static_cast<std::size_t>(d + h)] * truth.at<float>(r, b + d);
        }
      }
    }
  }
  cv::Mat counts;
  image.convertTo(counts, CV_16U);  // rounds, as frames are stored
  counts.convertTo(image, CV_32F);
  return image;
}

BeamWidthEstimate estimateOf(const std::vector<cv::Mat>& frames, int beams = kBeams,
                             double spacing_deg = kSpacingDeg) {
  BearingSpectrum spectrum(beams);
  for (const cv::Mat& f : frames) {
    spectrum.add(f);
  }
  return estimateBeamWidth(spectrum, BearingTable::uniform(degToRad(beams * spacing_deg), beams));
}

TEST(BeamWidthEstimate, ReadsTheWidthOfBeamsWellWiderThanTheirSpacing) {
  for (const double width : {0.6, 1.0, 2.0}) {
    const BeamWidthEstimate e = estimateOf({sceneRows(width, 1), sceneRows(width, 2)});
    EXPECT_NEAR(radToDeg(e.width_rad), width, widthTolerance(width / kSpacingDeg, kBeams) * width)
        << e.reason;
    // The cutoff lies near where the sinc^2 pattern's triangle spectrum ends, 0.8845 / width
    // cycles per radian: the pattern cut at its second null and averaged over each beam
    // falls most steeply 4 to 6 % above that.
    const double triangle_end = 0.8845 * 0.2 / width;
    EXPECT_GT(e.cutoff, triangle_end) << width;
    EXPECT_LT(e.cutoff, 1.08 * triangle_end) << width;
    EXPECT_NE(e.reason.find("cut off across bearing"), std::string::npos) << e.reason;
  }
}

TEST(BeamWidthEstimate, ReadsTheWidthOnFewBeams) {
  // 64 and 128 beams (the example mission's 64, 0.95 degree apart): a cutoff bin is a larger
  // share of the cutoff, and the window's spread of the spectrum matters.
  for (const int beams : {64, 128}) {
    for (const double spacings : {6.0, 10.0}) {
      const double width = spacings * 0.95;
      const BeamWidthEstimate e = estimateOf(
          {sceneRows(width, 6, beams, 0.95), sceneRows(width, 7, beams, 0.95)}, beams, 0.95);
      EXPECT_NEAR(radToDeg(e.width_rad), width, widthTolerance(spacings, beams) * width)
          << beams << " beams: " << e.reason;
    }
  }
}

TEST(BeamWidthEstimate, FindsNoneWhereTheBeamsHardlyBlur) {
  // Clipped beams, beams as wide as their spacing, and 0.3 degree beams, whose cutoff lies
  // beyond the Nyquist frequency of the beam spacing.
  for (const double width : {0.0, 0.2, 0.3}) {
    const BeamWidthEstimate e = estimateOf({sceneRows(width, 3), sceneRows(width, 4)});
    EXPECT_EQ(e.width_rad, 0.0) << width << ": " << e.reason;
    EXPECT_FALSE(e.reason.empty());
  }
}

TEST(BeamWidthEstimate, FindsNoneInNoiseWhiteAcrossBearing) {
  // Wide beams' rows under noise drawn independently in each pixel: their cutoff is hidden.
  cv::Mat noisy = sceneRows(1.0, 5);
  cv::Mat noise(noisy.size(), CV_32F);
  cv::randn(noise, 150.0, 80.0);
  noisy += cv::max(noise, 0.0);
  EXPECT_EQ(estimateOf({noisy}).width_rad, 0.0);
}

TEST(BeamWidthEstimate, SaysWhyWhenTheFramesAreDarkOrTheWrongSize) {
  const BeamWidthEstimate dark = estimateOf({cv::Mat(10, kBeams, CV_32F, cv::Scalar(0.0f))});
  EXPECT_EQ(dark.width_rad, 0.0);
  EXPECT_NE(dark.reason.find("no returns"), std::string::npos) << dark.reason;
  const BeamWidthEstimate none = estimateOf({});
  EXPECT_EQ(none.width_rad, 0.0);
  BearingSpectrum spectrum(kBeams);
  EXPECT_THROW(spectrum.add(cv::Mat(10, kBeams - 1, CV_32F, cv::Scalar(0.0f))), Error);
  EXPECT_THROW(spectrum.add(cv::Mat(10, kBeams, CV_8U, cv::Scalar(0))), Error);
  // Too few beams to find a cutoff in.
  BearingSpectrum narrow(8);
  narrow.add(cv::Mat(4, 8, CV_32F, cv::Scalar(1.0f)));
  EXPECT_EQ(estimateBeamWidth(narrow, BearingTable::uniform(degToRad(10.0), 8)).width_rad, 0.0);
}

}  // namespace
}  // namespace sonarcarve
