// The demo missions' outputs, byte for byte, as the commit named in tests/data/golden/README.md
// wrote them: a change that reorganises the engine (its layout, its stages, how choices are
// recorded) must leave every deliverable unchanged. A change meant to change them regenerates
// the checksums (tests/data/golden/make-golden.sh) and says why in its commit.
//
// The missions and runs are make-golden.sh's own, so the test and the list cannot drift apart:
// the noisy riser (the default detector learns its noise model from the mission), and the
// noise-free jacket node, each reconstructed twice: as the CLI runs by default (finished blocks
// let go as the track leaves them) and with --save-map (the whole map kept, as the workbench
// does, then occlusion resolution over it). 30 frames each keep the suite short.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "support/cli_runner.h"

namespace sonarcarve {
namespace {

// "checksum  case/mode/file" lines (sha256sum's), by "case/mode/file".
std::map<std::string, std::string> checksums(std::istream& lines) {
  std::map<std::string, std::string> sums;
  std::string sum;
  std::string name;
  while (lines >> sum >> name) {
    sums[name] = sum;
  }
  return sums;
}

TEST(GoldenOutputs, DeliverablesAreUnchangedByteForByte) {
  const std::string golden_dir = std::string(SONARCARVE_TEST_DATA_DIR) + "/golden";
  std::ifstream golden_file(golden_dir + "/outputs.sha256");
  const auto golden = checksums(golden_file);
  ASSERT_EQ(golden.size(), 22u) << "tests/data/golden/outputs.sha256 is missing or incomplete";
  const auto run = test::runShell(test::quoted(golden_dir + "/make-golden.sh") + " " +
                                  test::quoted(SONARCARVE_CLI));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::istringstream output(run.output);
  const auto now = checksums(output);
  for (const auto& [name, sum] : golden) {
    const auto it = now.find(name);
    ASSERT_NE(it, now.end()) << name << " was not written\n" << run.output;
    EXPECT_EQ(it->second, sum) << name << " changed";
  }
  EXPECT_EQ(now.size(), golden.size()) << "the runs wrote other files than the list's\n"
                                       << run.output;
}

}  // namespace
}  // namespace sonarcarve
