// The simulator's families of elevation pattern (sim/elevation_pattern.h) and the tables it
// reads.
#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "sim/elevation_pattern.h"
#include "sonar/beam_pattern.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

ElevationBeamSpec family(ElevationFamily f) {
  ElevationBeamSpec spec;
  spec.family = f;
  return spec;
}

// The angle in (0, hi) where the falling `pattern` crosses `level_db`, bisected.
double crossingOf(const ElevationPattern& pattern, double level_db, double hi) {
  double lo = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (10.0 * std::log10(pattern.power(mid)) > level_db ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(ElevationPattern, Sinc2IsTheSincSquaredTracedToTheNullAfterItsSideLobes) {
  const double aperture = degToRad(20);
  const SincSquaredBeam sinc2(aperture);
  const ElevationPattern p(family(ElevationFamily::Sinc2), aperture, 1);
  EXPECT_DOUBLE_EQ(p.tracedHalfAngle(), sinc2.null(2));
  for (double deg : {0.0, 5.0, -10.0, 22.0, 32.3, -40.0}) {
    EXPECT_DOUBLE_EQ(p.power(degToRad(deg)), sinc2.power(degToRad(deg))) << deg;
  }
  EXPECT_EQ(p.power(sinc2.null(2) + 1e-6), 0.0);
  EXPECT_DOUBLE_EQ(ElevationPattern(family(ElevationFamily::Sinc2), aperture, 2).tracedHalfAngle(),
                   sinc2.null(3));
  const auto [lo, hi] = p.interval(-3.0);
  EXPECT_DOUBLE_EQ(hi, sinc2.halfAngleAt(-3.0));
  EXPECT_DOUBLE_EQ(lo, -hi);
}

TEST(ElevationPattern, GaussianIsAsWideAsTheApertureAndTracedToMinus30dB) {
  for (double aperture_deg : {10.0, 20.0, 28.0}) {
    const double aperture = degToRad(aperture_deg);
    const ElevationPattern p(family(ElevationFamily::Gaussian), aperture, 1);
    EXPECT_DOUBLE_EQ(p.power(0.0), 1.0);
    const double width = 2.0 * crossingOf(p, -3.0, aperture);
    EXPECT_NEAR(radToDeg(width), aperture_deg, 0.05);
    EXPECT_NEAR(p.power(-0.5 * aperture), p.power(0.5 * aperture), 1e-15);
    // Traced to -30 dB, nothing beyond.
    EXPECT_NEAR(10.0 * std::log10(p.power(p.tracedHalfAngle())), -30.0, 1e-9);
    EXPECT_NEAR(p.tracedHalfAngle(), std::sqrt(10.0) * 0.5 * aperture, 1e-12);
    EXPECT_EQ(p.power(p.tracedHalfAngle() + 1e-9), 0.0);
    EXPECT_NEAR(p.interval(-3.0).second, 0.5 * aperture, 1e-12);
    EXPECT_NEAR(p.interval(-10.0).second, std::sqrt(10.0 / 3.0) * 0.5 * aperture, 1e-12);
  }
}

TEST(ElevationPattern, TruncatedIsTheSincSquaredMainLobeCutAtMinus6dB) {
  const double aperture = degToRad(20);
  const SincSquaredBeam sinc2(aperture);
  const ElevationPattern p(family(ElevationFamily::Truncated), aperture, 1);
  const double cut = sinc2.halfAngleAt(-6.0);
  EXPECT_DOUBLE_EQ(p.tracedHalfAngle(), cut);
  EXPECT_NEAR(radToDeg(cut), 13.62, 0.01);
  for (double t = 0.0; t < cut; t += degToRad(0.5)) {
    EXPECT_DOUBLE_EQ(p.power(t), sinc2.power(t));
    EXPECT_DOUBLE_EQ(p.power(-t), sinc2.power(t));
  }
  EXPECT_NEAR(2.0 * crossingOf(p, -3.0, aperture), aperture, degToRad(0.05));
  for (double t = cut + 1e-9; t < degToRad(60); t += degToRad(0.25)) {
    EXPECT_EQ(p.power(t), 0.0) << radToDeg(t);
    EXPECT_EQ(p.power(-t), 0.0) << radToDeg(t);
  }
  EXPECT_DOUBLE_EQ(p.interval(-3.0).second, sinc2.halfAngleAt(-3.0));
  EXPECT_DOUBLE_EQ(p.interval(-10.0).second, cut);
}

TEST(ElevationPattern, TableInterpolatesInDecibelsAndIsZeroOutside) {
  ElevationBeamSpec spec = family(ElevationFamily::Table);
  auto table = std::make_shared<ElevationTable>();
  table->rows =
      parseElevationTable("# measured\nelevation_deg,gain_db\n-12,-9\n0,0\n\n10, -6\n", "beam.csv");
  ASSERT_EQ(table->rows.size(), 3u);
  spec.table = table;
  const ElevationPattern p(spec, degToRad(20), 1);
  EXPECT_DOUBLE_EQ(p.tracedHalfAngle(), degToRad(12));
  EXPECT_DOUBLE_EQ(p.power(0.0), 1.0);
  EXPECT_NEAR(10.0 * std::log10(p.power(degToRad(5))), -3.0, 1e-9);
  EXPECT_NEAR(10.0 * std::log10(p.power(degToRad(-4))), -3.0, 1e-9);
  EXPECT_NEAR(10.0 * std::log10(p.power(degToRad(10))), -6.0, 1e-9);
  EXPECT_NEAR(10.0 * std::log10(p.power(degToRad(-12))), -9.0, 1e-9);
  EXPECT_EQ(p.power(degToRad(10.01)), 0.0);
  EXPECT_EQ(p.power(degToRad(-12.01)), 0.0);
  const auto [lo, hi] = p.interval(-3.0);
  EXPECT_NEAR(radToDeg(lo), -4.0, 2e-3);
  EXPECT_NEAR(radToDeg(hi), 5.0, 2e-3);
}

TEST(ElevationPattern, BadTablesAreRefusedNamingTheFileAndLine) {
  const auto parse = [](const std::string& text) { return parseElevationTable(text, "b.csv"); };
  test::expectError([&] { parse(""); }, {"b.csv", "empty"});
  test::expectError([&] { parse("elevation_deg,gain_db\n"); }, {"b.csv", "at least 2 rows"});
  test::expectError([&] { parse("0,0\n"); }, {"b.csv", "at least 2 rows"});
  // Cut short: the last line lost its gain.
  test::expectError([&] { parse("-5,-3\n0,0\n5"); }, {"b.csv", "line 3", "2 values"});
  test::expectError([&] { parse("-5,-3\n5,-3\n0,0\n"); }, {"b.csv", "line 3", "sorted"});
  test::expectError([&] { parse("-5,-3\n-5,0\n"); }, {"b.csv", "line 2", "increasing"});
  test::expectError([&] { parse("-5,-3\n0,nan\n5,-3\n"); },
                    {"b.csv", "line 2", "gain_db as a finite number"});
  test::expectError([&] { parse("-5,-3\n0,inf\n"); },
                    {"b.csv", "line 2", "gain_db as a finite number"});
  test::expectError([&] { parse("-95,-3\n0,0\n"); }, {"b.csv", "line 1", "-90 and 90"});
  test::expectError([&] { parse("-5,-3,1\n0,0,1\n"); }, {"b.csv", "line 1", "2 values"});
  test::expectError([&] { parse("angle,gain\n0,0\n1,-1\n"); },
                    {"b.csv", "line 1", "elevation_deg as a finite number"});
}

TEST(ElevationPattern, SpecsNameAFamilyOrATableFile) {
  EXPECT_EQ(elevationBeamSpec("sinc2").family, ElevationFamily::Sinc2);
  EXPECT_EQ(elevationBeamSpec("gaussian").family, ElevationFamily::Gaussian);
  EXPECT_EQ(elevationBeamSpec("truncated").family, ElevationFamily::Truncated);
  test::ScratchDir dir;
  const auto file = dir.path() / "beam.csv";
  test::writeText(file, "-20,-20\n0,0\n20,-20\n");
  const ElevationBeamSpec table = elevationBeamSpec("table:" + file.string());
  EXPECT_EQ(table.family, ElevationFamily::Table);
  ASSERT_TRUE(table.table);
  EXPECT_EQ(table.table->file, file.string());
  EXPECT_EQ(table.table->rows.size(), 3u);
  test::expectError([] { elevationBeamSpec("cosine"); }, {"expected sinc2, gaussian"});
  test::expectError([] { elevationBeamSpec("table:"); }, {"expected sinc2, gaussian"});
  test::expectError([&] { elevationBeamSpec("table:" + (dir.path() / "none.csv").string()); },
                    {"none.csv"});
  for (auto f : {ElevationFamily::Sinc2, ElevationFamily::Gaussian, ElevationFamily::Truncated}) {
    EXPECT_EQ(elevationBeamSpec(elevationFamilyName(f)).family, f);
  }
  EXPECT_EQ(elevationFamilyName(ElevationFamily::Table), "table");
}

}  // namespace
}  // namespace sonarcarve
