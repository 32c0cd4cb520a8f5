#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

TEST(BeamPattern, IsOneOnAxisAndMinus3dBAtHalfAperture) {
  for (double aperture_deg : {10.0, 20.0, 28.0}) {
    const BeamPattern b(degToRad(aperture_deg));
    EXPECT_DOUBLE_EQ(b.weight(0.0), 1.0);
    const double half = degToRad(aperture_deg) / 2;
    EXPECT_NEAR(10 * std::log10(b.weight(half)), -3.0, 1e-9);
    EXPECT_NEAR(10 * std::log10(b.weight(-half)), -3.0, 1e-9);
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
}

}  // namespace
}  // namespace sonarcarve
