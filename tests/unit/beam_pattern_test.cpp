#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

// pattern(0) = 1 and pattern(+-width/2) = -3 dB.
template <typename Pattern>
void expectOneOnAxisAndMinus3dBAtHalf(Pattern pattern, double width_rad) {
  EXPECT_DOUBLE_EQ(pattern(0.0), 1.0);
  for (double angle : {0.5 * width_rad, -0.5 * width_rad}) {
    EXPECT_NEAR(10 * std::log10(pattern(angle)), -3.0, 1e-9) << width_rad;
  }
}

TEST(BeamPattern, IsOneOnAxisAndMinus3dBAtHalfAperture) {
  for (double aperture_deg : {10.0, 20.0, 28.0}) {
    const BeamPattern b(degToRad(aperture_deg));
    expectOneOnAxisAndMinus3dBAtHalf([&](double t) { return b.weight(t); }, degToRad(aperture_deg));
  }
}

TEST(BeamPattern, SincArgumentSolvesTheMinus3dBEquation) {
  const double x = sincMinus3dBArgument();
  EXPECT_NEAR(std::sin(x) / x, std::pow(10.0, -0.3), 1e-12);
  EXPECT_GT(x, 0.0);
  EXPECT_LT(x, M_PI);
}

TEST(BeamPattern, FallsMonotonicallyToTheFirstNullAndIsZeroBeyond) {
  const BeamPattern b(degToRad(20));
  double previous = 1.0;
  for (double theta = 0.0; theta < b.firstNull(); theta += 1e-4) {
    const double w = b.weight(theta);
    EXPECT_LE(w, previous + 1e-15);
    EXPECT_GE(w, 0.0);
    EXPECT_DOUBLE_EQ(w, b.weight(-theta));
    previous = w;
  }
  EXPECT_EQ(b.weight(b.firstNull() * 1.01), 0.0);
  EXPECT_EQ(b.weight(degToRad(90)), 0.0);
  // The first null of a sinc lies at pi / x3dB half apertures.
  EXPECT_NEAR(b.firstNull(), degToRad(10) * M_PI / sincMinus3dBArgument(), 1e-12);
}

TEST(BeamPattern, RejectsNonPositiveAperture) {
  EXPECT_THROW(BeamPattern(0.0), Error);
  EXPECT_THROW(BeamPattern(-1.0), Error);
  EXPECT_THROW(BeamPattern(NAN), Error);
  EXPECT_THROW(SincSquaredBeam(0.0), Error);
  EXPECT_THROW(SincSquaredBeam(NAN), Error);
}

TEST(SincSquaredBeam, IsOneOnAxisAndMinus3dBAtHalfWidth) {
  for (double width_deg : {1.0, 20.0, 28.0}) {
    const SincSquaredBeam b(degToRad(width_deg));
    expectOneOnAxisAndMinus3dBAtHalf([&](double t) { return b.power(t); }, degToRad(width_deg));
    EXPECT_NEAR(b.halfAngleAt(-3.0), degToRad(width_deg) / 2, 1e-12);
  }
  const double x = sincSquaredMinus3dBArgument();
  EXPECT_NEAR(std::pow(std::sin(x) / x, 2), std::pow(10.0, -0.3), 1e-12);
}

TEST(SincSquaredBeam, NullsAndSideLobesOfAUniformAperture) {
  // The textbook values: -3 dB (10^-0.3) at x = 1.3894, first null at pi / 1.3894 = 2.261
  // half-widths (22.6 degrees for 20), first side lobe at x = 4.4934 (tan x = x) and
  // -13.26 dB, second null at 2 pi.
  const SincSquaredBeam b(degToRad(20));
  const double half = degToRad(10);
  EXPECT_NEAR(sincSquaredMinus3dBArgument(), 1.3894, 1e-4);
  EXPECT_NEAR(b.null(1) / half, M_PI / sincSquaredMinus3dBArgument(), 1e-12);
  EXPECT_NEAR(radToDeg(b.null(1)), 22.61, 0.01);
  EXPECT_NEAR(b.null(2), 2 * b.null(1), 1e-12);
  EXPECT_LT(b.power(b.null(1)), 1e-20);
  EXPECT_LT(b.power(b.null(2)), 1e-20);
  const double k = sincSquaredMinus3dBArgument() / half;
  EXPECT_NEAR(k * b.sideLobePeak(1), 4.4934, 1e-4);
  EXPECT_NEAR(k * b.sideLobePeak(2), 7.7253, 1e-4);
  EXPECT_NEAR(10 * std::log10(b.power(b.sideLobePeak(1))), -13.26, 0.005);
  EXPECT_NEAR(10 * std::log10(b.power(b.sideLobePeak(2))), -17.83, 0.005);
  // A peak: the pattern is lower on either side.
  for (int n : {1, 2}) {
    EXPECT_GT(b.power(b.sideLobePeak(n)), b.power(b.sideLobePeak(n) * 1.01));
    EXPECT_GT(b.power(b.sideLobePeak(n)), b.power(b.sideLobePeak(n) * 0.99));
  }
  // The main lobe falls monotonically to its first null.
  double previous = 1.0;
  for (double t = 0.0; t < b.null(1); t += 1e-4) {
    EXPECT_LE(b.power(t), previous + 1e-15);
    previous = b.power(t);
  }
  EXPECT_THROW(b.halfAngleAt(0.0), Error);
}

TEST(SincSquaredBeam, MeansOverBeamsFollowThePatternAndNeedASpacing) {
  // Beams as wide as their spacing: the centre beam's mean over its interval, [-w/2, w/2], is
  // under 1 and over the -3 dB at its edges; the amplitude's mean squared is near the power's.
  const SincSquaredBeam beam(degToRad(1.0));
  const std::vector<double> power = meansOverBeams(beam, degToRad(1.0), 10, false);
  const std::vector<double> field = meansOverBeams(beam, degToRad(1.0), 10, true);
  ASSERT_EQ(power.size(), 5u);  // to the second null, 2.26 widths: 2 beams each side
  EXPECT_LT(power[2], 1.0);
  EXPECT_GT(power[2], std::pow(10.0, -0.3));
  EXPECT_NEAR(field[2] * field[2], power[2], 0.05);
  EXPECT_EQ(meansOverBeams(beam, degToRad(0.2), 3, false).size(), 7u);  // at most max_half
  EXPECT_THROW(meansOverBeams(beam, 0.0, 10, false), Error);
}

}  // namespace
}  // namespace sonarcarve
