// End-to-end: `sonarcarve-cli import` and `info` on vendor logs, as a user runs them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/angles.h"
#include "io/mission/mission.h"
#include "sonar/attitude.h"
#include "support/cli_runner.h"
#include "support/oculus_encoder.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;
using test::RunResult;

nlohmann::json infoJson(const std::filesystem::path& path) {
  const RunResult r = runCli("info --json " + quoted(path));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(r.output);
}

TEST(CliImport, InfoOnTheFixtureReportsItsGeometry) {
  const auto j = infoJson(test::oculusFixture());
  EXPECT_EQ(j["sonar"]["beams"], 256);
  EXPECT_EQ(j["sonar"]["range_bins"], 703);
  EXPECT_NEAR(j["sonar"]["range_resolution_m"].get<double>() * 1000.0, 2.842, 5e-4);
  EXPECT_NEAR(j["sonar"]["bearing_min_deg"].get<double>(), -30.0, 1e-9);
  EXPECT_NEAR(j["sonar"]["bearing_max_deg"].get<double>(), 30.0, 1e-9);
  EXPECT_EQ(j["sonar"]["bearing_table"], "explicit");
  EXPECT_EQ(j["frames"]["count"], 1);
  EXPECT_NEAR(j["log"]["frequency_hz"].get<double>(), 2098880.6, 0.05);
  EXPECT_NEAR(j["log"]["speed_of_sound_mps"].get<double>(), 1490.66, 0.005);
  EXPECT_TRUE(j["log"]["problems"].empty());
  const RunResult text = runCli("info " + quoted(test::oculusFixture()));
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("256 beams x 703 range bins"), std::string::npos) << text.output;
}

