// End-to-end: the parameter flags of `reconstruct` and the `params` verb, as a user runs them.
#include <gtest/gtest.h>

#include "common/angles.h"
#include "pipeline/param_schema.h"
#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;
using test::RunResult;

TEST(CliParams, FlagsOverrideTheParamsFile) {
  test::ScratchDir dir;
  const auto file = dir.path() / "p.yaml";
  test::writeText(
      file, "voxel_size_m: 0.05\nmin_views: 3\nframes: {stride: 1}\nmesh: {enabled: false}\n");
  const auto out = dir.path() / "out";
  const RunResult r =
      runCli("reconstruct " + quoted(test::exampleMission()) + " --out " + quoted(out) +
             " --params " + quoted(file) + " --voxel-size 0.04 --stride 2 --elevation-step 0.5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // params.yaml holds what was used: the flags over the file, the file over the defaults.
  const ReconstructionParams used =
      ReconstructionParams::fromYamlFile((out / "params.yaml").string());
  EXPECT_EQ(used.carve.voxel_size_m, 0.04);
  EXPECT_EQ(used.stride, 2u);
  EXPECT_EQ(used.carve.elevation_step_rad, degToRad(0.5));
  EXPECT_EQ(used.min_views, 3u);
  EXPECT_FALSE(used.mesh_enabled);
  EXPECT_EQ(used.detector.z, DetectorParams{}.z);
}

TEST(CliParams, ABadFlagValueNamesTheFlag) {
  test::ScratchDir dir;
  const std::string run =
      "reconstruct " + quoted(test::exampleMission()) + " --out " + quoted(dir.path() / "out");
  const auto expectRefused = [&](const std::string& flags, const std::string& message) {
    const RunResult r = runCli(run + " " + flags);
    EXPECT_EQ(r.exit_code, 1) << flags;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out")) << flags;
  };
  expectRefused("--voxel-size -0.1",
                "--voxel-size: expected a number, above 0 and at most 10, got -0.1");
  // The schema's range, as the panel and a params YAML have it: 1e8 smoothing passes ran past
  // 60 s and took 2.4 GB.
  expectRefused("--mesh-smoothing 100000000",
                "--mesh-smoothing: expected a whole number, from 0 to 1000, got 100000000");
  expectRefused("--detector zscore",
                "--detector: expected auto, none, ztest or cfar, got 'zscore'");
}

TEST(CliParams, PrintsTheDefaultsAndTheTable) {
  const RunResult yaml = runCli("params --yaml");
  ASSERT_EQ(yaml.exit_code, 0) << yaml.output;
  EXPECT_EQ(yaml.output, ReconstructionParams{}.toYaml());
  const RunResult table = runCli("params --markdown");
  ASSERT_EQ(table.exit_code, 0) << table.output;
  for (const ParamSpec& spec : paramSchema()) {
    EXPECT_NE(
        table.output.find("| `" + std::string(spec.key) + "` | `" + std::string(spec.flag) + "` |"),
        std::string::npos)
        << spec.key;
  }
}

}  // namespace
}  // namespace sonarcarve
