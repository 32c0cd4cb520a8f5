// End-to-end: recordings read in place. `reconstruct LOG --nav NAV.csv` on an Oculus log must
// give exactly what importing the log into a mission folder and reconstructing that gives:
// the frame source seam reads the same frames, times and geometry as the importer.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/oculus_encoder.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;
using test::RunResult;

nlohmann::json reportOf(const std::filesystem::path& out) {
  std::ifstream in(out / "report.json");
  return nlohmann::json::parse(in);
}

TEST(CliRecording, ReconstructsAnOculusLogInPlaceAsIfImported) {
  const test::ScratchDir dir;
  // The fixture's ping, 5 m deep, pitched 30 degrees down at a seabed, held for a long time
  // around the ping's time (52 minutes after the sonar's power-up).
  const auto nav = dir.path() / "nav.csv";
  std::ofstream(nav) << "time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n"
                     << "0,0,0,5,0,-30,0\n"
                     << "100000,0,0,5,0,-30,0\n";
  const std::string common = " --min-views 1 --detector none";
  const RunResult imported =
      runCli("import --format oculus " + quoted(test::oculusFixture()) + " --nav " + quoted(nav) +
             " --out " + quoted(dir.path() / "mission"));
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  const RunResult via_mission = runCli("reconstruct " + quoted(dir.path() / "mission") + " --out " +
                                       quoted(dir.path() / "a") + common);
  ASSERT_EQ(via_mission.exit_code, 0) << via_mission.output;
  const RunResult in_place = runCli("reconstruct " + quoted(test::oculusFixture()) + " --nav " +
                                    quoted(nav) + " --out " + quoted(dir.path() / "b") + common);
  ASSERT_EQ(in_place.exit_code, 0) << in_place.output;

  const auto a = reportOf(dir.path() / "a");
  const auto b = reportOf(dir.path() / "b");
  EXPECT_EQ(b["source"], "oculus messages");
  EXPECT_EQ(a["source"], "mission folder");
  EXPECT_EQ(b["frames_used"], 1);
  EXPECT_GT(b["occupied_voxels"].get<int>(), 1000);
  EXPECT_EQ(a["occupied_voxels"], b["occupied_voxels"]);
  EXPECT_EQ(a["surface_points"], b["surface_points"]);
  EXPECT_EQ(test::readBytes((dir.path() / "a" / "surface_points.ply").string()),
            test::readBytes((dir.path() / "b" / "surface_points.ply").string()));
}

TEST(CliRecording, AnOculusLogWithoutNavigationSaysItIsStationary) {
  const test::ScratchDir dir;
  const RunResult r = runCli("reconstruct " + quoted(test::oculusFixture()) + " --out " +
                             quoted(dir.path() / "out") + " --min-views 1 --detector none");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("stationary"), std::string::npos) << r.output;
}

TEST(CliRecording, AFileNoReaderKnowsIsAClearError) {
  const test::ScratchDir dir;
  const auto junk = dir.path() / "junk.bin";
  std::ofstream(junk) << "nothing a sonar wrote";
  const RunResult r = runCli("reconstruct " + quoted(junk) + " --out " + quoted(dir.path() / "o"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("junk.bin"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not a recording this build reads"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("oculus"), std::string::npos) << r.output;
}

TEST(CliRecording, FrameAndInfoOpenAnOculusLogWithNavigation) {
  const test::ScratchDir dir;
  const auto nav = dir.path() / "nav.csv";
  std::ofstream(nav) << "time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n"
                     << "0,0,0,5,0,-30,0\n100000,10,0,5,0,-30,0\n";
  const RunResult info =
      runCli("info --json " + quoted(test::oculusFixture()) + " --nav " + quoted(nav));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const auto j = nlohmann::json::parse(info.output);
  EXPECT_EQ(j["source"], "oculus messages");
  EXPECT_EQ(j["navigation"]["samples"], 2);
  EXPECT_TRUE(j["frames"]["outside_navigation"].empty());
  const RunResult frame = runCli("frame " + quoted(test::oculusFixture()) + " --nav " +
                                 quoted(nav) + " --polar " + quoted(dir.path() / "p.png"));
  ASSERT_EQ(frame.exit_code, 0) << frame.output;
  EXPECT_TRUE(std::filesystem::file_size(dir.path() / "p.png") > 1000);
}

}  // namespace
}  // namespace sonarcarve
