// Coordinate reference systems through PROJ (core/geo/): which CRSs a map grid accepts, with
// errors that say why; transforms in the order easting/longitude first; and the grid bearing
// of true north that turns headings from true to grid north. Expected values are PROJ's own
// cs2cs (9.1.1) or the textbook convergence of a transverse Mercator.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "common/error.h"
#include "geo/crs.h"
#include "geo/crs_transform.h"
#include "geo/grid_projection.h"
#include "sonar/attitude.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;

// PROJ's transverse Mercator agrees with itself to the nanometre; cs2cs printed 6 decimals.
constexpr double kCs2csPrinted_m = 1e-6;

TEST(GridCrs, ProjectedCrsInMetresOnly) {
  EXPECT_FALSE(gridCrsProblem("EPSG:32631"));
  EXPECT_FALSE(gridCrsProblem("+proj=utm +zone=31 +datum=WGS84 +units=m +type=crs"));
  const auto unknown = gridCrsProblem("EPSG:99999999");
  ASSERT_TRUE(unknown);
  EXPECT_NE(unknown->find("'EPSG:99999999' is not a CRS PROJ knows"), std::string::npos);
  EXPECT_NE(unknown->find("expected a projected CRS in metres"), std::string::npos);
  const auto geographic = gridCrsProblem("EPSG:4326");
  ASSERT_TRUE(geographic);
  EXPECT_NE(geographic->find("not a projected CRS"), std::string::npos);
  const auto feet = gridCrsProblem("EPSG:2263");  // NAD83 / New York Long Island (ftUS)
  ASSERT_TRUE(feet);
  EXPECT_NE(feet->find("does not have two axes in metres"), std::string::npos);
  EXPECT_TRUE(gridCrsProblem(""));
  EXPECT_TRUE(gridCrsProblem("not a crs at all"));
  EXPECT_TRUE(gridCrsProblem("+proj=utm +zone=31"));  // a conversion, not a CRS
  expectError([] { requireGridCrs("EPSG:4326", "mission.yaml", "line 4: crs"); },
              {"mission.yaml: line 4: crs: 'EPSG:4326'", "not a projected CRS"});
}

TEST(GridCrs, UtmZoneByLongitudeAndHemisphere) {
  EXPECT_EQ(utmZoneCrs(43.0, 3.0), "EPSG:32631");
  EXPECT_EQ(utmZoneCrs(-33.9, 151.2), "EPSG:32756");  // Sydney
  EXPECT_EQ(utmZoneCrs(0.0, -180.0), "EPSG:32601");
  EXPECT_EQ(utmZoneCrs(10.0, 180.0), "EPSG:32660");  // the antimeridian stays in zone 60
  EXPECT_EQ(crsName("EPSG:32631"), "WGS 84 / UTM zone 31N");
  EXPECT_EQ(crsComment("EPSG:32631"), "crs EPSG:32631");
  EXPECT_EQ(crsComment("PROJCRS[\"x\",\n  BASEGEOGCRS"), "crs PROJCRS[\"x\",   BASEGEOGCRS");
}

TEST(CrsTransform, LongitudeLatitudeToUtmAsCs2cs) {
  CrsTransform utm(kWgs84Crs, "EPSG:32631", "test", "");
  // cs2cs -f %.6f EPSG:4326 EPSG:32631 <<< "43 3 0": 500000.000000 4760814.796087
  const auto p = utm.apply({3.0, 43.0, -12.5});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x(), 500000.0, kCs2csPrinted_m);
  EXPECT_NEAR(p->y(), 4760814.796087, kCs2csPrinted_m);
  EXPECT_EQ(p->z(), -12.5);  // heights pass through a 2D projection
  // Moved, it still works; the moved-from object is not used again.
  CrsTransform moved = std::move(utm);
  const auto q = moved.apply({5.0, 43.0, 0.0});  // cs2cs: 663019.070081 4762755.641689
  ASSERT_TRUE(q);
  EXPECT_NEAR(q->x(), 663019.070081, kCs2csPrinted_m);
  EXPECT_NEAR(q->y(), 4762755.641689, kCs2csPrinted_m);
  EXPECT_FALSE(moved.apply({3.0, 95.0, 0.0}));  // no latitude 95
  EXPECT_FALSE(moved.lastError().empty());
}

