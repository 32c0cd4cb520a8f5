// Geodetic and projected navigation (docs/formats.md, "nav.csv"; docs/conventions.md,
// "Geodetic navigation and CRSs"): latitude/longitude or easting/northing with a CRS, placed on
// the mission's projected grid by PROJ, also through a column mapping; a mission origin in
// mission.yaml; and every bad input (two kinds of position, wrong CRS codes, positions off the
// Earth, empty, truncated and corrupt files) refused naming the file, the place and what was
// expected. Expected positions are PROJ's cs2cs (9.1.1) printed to the micrometre.
#include <gtest/gtest.h>

#include <sstream>

#include "common/angles.h"
#include "common/error.h"
#include "io/frame_source.h"
#include "io/mission/mission.h"
#include "io/mission/mission_writer.h"
#include "io/mission/nav_csv.h"
#include "io/mission/nav_import.h"
#include "sonar/attitude.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;
using test::readText;
using test::writeText;

constexpr double kCs2csPrinted_m = 1e-6;
// cs2cs -f %.6f EPSG:4326 EPSG:32631: (43 N, 3 E) and (43 N, 5 E).
const Eigen::Vector2d kAt3E(500000.0, 4760814.796087);  // easting, northing
const Eigen::Vector2d kAt5E(663019.070081, 4762755.641689);

// The example mission's navigation times and depths with other position columns: `header`
// replaces "north_m,east_m" and `position(i)` the two values of row i.
std::string navWith(const std::string& header, const std::function<std::string(int)>& position) {
  std::istringstream in(readText(test::exampleMission() / "nav.csv"));
  std::string line, out;
  std::getline(in, line);
  out = "time_s," + header + ",down_m,roll_deg,pitch_deg,yaw_deg\n";
  for (int i = 0; std::getline(in, line); ++i) {
    const auto first = line.find(',');
    const auto third = line.find(',', line.find(',', first + 1) + 1);
    out += line.substr(0, first + 1) + position(i) + line.substr(third) + "\n";
  }
  return out;
}

class GeodeticNav : public ::testing::Test {
 protected:
  void SetUp() override { mission_ = test::copyExampleMission(dir_.path()); }
  void yamlAppend(const std::string& text) {
    writeText(mission_ / "mission.yaml", readText(mission_ / "mission.yaml") + text);
  }
  void expectReadError(const std::vector<std::string>& fragments) {
    expectError([&] { readMission(mission_); }, fragments);
  }
  test::ScratchDir dir_;
  std::filesystem::path mission_;
};

TEST_F(GeodeticNav, LatitudeLongitudeLandOnTheUtmZoneOfTheFirstSample) {
  writeText(mission_ / "nav.csv", navWith("latitude_deg,longitude_deg", [](int i) {
              return i == 0 ? std::string("43,5") : std::string("43,3");
            }));
  const Mission m = readMission(mission_);
  EXPECT_EQ(m.crs, "EPSG:32631");
  EXPECT_TRUE(m.origin_ned_m.isZero());  // placed near zero by openMission, not here
  const NavSample& a = m.nav.samples()[0];
  EXPECT_NEAR(a.position_m.x(), kAt5E.y(), kCs2csPrinted_m);
  EXPECT_NEAR(a.position_m.y(), kAt5E.x(), kCs2csPrinted_m);
  EXPECT_EQ(a.position_m.z(), 9.95);
  // Heading 0 (true north) at 5 E is about -1.364 deg on the grid: the convergence.
  EXPECT_NEAR(radToDeg(rollPitchYawFromQuaternion(a.q_world_vehicle).yaw_rad), -1.364, 0.001);
  const NavSample& b = m.nav.samples()[1];
  EXPECT_NEAR(b.position_m.x(), kAt3E.y(), kCs2csPrinted_m);
  EXPECT_NEAR(radToDeg(rollPitchYawFromQuaternion(b.q_world_vehicle).yaw_rad), 0.0, 1e-7);
  // Opened, the mission is carved about an origin near its track, as UTM navigation is.
  const Mission opened = openMission(mission_);
  EXPECT_EQ(opened.crs, "EPSG:32631");
  EXPECT_GT(opened.origin_ned_m.norm(), 4e6);
}

