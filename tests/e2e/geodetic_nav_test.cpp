// Geodetic navigation in, georeferenced points out (issue 43): the simulated riser with its
// navigation given in WGS84 latitude and longitude, 60 km east of UTM 31N's central meridian
// (headings there are 0.5 deg off grid north), reconstructs to the same surface as its NED
// twin; `export --crs EPSG:32631` writes points where PROJ's own cs2cs puts the mission origin
// plus their local offsets (the round trip geodetic -> local -> projected of
// docs/conventions.md), and `--crs EPSG:32632` where cs2cs moves them to the next zone, each
// to 1 mm. cs2cs comes from proj-bin (packaging/install-deps.sh).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/angles.h"
#include "common/number_text.h"
#include "io/mission/nav_csv.h"
#include "occlusion/surface_points.h"
#include "sonar/attitude.h"
#include "support/cli_runner.h"
#include "support/las_read_back.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

// The bar: a point's coordinates as cs2cs's to a millimetre.
constexpr double kCs2csAgreement_m = 0.001;
// The NED twin's world frame on the grid of UTM 31N: 60 km east of the central meridian.
const Eigen::Vector2d kGridOffsetEN(560000.0, 4760000.0);
// The bearing of true north from a point 1e-5 deg north of it (docs/conventions.md).
constexpr double kNorthStep_deg = 1e-5;

// x, y, z of every input line through `cs2cs -f %.12f from to` (12 decimals: 1e-7 m in
// degrees, 1e-12 m in metres).
std::vector<Eigen::Vector3d> cs2cs(const std::filesystem::path& dir, const std::string& from,
                                   const std::string& to,
                                   const std::vector<Eigen::Vector3d>& points) {
  std::ostringstream in;
  in.precision(17);
  for (const Eigen::Vector3d& p : points) {
    in << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  test::writeText(dir / "cs2cs-in.txt", in.str());
  const auto run = test::runShell("cs2cs -f %.12f " + from + " " + to + " < " +
                                  quoted(dir / "cs2cs-in.txt") + " 2>&1");
  EXPECT_EQ(run.exit_code, 0) << "PROJ's cs2cs (Debian proj-bin, packaging/install-deps.sh): "
                              << run.output;
  std::vector<Eigen::Vector3d> out;
  std::istringstream lines(run.output);
  Eigen::Vector3d p;
  while (lines >> p.x() >> p.y() >> p.z()) {
    out.push_back(p);
  }
  EXPECT_EQ(out.size(), points.size()) << run.output;
  return out;
}

class GeodeticNavigation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir;
    const auto sim =
        runCli("simulate --scene riser --noise none --max-frames 20 --out " + quoted(path("ned")));
    ASSERT_EQ(sim.exit_code, 0) << sim.output;
    const auto rec =
        runCli("reconstruct " + quoted(path("ned")) + " --out " + quoted(path("out-ned")));
    ASSERT_EQ(rec.exit_code, 0) << rec.output;
    writeGeodeticTwin();
    const auto geo = runCli("reconstruct " + quoted(path("geodetic")) + " --out " +
                            quoted(path("out-geodetic")));
    ASSERT_EQ(geo.exit_code, 0) << geo.output;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::filesystem::path path(const std::string& name) { return dir_->path() / name; }

  // The NED mission with its navigation in latitude and longitude (cs2cs from the grid
  // position kGridOffsetEN + east, north), headings from true north, and a geodetic origin
  // at kGridOffsetEN; its ground truth files, in the twin's frame, are left out.
  static void writeGeodeticTwin() {
    test::copyMissionWithoutTruth(path("ned"), path("geodetic"));
    const NavTrack nav = readNavCsv(path("ned") / "nav.csv");
    std::vector<Eigen::Vector3d> grid = {{kGridOffsetEN.x(), kGridOffsetEN.y(), 0.0}};
    for (const NavSample& s : nav.samples()) {
      grid.emplace_back(kGridOffsetEN.x() + s.position_m.y(), kGridOffsetEN.y() + s.position_m.x(),
                        0.0);
    }
    const auto geodetic = cs2cs(dir_->path(), "EPSG:32631", "EPSG:4326", grid);  // lat lon
    std::vector<Eigen::Vector3d> north_of;
    for (const Eigen::Vector3d& g : geodetic) {
      north_of.emplace_back(g.x() + kNorthStep_deg, g.y(), 0.0);
    }
    const auto north_grid = cs2cs(dir_->path(), "EPSG:4326", "EPSG:32631", north_of);
    ASSERT_EQ(north_grid.size(), grid.size());
    std::ostringstream csv;
    csv.precision(17);
    csv << "time_s,latitude_deg,longitude_deg,down_m,roll_deg,pitch_deg,yaw_deg\n";
    for (std::size_t i = 0; i < nav.samples().size(); ++i) {
      const NavSample& s = nav.samples()[i];
      const Eigen::Vector3d toward_north = north_grid[i + 1] - grid[i + 1];
      const double true_north_bearing = std::atan2(toward_north.x(), toward_north.y());
      const RollPitchYaw rpy = rollPitchYawFromQuaternion(s.q_world_vehicle);
      csv << s.time_s << ',' << geodetic[i + 1].x() << ',' << geodetic[i + 1].y() << ','
          << s.position_m.z() << ',' << radToDeg(rpy.roll_rad) << ',' << radToDeg(rpy.pitch_rad)
          << ',' << radToDeg(rpy.yaw_rad - true_north_bearing) << '\n';
    }
    test::writeText(path("geodetic") / "nav.csv", csv.str());
    origin_lat_lon_ = geodetic.front();
    std::ostringstream origin;
    origin.precision(17);
    origin << "origin: {latitude_deg: " << origin_lat_lon_.x()
           << ", longitude_deg: " << origin_lat_lon_.y() << ", depth_m: 0}\n";
    test::writeText(path("geodetic") / "mission.yaml",
                    test::readText(path("ned") / "mission.yaml") + origin.str());
  }

  static test::ScratchDir* dir_;
  static Eigen::Vector3d origin_lat_lon_;
};

