// The demo missions' outputs, byte for byte, as the commit named in tests/data/golden/README.md
// wrote them: a change that reorganises the engine (its layout, its stages, how choices are
// recorded) must leave every deliverable unchanged. A change meant to change them regenerates
// the checksums (tests/data/golden/make-golden.sh) and says why in its commit.
//
// Cases: the noisy riser (the default detector learns its noise model from the mission), and the
// noise-free jacket node, each reconstructed twice: as the CLI runs by default (finished blocks
// let go as the track leaves them) and with --save-map (the whole map kept, as the workbench
// does, then occlusion resolution over it). 30 frames each keep the suite short.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;
using test::runShell;

// "checksum  case/file" lines of the golden list, by "case/file".
std::map<std::string, std::string> goldenChecksums() {
  std::ifstream in(std::string(SONARCARVE_TEST_DATA_DIR) + "/golden/outputs.sha256");
  std::map<std::string, std::string> sums;
  std::string sum;
  std::string name;
  while (in >> sum >> name) {
    sums[name] = sum;
  }
  return sums;
}

std::string sha256(const std::filesystem::path& file) {
  const auto run = runShell("sha256sum " + quoted(file));
  std::istringstream words(run.output);
  std::string sum;
  words >> sum;
  return run.exit_code == 0 ? sum : "unreadable: " + run.output;
}

struct GoldenCase {
  const char* name;
  const char* simulate;
};

void PrintTo(const GoldenCase& c, std::ostream* out) {
  *out << c.name;
}

class GoldenOutputs : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenOutputs, DeliverablesAreUnchangedByteForByte) {
  const GoldenCase& c = GetParam();
  const auto golden = goldenChecksums();
  ASSERT_FALSE(golden.empty()) << "tests/data/golden/outputs.sha256 is missing";
  test::ScratchDir dir;
  const auto mission = dir.path() / "mission";
  const auto sim =
      runCli(std::string("simulate ") + c.simulate + " --max-frames 30 --out " + quoted(mission));
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  for (const std::string mode : {"evicting", "whole-map"}) {
    const auto out = dir.path() / mode;
    const std::string keep = mode == "whole-map" ? " --save-map" : "";
    const auto rec = runCli("reconstruct " + quoted(mission) + keep + " --out " + quoted(out));
    ASSERT_EQ(rec.exit_code, 0) << rec.output;
    std::size_t compared = 0;
    for (const auto& [name, sum] : golden) {
      const std::string prefix = std::string(c.name) + "/" + mode + "/";
      if (name.rfind(prefix, 0) != 0) {
        continue;
      }
      EXPECT_EQ(sha256(out / name.substr(prefix.size())), sum) << name << " changed";
      ++compared;
    }
    EXPECT_GE(compared, 5u) << "the golden list has too few files for " << c.name << "/" << mode;
  }
}

INSTANTIATE_TEST_SUITE_P(DemoMissions, GoldenOutputs,
                         ::testing::Values(GoldenCase{"riser-noisy", "--scene riser --seed 7"},
                                           GoldenCase{"jacket-node",
                                                      "--scene jacket-node --noise none"}),
                         [](const ::testing::TestParamInfo<GoldenCase>& param) {
                           std::string name = param.param.name;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace sonarcarve
