// End-to-end: two runs over the halves of a mission, each saving its map, merged with
// `sonarcarve-cli merge`, give the map of one run over the whole mission, byte for byte; so
// does a run over the second half that starts from the first half's map (--load-map).
#include <gtest/gtest.h>

#include "carve/map_file.h"
#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

TEST(CliMerge, TheMapsOfTwoHalvesMergeIntoTheMapOfTheWhole) {
  // The clipped beam: carving by the seed paper's rule, whose outcome does not depend on the
  // frames a run sees (beam-aware carving's keep level is measured on each run's own frames).
  test::ScratchDir dir;
  const auto mission = dir.path() / "riser";
  ASSERT_EQ(runCli("simulate --scene riser --beam clipped --noise none --max-frames 16 --out " +
                   quoted(mission))
                .exit_code,
            0);
  const auto run = [&](const std::string& name, const std::string& frames) {
    const auto r = runCli("reconstruct " + quoted(mission) + " --out " + quoted(dir.path() / name) +
                          " --mesh false --save-map " + frames);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return dir.path() / name / "map.scmap";
  };
  const auto whole = run("whole", "");
  const auto first = run("first", "--last-frame 8");
  const auto second = run("second", "--first-frame 8");
  const auto merged = dir.path() / "merged.scmap";
  const auto r =
      runCli("merge " + quoted(first) + " " + quoted(second) + " --out " + quoted(merged));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("merged 2 maps"), std::string::npos) << r.output;
  EXPECT_NE(test::readText(first), test::readText(whole));
  EXPECT_EQ(test::readText(merged), test::readText(whole));

  // A run over the second half that starts from the first half's map carves the same map.
  const auto continued = run("continued", "--first-frame 8 --load-map " + quoted(first));
  EXPECT_EQ(test::readText(continued), test::readText(whole));

  // The last step of a sharded run: the merged map's surface over every frame, without carving
  // again, is the whole run's surface.
  const auto surface =
      runCli("reconstruct " + quoted(mission) + " --out " + quoted(dir.path() / "surface") +
             " --mesh false --load-map " + quoted(merged) + " --surface-only");
  ASSERT_EQ(surface.exit_code, 0) << surface.output;
  EXPECT_EQ(test::readText(dir.path() / "surface" / "surface_points.ply"),
            test::readText(dir.path() / "whole" / "surface_points.ply"));
  const auto alone = runCli("reconstruct " + quoted(mission) + " --out " +
                            quoted(dir.path() / "alone") + " --surface-only");
  EXPECT_NE(alone.exit_code, 0);
  EXPECT_NE(alone.output.find("needs --load-map"), std::string::npos) << alone.output;

  // A broken map is refused by name, and nothing is written.
  test::writeText(dir.path() / "cut.scmap", test::readText(first).substr(0, 100));
  const auto bad = runCli("merge " + quoted(dir.path() / "cut.scmap") + " " + quoted(second) +
                          " --out " + quoted(dir.path() / "never.scmap"));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("cut.scmap: byte"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "never.scmap"));
}

}  // namespace
}  // namespace sonarcarve