test::ScratchDir* GeodeticNavigation::dir_ = nullptr;
Eigen::Vector3d GeodeticNavigation::origin_lat_lon_ = Eigen::Vector3d::Zero();

TEST_F(GeodeticNavigation, SameSurfaceAsTheNedTwinWithTheCrsInEveryOutput) {
  const auto report = nlohmann::json::parse(test::readText(path("out-geodetic") / "report.json"));
  EXPECT_EQ(report["crs"], "EPSG:32631");  // the UTM zone of the first sample
  EXPECT_FALSE(
      nlohmann::json::parse(test::readText(path("out-ned") / "report.json")).contains("crs"));
  for (const char* file : {"surface_points.ply", "mesh.ply", "map.bt"}) {
    EXPECT_NE(test::readText(path("out-geodetic") / file).find("crs EPSG:32631\n"),
              std::string::npos)
        << file;
  }
  const auto info = runCli("info " + quoted(path("geodetic")));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("CRS          EPSG:32631 (WGS 84 / UTM zone 31N)"), std::string::npos)
      << info.output;
  const auto info_json =
      nlohmann::json::parse(runCli("info --json " + quoted(path("geodetic"))).output);
  EXPECT_EQ(info_json["crs"], "EPSG:32631");
  // Local to an origin cs2cs puts at kGridOffsetEN (to 1e-7 m), the points are the twin's:
  // a heading left on true north would turn them by 0.5 deg, 9 mm per metre of range.
  const SurfacePoints ned = readSurfacePointsPly(path("out-ned") / "surface_points.ply");
  const SurfacePoints geo = readSurfacePointsPly(path("out-geodetic") / "surface_points.ply");
  ASSERT_GT(ned.size(), 500u);
  EXPECT_EQ(geo.size(), ned.size());
  double worst_m = 0.0;
  for (const SurfacePoint& p : geo) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const SurfacePoint& q : ned) {
      nearest = std::min(nearest, (p.position_m - q.position_m).cast<double>().norm());
    }
    worst_m = std::max(worst_m, nearest);
  }
  EXPECT_LE(worst_m, kCs2csAgreement_m);
  RecordProperty("worst_twin_difference_mm", std::to_string(worst_m * 1e3));
}