TEST_F(GeodeticNav, DeclaredCrsAndGeodeticOrigin) {
  writeText(mission_ / "nav.csv",
            navWith("latitude_deg,longitude_deg", [](int) { return std::string("43,3"); }));
  yamlAppend("crs: EPSG:32632\norigin: {latitude_deg: 43, longitude_deg: 3, depth_m: 2}\n");
  const Mission m = readMission(mission_);
  EXPECT_EQ(m.crs, "EPSG:32632");
  // cs2cs -f %.6f EPSG:4326 EPSG:32632 <<< "43 3": 10887.227805 4778314.012073
  EXPECT_NEAR(m.origin_ned_m.x(), 4778314.012073, kCs2csPrinted_m);
  EXPECT_NEAR(m.origin_ned_m.y(), 10887.227805, kCs2csPrinted_m);
  EXPECT_EQ(m.origin_ned_m.z(), 2.0);
  // The navigation is local to the origin: here, at it, 2 m above its depth.
  EXPECT_NEAR(m.nav.samples()[0].position_m.head<2>().norm(), 0.0, 1e-6);
  EXPECT_NEAR(m.nav.samples()[0].position_m.z(), 9.95 - 2.0, 1e-12);
  EXPECT_NEAR(worldTrack(m).samples()[0].position_m.x(), 4778314.012073, kCs2csPrinted_m);
}

TEST_F(GeodeticNav, EastingNorthingInTheMissionCrsWithAProjectedOrigin) {
  writeText(mission_ / "nav.csv", navWith("easting_m,northing_m", [](int i) {
              return i == 0 ? std::string("663019.070081,4762755.641689")
                            : std::string("500000,4760814.796087");
            }));
  yamlAppend("crs: EPSG:32631\norigin: {easting_m: 500000, northing_m: 4760800, depth_m: 0}\n");
  const Mission m = readMission(mission_);
  EXPECT_EQ(m.crs, "EPSG:32631");
  EXPECT_EQ(m.origin_ned_m, Eigen::Vector3d(4760800, 500000, 0));
  EXPECT_NEAR(m.nav.samples()[1].position_m.x(), 14.796087, 1e-9);
  EXPECT_NEAR(m.nav.samples()[1].position_m.y(), 0.0, 1e-9);
  // Headings are from true north still: turned by the convergence at 5 E.
  EXPECT_NEAR(radToDeg(rollPitchYawFromQuaternion(m.nav.samples()[0].q_world_vehicle).yaw_rad),
              -1.364, 0.001);
}

TEST_F(GeodeticNav, AWrittenMissionKeepsItsCrs) {
  writeText(mission_ / "nav.csv",
            navWith("latitude_deg,longitude_deg", [](int) { return std::string("43,5"); }));
  const Mission m = readMission(mission_);
  MissionWriter writer(dir_.path() / "copy", m.name, m.sonar, m.mounting);
  writer.addFrame(loadFrame(m, 0));
  writer.finish(worldTrack(m), m.crs);
  const Mission copy = readMission(dir_.path() / "copy");
  EXPECT_EQ(copy.crs, "EPSG:32631");
  // World NED on the grid, headings on grid north: read back as they were written.
  EXPECT_NEAR(copy.nav.samples()[0].position_m.y(), kAt5E.x(), kCs2csPrinted_m);
  EXPECT_NEAR(rollPitchYawFromQuaternion(copy.nav.samples()[0].q_world_vehicle).yaw_rad,
              rollPitchYawFromQuaternion(m.nav.samples()[0].q_world_vehicle).yaw_rad, 1e-12);
}

