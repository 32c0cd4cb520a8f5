// The LAS 1.4 writer (core/io/mesh/las_file.h) read back field by field from the
// specification's offsets (support/las_read_back.h): UTM-sized coordinates kept to half the
// scale, the header of point format 6 with the WKT bit, the CRS record, and bad points refused
// with the previous file kept.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/error.h"
#include "geo/crs.h"
#include "io/mesh/las_file.h"
#include "support/las_read_back.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;

// Points about an easting and northing of UTM 31N: eastings of 5e5 m and northings of 4.8e6 m,
// where float32 keeps only 0.25 to 0.5 m, a few metres apart, at sub-millimetre positions.
LasCloud utmCloud() {
  LasCloud cloud;
  cloud.crs_wkt = crsWkt("EPSG:32631", "test", "crs");
  for (int i = 0; i < 50; ++i) {
    LasPoint p;
    p.xyz = {560000.123456 + 0.37 * i, 4760000.987654 - 0.21 * i, -9.876543 + 0.013 * i};
    p.intensity = static_cast<std::uint16_t>(100 * i);
    p.user_data = static_cast<std::uint8_t>(i);
    p.classification = i % 2 == 0 ? LasClass::Ground : LasClass::NeverClassified;
    cloud.points.push_back(p);
  }
  return cloud;
}

TEST(LasFile, UtmCoordinatesReadBackToHalfTheScale) {
  test::ScratchDir dir;
  const LasCloud cloud = utmCloud();
  writeLasFile(dir.path() / "utm.las", cloud);
  const test::LasReadBack las = test::readLasBack(dir.path() / "utm.las");
  EXPECT_EQ(las.version_major, 1);
  EXPECT_EQ(las.version_minor, 4);
  EXPECT_EQ(las.header_size, 375);
  EXPECT_EQ(las.point_format, 6);
  EXPECT_EQ(las.point_size, 30);
  EXPECT_EQ(las.legacy_count, 0u);  // format 6 keeps its count in the 64-bit field only
  EXPECT_EQ(las.global_encoding & 0x10, 0x10) << "the WKT bit";
  EXPECT_EQ(las.scale, Eigen::Vector3d::Constant(0.0001));
  ASSERT_EQ(las.points.size(), cloud.points.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < las.points.size(); ++i) {
    worst = std::max(worst, (las.points[i] - cloud.points[i].xyz).cwiseAbs().maxCoeff());
    EXPECT_EQ(las.intensity[i], cloud.points[i].intensity);
    EXPECT_EQ(las.user_data[i], cloud.points[i].user_data);
    EXPECT_EQ(las.classification[i], static_cast<std::uint8_t>(cloud.points[i].classification));
    EXPECT_EQ(las.returns[i], 0x11) << "return 1 of 1";
  }
  EXPECT_LE(worst, 0.5 * 0.0001 + 1e-9);  // rounding to the scale, in double
  EXPECT_NEAR(las.min.x(), 560000.123456, 0.0001);
  EXPECT_NEAR(las.max.x(), 560000.123456 + 0.37 * 49, 0.0001);
  EXPECT_NEAR(las.min.y(), 4760000.987654 - 0.21 * 49, 0.0001);
  EXPECT_EQ(las.wkt, cloud.crs_wkt);
  EXPECT_NE(las.wkt.find("UTM zone 31N"), std::string::npos) << las.wkt;
}

TEST(LasFile, WithoutACrsThereIsNoCrsRecord) {
  test::ScratchDir dir;
  LasCloud cloud = utmCloud();
  cloud.crs_wkt.clear();
  writeLasFile(dir.path() / "local.las", cloud);
  const test::LasReadBack las = test::readLasBack(dir.path() / "local.las");
  EXPECT_TRUE(las.wkt.empty());
  EXPECT_EQ(las.points.size(), cloud.points.size());
}

TEST(LasFile, AnEmptyCloudIsAHeaderAlone) {
  test::ScratchDir dir;
  LasCloud cloud;
  writeLasFile(dir.path() / "empty.las", cloud);
  const test::LasReadBack las = test::readLasBack(dir.path() / "empty.las");
  EXPECT_EQ(las.count, 0u);
  EXPECT_EQ(std::filesystem::file_size(dir.path() / "empty.las"), 375u);
}

TEST(LasFile, ScaleCoarsensForWideCloudsAndRefusesBeyondMillimetres) {
  EXPECT_EQ(lasScaleFor(0.0), 0.0001);
  EXPECT_EQ(lasScaleFor(199999.0), 0.0001);  // 2e9 steps of 0.1 mm
  EXPECT_EQ(lasScaleFor(250000.0), 0.001);
  EXPECT_EQ(lasScaleFor(2.1e6), 0.0);
  LasCloud wide;
  wide.points.resize(2);
  wide.points[1].xyz = {5.0e6, 0.0, 0.0};
  expectError([&] { lasBytes(wide, "wide.las"); }, {"wide.las", "extent", "within 4000 km"});
}

TEST(LasFile, APointNotFiniteIsRefusedAndThePreviousFileKept) {
  test::ScratchDir dir;
  const auto path = dir.path() / "kept.las";
  writeLasFile(path, utmCloud());
  const std::string before = test::readText(path);
  LasCloud bad = utmCloud();
  bad.points[7].xyz.y() = std::numeric_limits<double>::quiet_NaN();
  expectError([&] { writeLasFile(path, bad); },
              {path.string(), "point 7", "expected finite coordinates"});
  EXPECT_EQ(test::readText(path), before);
}

}  // namespace
}  // namespace sonarcarve