TEST_F(GeodeticNavigation, ExportInUtmMatchesCs2csToAMillimetre) {
  const auto local_file = path("out-geodetic") / "surface_points.ply";
  const auto utm31 = path("utm31.ply");
  const auto exported =
      runCli("export " + quoted(path("out-geodetic")) +
             " --points --crs EPSG:32631 --format ply-ascii --out " + quoted(utm31));
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  std::string header;
  const std::vector<Eigen::Vector3d> points = test::readAsciiPlyPoints(utm31, &header);
  EXPECT_NE(header.find("property double x"), std::string::npos);
  EXPECT_NE(header.find("comment crs EPSG:32631\n"), std::string::npos);
  EXPECT_NE(header.find("comment axes x easting, y northing, z up"), std::string::npos);
  EXPECT_NE(header.find("comment mission origin (north east down)"), std::string::npos);
  EXPECT_EQ(header.find("comment origin_ned_m"), std::string::npos);  // not local to it
  const SurfacePoints local = readSurfacePointsPly(local_file);
  ASSERT_EQ(points.size(), local.size());

  // The round trip: the origin's latitude and longitude through cs2cs, plus each point's local
  // north, east and down (up = -down).
  const Eigen::Vector3d origin =
      cs2cs(dir_->path(), "EPSG:4326", "EPSG:32631", {origin_lat_lon_}).front();
  double worst_m = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = local[i].position_m.cast<double>();
    const Eigen::Vector3d expected(origin.x() + p.y(), origin.y() + p.x(), -p.z());
    worst_m = std::max(worst_m, (points[i] - expected).norm());
  }
  EXPECT_LE(worst_m, kCs2csAgreement_m);
  RecordProperty("worst_cs2cs_difference_utm31_mm", std::to_string(worst_m * 1e3));

  // Into the next zone: cs2cs moves the UTM 31N points, we move the map.
  const auto utm32 = path("utm32.ply");
  const auto next = runCli("export " + quoted(path("out-geodetic")) +
                           " --points --crs EPSG:32632 --format ply-ascii --out " + quoted(utm32));
  ASSERT_EQ(next.exit_code, 0) << next.output;
  std::string header32;
  const std::vector<Eigen::Vector3d> moved = test::readAsciiPlyPoints(utm32, &header32);
  EXPECT_NE(header32.find("comment crs EPSG:32632\n"), std::string::npos);
  const auto expected32 = cs2cs(dir_->path(), "EPSG:32631", "EPSG:32632", points);
  ASSERT_EQ(moved.size(), expected32.size());
  double worst32_m = 0.0;
  for (std::size_t i = 0; i < moved.size(); ++i) {
    worst32_m = std::max(worst32_m, (moved[i] - expected32[i]).norm());
  }
  EXPECT_LE(worst32_m, kCs2csAgreement_m);
  EXPECT_GT((moved.front() - points.front()).norm(), 1e5) << "another zone, another grid";
  RecordProperty("worst_cs2cs_difference_utm32_mm", std::to_string(worst32_m * 1e3));

  // The mesh as OBJ in the CRS too; STL (float32) is refused.
  const auto obj = runCli("export " + quoted(path("out-geodetic")) + " --crs EPSG:32631 --out " +
                          quoted(path("mesh31.obj")));
  ASSERT_EQ(obj.exit_code, 0) << obj.output;
  EXPECT_NE(test::readText(path("mesh31.obj")).find("# crs EPSG:32631\n"), std::string::npos);
  const auto stl = runCli("export " + quoted(path("out-geodetic")) + " --crs EPSG:32631 --out " +
                          quoted(path("mesh31.stl")));
  EXPECT_NE(stl.exit_code, 0);
  EXPECT_NE(stl.output.find("STL holds float32"), std::string::npos) << stl.output;
}