TEST_F(GeodeticNav, NedNavigationWithADeclaredCrsKeepsItsNumbers) {
  yamlAppend("crs: EPSG:32631\n");
  const Mission m = readMission(mission_);
  const Mission plain = readMission(test::exampleMission());
  EXPECT_EQ(m.crs, "EPSG:32631");
  EXPECT_TRUE(plain.crs.empty());
  for (std::size_t i = 0; i < m.nav.samples().size(); ++i) {
    EXPECT_EQ(m.nav.samples()[i].position_m, plain.nav.samples()[i].position_m);
    EXPECT_TRUE(
        m.nav.samples()[i].q_world_vehicle.isApprox(plain.nav.samples()[i].q_world_vehicle, 0.0));
  }
}

TEST_F(GeodeticNav, BothLatitudeLongitudeAndNorthEastIsAnError) {
  writeText(mission_ / "nav.csv",
            "time_s,north_m,east_m,latitude_deg,longitude_deg,down_m,roll_deg,pitch_deg,yaw_deg\n"
            "99.75,0,0,43,3,9.95,0,0,0\n");
  expectReadError({"nav.csv: line 1", "positions of two kinds", "north_m, east_m",
                   "latitude_deg, longitude_deg", "expected one kind"});
  writeText(mission_ / "nav.csv",
            "time_s,easting_m,northing_m,latitude_deg,longitude_deg,down_m,roll_deg,pitch_deg,"
            "yaw_deg\n99.75,0,0,43,3,9.95,0,0,0\n");
  expectReadError({"nav.csv: line 1", "positions of two kinds"});
}

TEST_F(GeodeticNav, WrongCrsCodesNameTheFileAndTheField) {
  yamlAppend("crs: EPSG:99999999\n");
  expectReadError({"mission.yaml: line 16: crs: 'EPSG:99999999' is not a CRS PROJ knows",
                   "expected a projected CRS in metres"});
  writeText(mission_ / "mission.yaml",
            readText(test::exampleMission() / "mission.yaml") + "crs: EPSG:4326\n");
  expectReadError({"mission.yaml: line 16: crs", "not a projected CRS"});
  writeText(mission_ / "mission.yaml", readText(test::exampleMission() / "mission.yaml") +
                                           "crs: EPSG:32631\norigin: {easting_m: 1, "
                                           "northing_m: 2, depth_m: 0, crs: EPSG:nonsense}\n");
  expectReadError({"mission.yaml: line 17: origin.crs: 'EPSG:nonsense' is not a CRS"});
}

TEST_F(GeodeticNav, OriginsThatCannotBePlaced) {
  yamlAppend("origin: {latitude_deg: 43, longitude_deg: 3, depth_m: 0}\n");
  expectReadError({"mission.yaml: line 16: origin", "NED without a CRS", "expected crs:"});
  const std::string base = readText(test::exampleMission() / "mission.yaml") + "crs: EPSG:32631\n";
  writeText(mission_ / "mission.yaml",
            base + "origin: {latitude_deg: 43, easting_m: 3, depth_m: 0}\n");
  expectReadError({"line 17: origin: keys of both kinds"});
  writeText(mission_ / "mission.yaml", base + "origin: {latitude_deg: 43, longitude_deg: 3}\n");
  expectReadError({"origin", "depth_m"});
  writeText(mission_ / "mission.yaml",
            base + "origin: {latitude_deg: 95, longitude_deg: 3, depth_m: 0}\n");
  expectReadError({"line 17", "latitude 95 deg: expected WGS84 degrees within -90..90"});
  writeText(mission_ / "mission.yaml", base + "origin: [43, 3]\n");
  expectReadError({"line 17: origin: expected {latitude_deg"});
}

TEST_F(GeodeticNav, ProjectedNavigationWithoutACrsIsAnError) {
  writeText(mission_ / "nav.csv",
            navWith("easting_m,northing_m", [](int) { return std::string("500000,4760800"); }));
  expectReadError(
      {"nav.csv: line 1", "easting and northing without the CRS", "expected crs: EPSG:NNNN"});
}

