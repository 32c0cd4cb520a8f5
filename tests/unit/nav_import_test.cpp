// Navigation CSVs of other tools through a column mapping: units, angle conventions and
// errors that name the file, the line and the column.
#include <gtest/gtest.h>

#include <numbers>

#include "common/angles.h"
#include "common/error.h"
#include "io/mission/nav_import.h"
#include "sonar/attitude.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

RollPitchYaw attitude(const NavSample& s) {
  return rollPitchYawFromQuaternion(s.q_world_vehicle);
}

TEST(NavImport, MappingYamlWithFeetDegreesAndCompassHeading) {
  test::ScratchDir dir;
  test::writeText(dir.path() / "map.yaml", R"(# a survey log in feet
columns:
  time: t
  north: N
  east: E
  depth: Z
  heading: HDG
  pitch: P
  roll: R
units: {time: ms, position: ft, angles: deg}
conventions: {heading: compass}
)");
  test::writeText(dir.path() / "nav.csv",
                  "t,N,E,Z,HDG,P,R,extra\n"
                  "1000,10,20,30,90,5,-3,x\n"
                  "1500,0,-10,3.28084,270,0,0,y\n");
  const NavMapping mapping = readNavMapping(dir.path() / "map.yaml");
  const NavTrack track = importNavCsv(dir.path() / "nav.csv", mapping);
  ASSERT_EQ(track.samples().size(), 2u);
  const NavSample& a = track.samples()[0];
  EXPECT_DOUBLE_EQ(a.time_s, 1.0);
  EXPECT_NEAR(a.position_m.x(), 3.048, 1e-12);
  EXPECT_NEAR(a.position_m.y(), 6.096, 1e-12);
  EXPECT_NEAR(a.position_m.z(), 9.144, 1e-12);             // depth is down
  EXPECT_NEAR(radToDeg(attitude(a).yaw_rad), 90.0, 1e-9);  // heading east = NED yaw 90
  EXPECT_NEAR(radToDeg(attitude(a).pitch_rad), 5.0, 1e-9);
  EXPECT_NEAR(radToDeg(attitude(a).roll_rad), -3.0, 1e-9);
  const NavSample& b = track.samples()[1];
  EXPECT_DOUBLE_EQ(b.time_s, 1.5);
  EXPECT_NEAR(b.position_m.z(), 1.0, 1e-6);
  EXPECT_NEAR(radToDeg(attitude(b).yaw_rad), -90.0, 1e-9);  // heading 270 = west
}

TEST(NavImport, EnuYawAltitudeRadiansAndColumnIndicesWithoutHeader) {
  NavMapping m;
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"header", "false"},
                                                        {"delimiter", ";"},
                                                        {"columns.time", "0"},
                                                        {"columns.east", "1"},
                                                        {"columns.north", "2"},
                                                        {"columns.altitude", "3"},
                                                        {"columns.yaw", "4"},
                                                        {"columns.pitch", "5"},
                                                        {"columns.roll", "6"},
                                                        {"units.angles", "rad"},
                                                        {"conventions.heading", "enu"},
                                                        {"conventions.pitch", "bow_down"}}) {
    setNavMapping(m, key, value, "flags");
  }
  const std::string text = "0;1;2;-5;0;0.1;0.2\n1;1;2;-6;1.5707963267948966;0;0\n";
  const NavTrack track = importNavCsvText(text, "ros.csv", m);
  const NavSample& a = track.samples()[0];
  EXPECT_DOUBLE_EQ(a.position_m.x(), 2.0);                        // north
  EXPECT_DOUBLE_EQ(a.position_m.y(), 1.0);                        // east
  EXPECT_DOUBLE_EQ(a.position_m.z(), 5.0);                        // altitude -5 = 5 m down
  EXPECT_NEAR(attitude(a).yaw_rad, std::numbers::pi / 2, 1e-12);  // ENU yaw 0 faces east
  EXPECT_NEAR(attitude(a).pitch_rad, -0.1, 1e-12);                // bow down positive
  EXPECT_NEAR(attitude(a).roll_rad, 0.2, 1e-12);
  EXPECT_NEAR(attitude(track.samples()[1]).yaw_rad, 0.0, 1e-12);  // ENU yaw 90 faces north
}

TEST(NavImport, TheDefaultMappingReadsTheMissionFormat) {
  const NavTrack track = importNavCsv(test::exampleMission() / "nav.csv", NavMapping{});
  EXPECT_EQ(track.samples().size(), 11u);
  EXPECT_DOUBLE_EQ(track.startTime(), 99.75);
}

TEST(NavImport, AttitudeColumnsAreOptional) {
  NavMapping m;
  m.roll = m.pitch = m.yaw = {};
  const NavTrack track = importNavCsvText("time_s,north_m,east_m,down_m\n0,1,2,3\n", "n.csv", m);
  EXPECT_TRUE(track.samples()[0].q_world_vehicle.isApprox(Eigen::Quaterniond::Identity()));
}

using test::expectError;

TEST(NavImport, ErrorsNameFileLineAndColumn) {
  NavMapping m;
  expectError([&] { importNavCsvText("time_s,north_m\n", "a.csv", m); },
              {"a.csv: line 1: missing column 'east_m'"});
  expectError(
      [&] {
        importNavCsvText("time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n0,1,2,x,0,0,0\n",
                         "b.csv", m);
      },
      {"b.csv: line 2: column 'down_m': expected a finite number, found 'x'"});
  expectError(
      [&] {
        importNavCsvText(
            "time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n1,0,0,0,0,0,0\n"
            "1,0,0,0,0,0,0\n",
            "c.csv", m);
      },
      {"c.csv: line 3: column 'time_s': time goes backwards or repeats"});
  NavMapping by_index;
  setNavMapping(by_index, "columns.time", "9", "flags");
  expectError(
      [&] { importNavCsvText("time_s,north_m,east_m,down_m\n0,0,0,0\n", "d.csv", by_index); },
      {"d.csv: column index 9 is past the last column"});
  expectError([&] { importNavCsvText("", "e.csv", m); }, {"e.csv: file is empty"});
  expectError([&] { setNavMapping(m, "units.position", "yards", "flags"); },
              {"units.position: 'yards' is not one of m, ft"});
}

TEST(NavImport, MappingYamlErrorsNameTheLine) {
  test::ScratchDir dir;
  test::writeText(dir.path() / "bad.yaml", "columns:\n  time: t\nunits:\n  position: furlong\n");
  expectError([&] { readNavMapping(dir.path() / "bad.yaml"); },
              {"bad.yaml: line 4: units.position: 'furlong' is not one of m, ft"});
  test::writeText(dir.path() / "unknown.yaml", "columns:\n  time: t\n  speed: v\n");
  expectError([&] { readNavMapping(dir.path() / "unknown.yaml"); },
              {"unknown.yaml: line 3: columns.speed"});
  test::writeText(dir.path() / "notime.yaml", "columns:\n  north: n\n");
  expectError([&] { readNavMapping(dir.path() / "notime.yaml"); }, {"columns.time: missing"});
  expectError([&] { parseNavMapping("columns: [", "inline.yaml"); },
              {"inline.yaml: line 1: not valid YAML"});
}

}  // namespace
}  // namespace sonarcarve