// LAS 1.4 in UTM 31N: the points read back (support/las_read_back.h) where cs2cs puts the
// mission origin plus their local offsets, to 1 mm; the CRS record is UTM 31N by GDAL's
// gdalsrsinfo (gdal-bin, packaging/install-deps.sh). Without --crs the LAS is in the mission's
// CRS, the same points.
TEST_F(GeodeticNavigation, LasReadsBackToTheMillimetreWithItsCrs) {
  const auto las_file = path("utm31.las");
  const auto exported = runCli("export " + quoted(path("out-geodetic")) +
                               " --format las --crs EPSG:32631 --out " + quoted(las_file));
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  const test::LasReadBack las = test::readLasBack(las_file);
  EXPECT_EQ(las.point_format, 6);
  EXPECT_EQ(las.global_encoding & 0x10, 0x10);
  const SurfacePoints local = readSurfacePointsPly(path("out-geodetic") / "surface_points.ply");
  ASSERT_EQ(las.points.size(), local.size());
  const Eigen::Vector3d origin =
      cs2cs(dir_->path(), "EPSG:4326", "EPSG:32631", {origin_lat_lon_}).front();
  double worst_m = 0.0;
  for (std::size_t i = 0; i < las.points.size(); ++i) {
    const Eigen::Vector3d p = local[i].position_m.cast<double>();
    const Eigen::Vector3d expected(origin.x() + p.y(), origin.y() + p.x(), -p.z());
    worst_m = std::max(worst_m, (las.points[i] - expected).norm());
  }
  EXPECT_LE(worst_m, kCs2csAgreement_m);
  RecordProperty("worst_las_cs2cs_difference_mm", std::to_string(worst_m * 1e3));

  test::writeText(path("las.wkt"), las.wkt);
  const auto srs = test::runShell("gdalsrsinfo -o epsg " + quoted(path("las.wkt")) + " 2>&1");
  EXPECT_EQ(srs.exit_code, 0) << "GDAL's gdalsrsinfo (Debian gdal-bin): " << srs.output;
  EXPECT_NE(srs.output.find("EPSG:32631"), std::string::npos) << srs.output;

  const auto mission_crs = runCli("export " + quoted(path("out-geodetic")) +
                                  " --format las --out " + quoted(path("mission.las")));
  ASSERT_EQ(mission_crs.exit_code, 0) << mission_crs.output;
  EXPECT_EQ(test::readText(path("mission.las")), test::readText(las_file));

  // A reconstruction without a CRS: local coordinates, x east, y north, z up, no CRS record.
  const auto ned =
      runCli("export " + quoted(path("out-ned")) + " --out " + quoted(path("local.las")));
  ASSERT_EQ(ned.exit_code, 0) << ned.output;
  const test::LasReadBack local_las = test::readLasBack(path("local.las"));
  EXPECT_TRUE(local_las.wkt.empty());
  const SurfacePoints ned_points = readSurfacePointsPly(path("out-ned") / "surface_points.ply");
  ASSERT_EQ(local_las.points.size(), ned_points.size());
  const Eigen::Vector3d n = ned_points.front().position_m.cast<double>();
  EXPECT_LE((local_las.points.front() - Eigen::Vector3d(n.y(), n.x(), -n.z())).norm(), 1e-4);
}

TEST_F(GeodeticNavigation, ExportRefusesWhatItCannotPlace) {
  const auto geographic = runCli("export " + quoted(path("out-geodetic")) +
                                 " --points --crs EPSG:4326 --out " + quoted(path("ll.ply")));
  EXPECT_NE(geographic.exit_code, 0);
  EXPECT_NE(geographic.output.find("export: crs: 'EPSG:4326'"), std::string::npos)
      << geographic.output;
  EXPECT_NE(geographic.output.find("not a projected CRS"), std::string::npos);
  const auto unknown = runCli("export " + quoted(path("out-geodetic")) +
                              " --points --crs EPSG:99999999 --out " + quoted(path("x.ply")));
  EXPECT_NE(unknown.exit_code, 0);
  EXPECT_NE(unknown.output.find("is not a CRS PROJ knows"), std::string::npos) << unknown.output;
  const auto no_crs = runCli("export " + quoted(path("out-ned")) +
                             " --points --crs EPSG:32631 --out " + quoted(path("y.ply")));
  EXPECT_NE(no_crs.exit_code, 0);
  EXPECT_NE(no_crs.output.find("the reconstruction has no CRS"), std::string::npos)
      << no_crs.output;
  EXPECT_FALSE(std::filesystem::exists(path("ll.ply")));
}

}  // namespace
}  // namespace sonarcarve