TEST_F(GeodeticNav, EmptyTruncatedAndCorruptGeodeticFiles) {
  const std::string header =
      "time_s,latitude_deg,longitude_deg,down_m,roll_deg,pitch_deg,yaw_deg\n";
  writeText(mission_ / "nav.csv", "");
  expectReadError({"nav.csv"});
  writeText(mission_ / "nav.csv", header);
  expectReadError({"nav.csv", "no navigation samples"});
  writeText(mission_ / "nav.csv", header + "99.75,43,3,9.95,0,0,0\n100.25,43.0001,3.0\n");
  expectReadError({"nav.csv: line 3"});
  writeText(mission_ / "nav.csv", header + "99.75,43,3,9.95,0,0,0\n100.25,43.x,3,9.95,0,0,0\n");
  expectReadError({"nav.csv: line 3", "latitude_deg", "expected a finite number"});
  writeText(mission_ / "nav.csv", header + "99.75,43,3,9.95,0,0,0\n100.25,95,3,9.95,0,0,0\n");
  expectReadError({"nav.csv: line 3", "latitude 95 deg: expected WGS84 degrees within -90..90"});
  writeText(mission_ / "nav.csv", header + "99.75,43,183,9.95,0,0,0\n");
  expectReadError({"nav.csv: line 2", "longitude 183 deg"});
  writeText(mission_ / "nav.csv",
            "time_s,latitude_deg,down_m,roll_deg,pitch_deg,yaw_deg\n1,43,0,0,0,0\n");
  expectReadError({"nav.csv: line 1", "missing column 'longitude_deg'"});
}

TEST_F(GeodeticNav, NavigationOutsideAMissionStaysNed) {
  writeText(dir_.path() / "truth.csv",
            navWith("latitude_deg,longitude_deg", [](int) { return std::string("43,3"); }));
  expectError([&] { readNavCsv(dir_.path() / "truth.csv"); },
              {"truth.csv: line 1", "geodetic or projected positions outside a mission",
               "expected north_m, east_m"});
}

TEST(GeodeticNavMapping, LatitudeLongitudeColumnsWithAMappingAndItsCrs) {
  test::ScratchDir dir;
  writeText(dir.path() / "map.yaml",
            "columns: {time: t, latitude: lat, longitude: lon, depth: z, heading: hdg}\n"
            "crs: EPSG:32631\n");
  writeText(dir.path() / "log.csv", "t,lat,lon,z,hdg\n0,43,5,10,0\n1,43,3,10,0\n");
  std::string crs;
  const NavTrack track =
      importNavCsv(dir.path() / "log.csv", readNavMapping(dir.path() / "map.yaml"), &crs);
  EXPECT_EQ(crs, "EPSG:32631");
  EXPECT_NEAR(track.samples()[0].position_m.y(), kAt5E.x(), kCs2csPrinted_m);
  EXPECT_NEAR(track.samples()[0].position_m.x(), kAt5E.y(), kCs2csPrinted_m);
  EXPECT_EQ(track.samples()[0].position_m.z(), 10.0);
  // From flags on the default mapping: latitude and longitude replace north and east; no crs
  // given, the first sample's UTM zone.
  NavMapping flags;
  setNavMapping(flags, "columns.time", "t", "--nav-column");
  setNavMapping(flags, "columns.latitude", "lat", "--nav-column");
  setNavMapping(flags, "columns.longitude", "lon", "--nav-column");
  setNavMapping(flags, "columns.depth", "z", "--nav-column");
  setNavMapping(flags, "columns.yaw", "hdg", "--nav-column");
  setNavMapping(flags, "columns.roll", "", "--nav-column");
  setNavMapping(flags, "columns.pitch", "", "--nav-column");
  std::string auto_crs;
  const NavTrack same = importNavCsv(dir.path() / "log.csv", flags, &auto_crs);
  EXPECT_EQ(auto_crs, "EPSG:32631");
  EXPECT_EQ(same.samples()[1].position_m, track.samples()[1].position_m);
  // The default mapping reads nav.csv's geodetic columns by the header.
  writeText(dir.path() / "nav.csv",
            "time_s,latitude_deg,longitude_deg,down_m,roll_deg,pitch_deg,yaw_deg\n"
            "0,43,3,1,0,0,0\n");
  std::string default_crs;
  const NavTrack by_header = importNavCsv(dir.path() / "nav.csv", NavMapping{}, &default_crs);
  EXPECT_EQ(default_crs, "EPSG:32631");
  EXPECT_NEAR(by_header.samples()[0].position_m.x(), kAt3E.y(), kCs2csPrinted_m);
}

