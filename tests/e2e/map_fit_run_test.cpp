// The model-based fit in a run (reconstruct --fit true; fit/map_fit.h): on a short noise-free
// riser pass it says what it did as a choice, explains more of the frames than the carved map
// did, and keeps a surface as close to the truth as the voxels allow.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

constexpr double kVoxel_m = 0.02;  // the default voxel size

TEST(MapFitRun, ExplainsMoreOfTheFramesAndKeepsTheSurfaceWithinTheVoxels) {
  test::ScratchDir dir;
  const auto mission = dir.path() / "riser";
  ASSERT_EQ(runCli("simulate --scene riser --noise none --max-frames 16 --out " + quoted(mission))
                .exit_code,
            0);
  const auto out = dir.path() / "fit";
  const test::RunResult run =
      runCli("reconstruct " + quoted(mission) + " --fit true --fit-passes 2 --mesh false --out " +
             quoted(out));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("map fit: on"), std::string::npos) << run.output;

  const nlohmann::json report = test::readJsonFile(out / "report.json");
  bool found = false;
  for (const auto& choice : report.at("choices")) {
    if (choice.at("name") == "map fit") {
      found = true;
      EXPECT_EQ(choice.at("value"), "on");
      EXPECT_FALSE(choice.at("warning").get<bool>());
    }
  }
  EXPECT_TRUE(found);

  const nlohmann::json score = test::evaluateRun(
      mission / "ground_truth.ply", mission / "visible_points.ply", out / "surface_points.ply");
  ASSERT_FALSE(score.contains("error")) << score.dump();
  EXPECT_GT(score.at("reconstructed_points").get<double>(), 0.0);
  // Half a voxel at the median, the 3 cm at the 90th percentile.
  EXPECT_LT(score.at("accuracy_median_m").get<double>(), 0.5 * kVoxel_m);
  EXPECT_LT(score.at("accuracy_p90_m").get<double>(), 1.5 * kVoxel_m);
}

}  // namespace
}  // namespace sonarcarve
