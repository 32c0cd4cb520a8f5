#include <gtest/gtest.h>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/sonar_model.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

TEST(RangeBins, BinsCoverHalfOpenIntervalsFromNearToFar) {
  const RangeBins bins{0.5, 0.02, 100};
  EXPECT_DOUBLE_EQ(bins.maxRange(), 2.5);
  EXPECT_DOUBLE_EQ(bins.centre(0), 0.51);
  EXPECT_EQ(bins.binOf(0.5), 0);
  EXPECT_EQ(bins.binOf(0.5199), 0);
  EXPECT_EQ(bins.binOf(0.5201), 1);
  EXPECT_EQ(bins.binOf(2.4999), 99);
  EXPECT_EQ(bins.binOf(2.5), std::nullopt);
  EXPECT_EQ(bins.binOf(0.4999), std::nullopt);
  EXPECT_EQ(bins.binOf(NAN), std::nullopt);
}

// pixel -> 3D -> pixel over every pixel, at elevations across the aperture.
void expectPixelRoundTrip(const SonarModel& sonar) {
  const double half = 0.5 * sonar.verticalAperture();
  for (double elevation : {-0.99 * half, -0.5 * half, 0.0, 0.3 * half, 0.99 * half}) {
    for (int row = 0; row < sonar.rows(); row += 7) {
      for (int col = 0; col < sonar.cols(); ++col) {
        Polar polar = sonar.pixelCentre({row, col});
        polar.elevation_rad = elevation;
        const auto pixel = sonar.pixelOf(pointFromPolar(polar));
        ASSERT_TRUE(pixel.has_value()) << row << "," << col;
        ASSERT_EQ(*pixel, (Pixel{row, col})) << "elevation " << elevation;
      }
    }
  }
}

TEST(SonarModel, PixelToPointToPixelRoundTripsOnUniformTable) {
  expectPixelRoundTrip(test::paperSonar());
}

TEST(SonarModel, PixelToPointToPixelRoundTripsOnNonUniformTable) {
  expectPixelRoundTrip(test::nonUniformSonar());
}

TEST(SonarModel, PointsOutsideTheFanAreNotSeen) {
  const SonarModel sonar = test::paperSonar();
  const double half = 0.5 * sonar.verticalAperture();
  EXPECT_FALSE(sonar.pixelOf(Polar{5.0, 0.0, half * 1.01}).has_value());
  EXPECT_FALSE(sonar.pixelOf(Polar{5.0, 0.0, -half * 1.01}).has_value());
  EXPECT_FALSE(sonar.pixelOf(Polar{10.01, 0.0, 0.0}).has_value());
  EXPECT_FALSE(sonar.pixelOf(Polar{5.0, degToRad(65.01), 0.0}).has_value());
  EXPECT_FALSE(sonar.pixelOf(Eigen::Vector3d(-5.0, 0.0, 0.0)).has_value());  // behind
  EXPECT_TRUE(sonar.pixelOf(Polar{5.0, degToRad(64.99), half * 0.99}).has_value());
}

TEST(SonarModel, RejectsInvalidGeometry) {
  auto bearings = BearingTable::uniform(degToRad(130), 10);
  EXPECT_THROW(SonarModel("s", RangeBins{0.0, 0.02, 0}, bearings, 0.3), Error);
  EXPECT_THROW(SonarModel("s", RangeBins{0.0, 0.0, 10}, bearings, 0.3), Error);
  EXPECT_THROW(SonarModel("s", RangeBins{-1.0, 0.02, 10}, bearings, 0.3), Error);
  EXPECT_THROW(SonarModel("s", RangeBins{0.0, 0.02, 10}, bearings, 0.0), Error);
  EXPECT_THROW(
      SonarModel("s", RangeBins{0.0, 0.02, 10}, BearingTable::uniform(degToRad(361), 10), 0.3),
      Error);
}

}  // namespace
}  // namespace sonarcarve