TEST(GeodeticNavMapping, EmptyTruncatedAndCorruptGeodeticLogs) {
  NavMapping m;
  setNavMapping(m, "columns.time", "t", "--nav-column");
  setNavMapping(m, "columns.latitude", "lat", "--nav-column");
  setNavMapping(m, "columns.longitude", "lon", "--nav-column");
  setNavMapping(m, "columns.depth", "z", "--nav-column");
  for (const char* angle : {"columns.roll", "columns.pitch", "columns.yaw"}) {
    setNavMapping(m, angle, "", "--nav-column");  // no attitude columns: 0
  }
  const auto read = [&](const std::string& text) { return importNavCsvText(text, "log.csv", m); };
  expectError([&] { read(""); }, {"log.csv"});
  expectError([&] { read("t,lat,lon,z\n"); }, {"log.csv", "no navigation samples"});
  expectError([&] { read("t,lat,lon,z\n0,43,3,1\n1,43.1"); }, {"log.csv: line 3"});
  expectError([&] { read("t,lat,lon,z\n0,43,3,1\n1,43.1,3e,1\n"); },
              {"log.csv: line 3", "'lon'", "expected a finite number"});
  expectError([&] { read("t,lat,lon,z\n0,-91,3,1\n"); },
              {"log.csv: line 2", "latitude -91 deg: expected WGS84 degrees within -90..90"});
  expectError([&] { read("t,lat,z\n0,43,1\n"); }, {"log.csv: line 1", "missing column 'lon'"});
  EXPECT_EQ(read("t,lat,lon,z\n0,43,3,1\n").samples().size(), 1u);
}

TEST(GeodeticNavMapping, BadCrsAndTwoKindsInAMapping) {
  test::ScratchDir dir;
  writeText(dir.path() / "map.yaml",
            "columns: {time: t, latitude: lat, longitude: lon, depth: z}\n"
            "crs: EPSG:123456789\n");
  expectError([&] { readNavMapping(dir.path() / "map.yaml"); },
              {"map.yaml: line 2: crs: 'EPSG:123456789' is not a CRS PROJ knows"});
  NavMapping m;
  expectError([&] { setNavMapping(m, "crs", "EPSG:4326", "--nav-set"); },
              {"--nav-set: crs: 'EPSG:4326'", "not a projected CRS"});
  writeText(dir.path() / "both.yaml",
            "columns: {time: t, north: n, east: e, latitude: lat, longitude: lon, depth: z}\n");
  writeText(dir.path() / "log.csv", "t,n,e,lat,lon,z\n0,0,0,43,3,1\n");
  expectError(
      [&] { importNavCsv(dir.path() / "log.csv", readNavMapping(dir.path() / "both.yaml")); },
      {"log.csv", "the navigation mapping", "positions of two kinds"});
  writeText(dir.path() / "proj.yaml", "columns: {time: t, easting: e, northing: n, depth: z}\n");
  expectError(
      [&] { importNavCsv(dir.path() / "log.csv", readNavMapping(dir.path() / "proj.yaml")); },
      {"log.csv: line 1", "easting and northing without the CRS"});
}

}  // namespace
}  // namespace sonarcarve