TEST(CliImport, ImportedMissionAgreesWithTheLog) {
  test::ScratchDir dir;
  const auto mission = dir.path() / "mission";
  const RunResult r = runCli("import --format oculus " + quoted(test::oculusFixture()) + " --out " +
                             quoted(mission));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("imported 1 frames"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stationary"), std::string::npos) << r.output;
  const auto from_log = infoJson(test::oculusFixture());
  const auto from_mission = infoJson(mission);
  EXPECT_EQ(from_mission["sonar"], from_log["sonar"]);
  EXPECT_EQ(from_mission["frames"], from_log["frames"]);
  EXPECT_EQ(from_mission["navigation"], from_log["navigation"]);
  // The image is stored exactly, in the sonar's own counts: bytes of gamma 0.5 (the fire
  // message's gammaCorrection 127), which a frame loads as the sonar's linear scale.
  const Mission m = readMission(mission);
  EXPECT_EQ(m.sonar.intensityScale(), IntensityScale::gamma(0.498, 255.0));
  const Frame frame = loadFrame(m, 0);
  EXPECT_NEAR(cv::mean(m.sonar.intensityScale().powerToCounts(frame.image))[0], 55.857, 1e-3);
}

TEST(CliImport, NavigationMappingMountingAndTimeOffset) {
  test::ScratchDir dir;
  // Two pings (version 2: times in seconds since power-up), at 10 s and 10.5 s.
  std::vector<std::vector<std::uint8_t>> parts;
  for (double t : {10.0, 10.5}) {
    test::OculusPingSpec spec;
    spec.version = 2;
    spec.ping_start_time = t;
    parts.push_back(test::encodeOculusPing(spec));
  }
  test::writeBytes((dir.path() / "two.raw").string(), test::concat(parts));
  test::writeText(dir.path() / "nav.csv",
                  "epoch_ms;northing_ft;easting_ft;depth_ft;heading\n"
                  "1000000;0;0;10;90\n"
                  "1001000;10;0;10;90\n");
  test::writeText(dir.path() / "map.yaml",
                  "delimiter: ';'\n"
                  "columns: {time: epoch_ms, north: northing_ft, east: easting_ft, "
                  "depth: depth_ft, heading: heading}\n"
                  "units: {time: ms, position: ft}\n");
  test::writeText(dir.path() / "mount.yaml",
                  "mounting:\n  translation_m: [0.5, 0, 0.2]\n  roll_pitch_yaw_deg: [0, 20, 0]\n");
  const auto out = dir.path() / "mission";
  // Sonar clock 10 s = navigation clock 1000.2 s.
  const RunResult r = runCli("import --format oculus " + quoted(dir.path() / "two.raw") +
                             " --out " + quoted(out) + " --nav " + quoted(dir.path() / "nav.csv") +
                             " --nav-map " + quoted(dir.path() / "map.yaml") + " --mounting " +
                             quoted(dir.path() / "mount.yaml") + " --time-offset 990.2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Mission m = readMission(out);
  ASSERT_EQ(m.frames.size(), 2u);
  EXPECT_NEAR(m.frames[0].time_s, 1000.2, 1e-9);
  EXPECT_NEAR(m.frames[1].time_s, 1000.7, 1e-9);
  ASSERT_EQ(m.nav.samples().size(), 2u);
  EXPECT_NEAR(m.nav.samples()[1].position_m.x(), 3.048, 1e-9);
  EXPECT_NEAR(m.nav.samples()[1].position_m.z(), 3.048, 1e-9);
  EXPECT_NEAR(radToDeg(rollPitchYawFromQuaternion(m.nav.samples()[0].q_world_vehicle).yaw_rad),
              90.0, 1e-9);
  EXPECT_NEAR(m.mounting.translation_m.x(), 0.5, 1e-12);
  EXPECT_NEAR(radToDeg(m.mounting.rpy.pitch_rad), 20.0, 1e-9);
  // The same with the mapping on the command line, and frames outside the navigation.
  const RunResult flags = runCli(
      "import " + quoted(dir.path() / "two.raw") + " --out " + quoted(dir.path() / "m2") +
      " --nav " + quoted(dir.path() / "nav.csv") +
      " --nav-column time=epoch_ms --nav-column north=northing_ft --nav-column east=easting_ft"
      " --nav-column depth=depth_ft --nav-column heading=heading --nav-column roll=-1"
      " --nav-set delimiter=';' --nav-set units.time=ms --nav-set units.position=ft");
  EXPECT_NE(flags.exit_code, 0) << flags.output;  // roll=-1 is not a column name
  const RunResult outside = runCli(
      "import " + quoted(dir.path() / "two.raw") + " --out " + quoted(dir.path() / "m3") +
      " --nav " + quoted(dir.path() / "nav.csv") + " --nav-map " + quoted(dir.path() / "map.yaml"));
  ASSERT_EQ(outside.exit_code, 0) << outside.output;
  EXPECT_NE(outside.output.find("2 frames lie outside the navigation"), std::string::npos)
      << outside.output;
}

TEST(CliImport, BrokenInputsFailWithFileAndPlace) {
  test::ScratchDir dir;
  const auto whole = test::readBytes(test::oculusFixture().string());
  test::writeBytes((dir.path() / "cut.raw").string(),
                   std::vector<std::uint8_t>(whole.begin(), whole.begin() + 1000));
  const RunResult cut = runCli("import --format oculus " + quoted(dir.path() / "cut.raw") +
                               " --out " + quoted(dir.path() / "m"));
  EXPECT_EQ(cut.exit_code, 1);
  EXPECT_NE(cut.output.find("cut.raw: byte 10: truncated message"), std::string::npos)
      << cut.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "m"));
  const RunResult info = runCli("info " + quoted(dir.path() / "cut.raw"));
  EXPECT_EQ(info.exit_code, 1);
  EXPECT_NE(info.output.find("cut.raw: byte 10"), std::string::npos) << info.output;
  test::writeText(dir.path() / "empty.raw", "");
  const RunResult empty =
      runCli("import " + quoted(dir.path() / "empty.raw") + " --out " + quoted(dir.path() / "m"));
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_NE(empty.output.find("empty.raw: byte 0: empty file"), std::string::npos) << empty.output;
  test::writeText(dir.path() / "bad_nav.csv", "time_s,north_m\n0,0\n");
  const RunResult nav =
      runCli("import " + quoted(test::oculusFixture()) + " --out " + quoted(dir.path() / "m") +
             " --nav " + quoted(dir.path() / "bad_nav.csv"));
  EXPECT_EQ(nav.exit_code, 1);
  EXPECT_NE(nav.output.find("bad_nav.csv: line 1: missing column 'east_m'"), std::string::npos)
      << nav.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "m"));
  const RunResult format = runCli("import --format xtf " + quoted(test::oculusFixture()) +
                                  " --out " + quoted(dir.path() / "m"));
  EXPECT_NE(format.exit_code, 0);
  EXPECT_NE(format.output.find("unknown format 'xtf'"), std::string::npos) << format.output;
}

}  // namespace
}  // namespace sonarcarve
