// End-to-end: sonarcarve-cli as a user runs it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;
using test::RunResult;

TEST(CliInfo, ReportsTheExampleMissionFigures) {
  const RunResult r = runCli("info --json " + quoted(test::exampleMission()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  // The example mission (resources/example_mission/make_example_mission.py): 10 frames every
  // 0.5 s from t = 100 s; 64 beams over 60 deg; 200 bins of 2.5 cm from 1 m; nav every 0.5 s
  // from 99.75 s to 104.75 s descending 10 cm per sample from 9.95 m to 10.95 m.
  EXPECT_EQ(j["frames"]["count"], 10);
  EXPECT_DOUBLE_EQ(j["frames"]["first_time_s"], 100.0);
  EXPECT_DOUBLE_EQ(j["frames"]["duration_s"], 4.5);
  EXPECT_TRUE(j["frames"]["failed"].empty());
  EXPECT_TRUE(j["frames"]["outside_navigation"].empty());
  EXPECT_EQ(j["sonar"]["id"], "example-sonar");
  EXPECT_EQ(j["sonar"]["beams"], 64);
  EXPECT_EQ(j["sonar"]["range_bins"], 200);
  EXPECT_DOUBLE_EQ(j["sonar"]["range_resolution_m"], 0.025);
  EXPECT_DOUBLE_EQ(j["sonar"]["range_max_m"], 6.0);
  EXPECT_EQ(j["sonar"]["bearing_table"], "uniform");
  EXPECT_NEAR(j["sonar"]["bearing_min_deg"].get<double>(), -30.0 + 60.0 / 128, 1e-9);
  EXPECT_NEAR(j["sonar"]["field_of_view_deg"].get<double>(), 60.0, 1e-9);
  EXPECT_NEAR(j["sonar"]["vertical_aperture_deg"].get<double>(), 20.0, 1e-9);
  EXPECT_EQ(j["navigation"]["samples"], 11);
  EXPECT_DOUBLE_EQ(j["navigation"]["start_s"], 99.75);
  EXPECT_DOUBLE_EQ(j["navigation"]["end_s"], 104.75);
  EXPECT_NEAR(j["navigation"]["min_ned_m"][2].get<double>(), 9.95, 1e-9);
  EXPECT_NEAR(j["navigation"]["max_ned_m"][2].get<double>(), 10.95, 1e-9);
  EXPECT_NEAR(j["navigation"]["path_length_m"].get<double>(), 1.0, 1e-9);
}

TEST(CliInfo, PrintsAReadableSummary) {
  const RunResult r = runCli("info " + quoted(test::exampleMission()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("64 beams x 200 range bins"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Failed       0 frames"), std::string::npos) << r.output;
}

TEST(CliInfo, ListsFramesThatFailToLoadAndKeepsGoing) {
  test::ScratchDir dir;
  const auto mission = test::copyExampleMission(dir.path());
  test::writeText(mission / "frames" / "000003.png", "not a png");
  const RunResult r = runCli("info --json " + quoted(mission));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["frames"]["count"], 10);
  ASSERT_EQ(j["frames"]["failed"].size(), 1u);
  EXPECT_EQ(j["frames"]["failed"][0]["index"], 3);
  EXPECT_NE(j["frames"]["failed"][0]["error"].get<std::string>().find("000003.png"),
            std::string::npos);
}

TEST(CliInfo, ABrokenMissionFailsWithTheFileAndLine) {
  test::ScratchDir dir;
  const auto mission = test::copyExampleMission(dir.path());
  test::writeText(mission / "nav.csv", "time_s,north_m\n1,2\n");
  const RunResult r = runCli("info " + quoted(mission));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("nav.csv: line 1: missing column 'east_m'"), std::string::npos)
      << r.output;
  const RunResult missing = runCli("info " + quoted(dir.path() / "nowhere"));
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("nowhere"), std::string::npos) << missing.output;
}

TEST(Cli, VersionAndHelp) {
  const RunResult version = runCli("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find(std::string("sonarcarve-cli ") + SONARCARVE_VERSION),
            std::string::npos);
  const RunResult help = runCli("--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* verb :
       {"info", "simulate", "reconstruct", "evaluate", "noise-model", "import", "bench"}) {
    EXPECT_NE(help.output.find(verb), std::string::npos) << verb;
  }
  EXPECT_NE(runCli("").exit_code, 0);
  EXPECT_NE(runCli("no-such-verb").exit_code, 0);
}

}  // namespace
}  // namespace sonarcarve
