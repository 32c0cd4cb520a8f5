// The seabed's elevation grid (core/mesh/seabed_grid.h) on synthetic points: a sloping seabed
// with a box standing on it and a few stray points below, and its GeoTIFF
// (core/io/raster/geotiff_file.h) read back by GDAL.
#include <gdal.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "geo/crs.h"
#include "io/raster/geotiff_file.h"
#include "mesh/seabed_grid.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;

constexpr double kVoxel_m = 0.02;
constexpr double kCell_m = 0.5;
// The seabed: up = -20 m + 0.1 x east, a 1:10 slope (5 cm across a cell).
double seabed(double east) {
  return -20.0 + 0.1 * east;
}

// Points every voxel over 4 m x 3 m east of 100 m, north of 50 m, on voxel centres; a box 0.5 m
// tall over the cell (east 101..101.5, north 51..51.5), seen on its top and the seabed around
// it; three stray points a metre below the seabed in the first cell; no point in the cell
// (east 103.5..104, north 52.5..53).
std::vector<Eigen::Vector3d> scene() {
  std::vector<Eigen::Vector3d> points;
  for (double e = 100.01; e < 104.0; e += kVoxel_m) {
    for (double n = 50.01; n < 53.0; n += kVoxel_m) {
      if (e > 103.5 && n > 52.5)
        continue;
      const double z = std::round(seabed(e) / kVoxel_m) * kVoxel_m;
      points.emplace_back(e, n, z);
      if (e > 101.0 && e < 101.5 && n > 51.0 && n < 51.25) {  // the box's top over half the cell
        points.back().z() = z + 0.5;
      }
    }
  }
  for (int i = 0; i < 3; ++i)
    points.emplace_back(100.1 + 0.1 * i, 50.1, -21.0);
  return points;
}

TEST(SeabedGrid, LowestSurfaceMedianPerCellAlignedOnTheCellSize) {
  SeabedGridParams params;
  params.cell_m = kCell_m;
  params.voxel_size_m = kVoxel_m;
  EXPECT_DOUBLE_EQ(params.band_m(), 0.25);  // half a cell over 3 voxels
  const HeightRaster r = seabedGrid(scene(), params);
  EXPECT_EQ(r.width, 8);
  EXPECT_EQ(r.height, 6);
  EXPECT_DOUBLE_EQ(r.west_m, 100.0);
  EXPECT_DOUBLE_EQ(r.north_m, 53.0);
  for (int row = 0; row < r.height; ++row) {
    for (int column = 0; column < r.width; ++column) {
      const float h = r.values[static_cast<std::size_t>(row * r.width + column)];
      const double centre_east = r.west_m + (column + 0.5) * kCell_m;
      if (row == 0 && column == 7) {
        EXPECT_TRUE(std::isnan(h)) << "no point: no data";
        continue;
      }
      // The box (half the cell) and the strays (3 of 625) are not the seabed; the median of
      // the seabed's voxel centres is its height at the cell's centre to half a voxel.
      EXPECT_NEAR(h, seabed(centre_east), 0.5 * kVoxel_m + 1e-4) << row << ' ' << column;
    }
  }
}

TEST(SeabedGrid, RefusesABadCellAndGivesNothingForNoPoints) {
  SeabedGridParams params;
  for (const auto& [cell, got] : {std::pair{0.0, "got 0"}, std::pair{1e300, "got 1e+300"},
                                  std::pair{std::nan(""), "got nan"}}) {
    params.cell_m = cell;
    expectError([&] { seabedGrid(scene(), params); },
                {"export: cell", "expected 0.001 to 1000 m", got});
  }
  params.cell_m = 1e-3;
  expectError(
      [&] {
        seabedGrid({{0, 0, 0}, {1e4, 1e4, 0}}, params);
      },
      {"export: cell", "expected a larger cell"});
  params.cell_m = 1.0;
  EXPECT_EQ(seabedGrid({}, params).width, 0);
}

TEST(GeoTiffFile, GdalReadsTheGridTheCrsAndNoData) {
  test::ScratchDir dir;
  SeabedGridParams params;
  params.cell_m = kCell_m;
  HeightRaster r = seabedGrid(scene(), params);
  r.crs_wkt = crsWkt("EPSG:32631", "test", "crs");
  r.description = "seabed height";
  const auto path = dir.path() / "dem.tif";
  writeGeoTiff(path, r);
  GDALAllRegister();
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  double t[6] = {};
  ASSERT_EQ(GDALGetGeoTransform(ds, t), CE_None);
  EXPECT_EQ(t[0], 100.0);
  EXPECT_EQ(t[1], kCell_m);
  EXPECT_EQ(t[3], 53.0);
  EXPECT_EQ(t[5], -kCell_m);
  EXPECT_NE(std::string(GDALGetProjectionRef(ds)).find("UTM zone 31N"), std::string::npos);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  int has_nodata = 0;
  EXPECT_EQ(GDALGetRasterNoDataValue(band, &has_nodata), kGeoTiffNoData);
  EXPECT_TRUE(has_nodata);
  std::vector<float> values(r.values.size());
  ASSERT_EQ(GDALRasterIO(band, GF_Read, 0, 0, r.width, r.height, values.data(), r.width, r.height,
                         GDT_Float32, 0, 0),
            CE_None);
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(values[i], std::isnan(r.values[i]) ? kGeoTiffNoData : r.values[i]) << i;
  }
  GDALClose(ds);

  // Without a CRS: none in the file.
  r.crs_wkt.clear();
  writeGeoTiff(dir.path() / "local.tif", r);
  ds = GDALOpen((dir.path() / "local.tif").c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  EXPECT_EQ(std::string(GDALGetProjectionRef(ds)), "");
  GDALClose(ds);
}

TEST(GeoTiffFile, AnEmptyGridIsRefusedAndThePreviousFileKept) {
  test::ScratchDir dir;
  const auto path = dir.path() / "dem.tif";
  test::writeText(path, "previous");
  expectError([&] { writeGeoTiff(path, HeightRaster{}); }, {path.string(), "no cell holds data"});
  EXPECT_EQ(test::readText(path), "previous");
}

}  // namespace
}  // namespace sonarcarve