TEST(CrsTransform, UnknownCrsNamesWhereItCameFrom) {
  expectError([] { CrsTransform bad("EPSG:32631", "EPSG:0", "export", "crs"); },
              {"export: crs: 'EPSG:0' is not a CRS PROJ knows", "EPSG:32631"});
  expectError([] { CrsTransform bad("", "EPSG:32631", "nav.csv", "line 1"); },
              {"nav.csv: line 1", "is not a CRS PROJ knows"});
}

TEST(GridProjection, TrueNorthBearingIsTheGridConvergence) {
  const GridProjection grid(kWgs84Crs, "EPSG:32631", "test", "");
  // On the central meridian grid north is true north.
  const auto on_meridian = grid.place(3.0, 43.0, "test", "");
  EXPECT_NEAR(on_meridian.true_north_bearing_rad, 0.0, 1e-9);
  EXPECT_NEAR(on_meridian.east_m, 500000.0, kCs2csPrinted_m);
  EXPECT_NEAR(on_meridian.north_m, 4760814.796087, kCs2csPrinted_m);
  // Two degrees east of it at 43 N the meridian leans west of grid north by the convergence,
  // tan(gamma) = tan(dlon) sin(lat) on the sphere: 1.3642 deg; the ellipsoid adds terms of
  // dlon^3, under 0.001 deg here.
  const auto east = grid.place(5.0, 43.0, "test", "");
  const double sphere = std::atan(std::tan(degToRad(2.0)) * std::sin(degToRad(43.0)));
  EXPECT_NEAR(east.true_north_bearing_rad, -sphere, degToRad(0.001));
  // West of it, the other way; south of the equator, the other way again.
  EXPECT_GT(grid.place(1.0, 43.0, "test", "").true_north_bearing_rad, 0.0);
  EXPECT_GT(grid.place(5.0, -43.0, "test", "").true_north_bearing_rad, 0.0);
}

TEST(GridProjection, HeadingsTurnFromTrueToGridNorth) {
  const GridProjection grid(kWgs84Crs, "EPSG:32631", "nav.csv", "header");
  std::vector<NavSample> samples(2);
  samples[0].position_m.z() = 7.0;
  samples[0].q_world_vehicle = quaternionFromRollPitchYaw({0.0, 0.0, degToRad(90.0)});
  samples[1].time_s = 1.0;
  const std::vector<Eigen::Vector2d> xy = {{5.0, 43.0}, {3.0, 43.0}};
  placeOnGrid(samples, xy, grid,
              {"nav.csv", [](std::size_t i) { return "sample " + std::to_string(i); }});
  EXPECT_NEAR(samples[0].position_m.y(), 663019.070081, kCs2csPrinted_m);
  EXPECT_NEAR(samples[0].position_m.x(), 4762755.641689, kCs2csPrinted_m);
  EXPECT_EQ(samples[0].position_m.z(), 7.0);
  const double bearing = grid.place(5.0, 43.0, "", "").true_north_bearing_rad;
  const RollPitchYaw rpy = rollPitchYawFromQuaternion(samples[0].q_world_vehicle);
  EXPECT_NEAR(rpy.yaw_rad, degToRad(90.0) + bearing, 1e-12);
  EXPECT_NEAR(rpy.roll_rad, 0.0, 1e-12);
  EXPECT_NEAR(rpy.pitch_rad, 0.0, 1e-12);
  // A point PROJ cannot place names the file and the sample.
  const std::vector<Eigen::Vector2d> far = {{3.0, 91.0}, {3.0, 43.0}};
  expectError(
      [&] {
        placeOnGrid(samples, far, grid,
                    {"nav.csv", [](std::size_t i) { return "line " + std::to_string(i + 2); }});
      },
      {"nav.csv: line 2", "cannot be placed on the mission's grid"});
}

}  // namespace
}  // namespace sonarcarve
