// `sonarcarve-cli bench validate --out DIR`: the validation table from scratch. Each mission of
// the set (scenes, trajectories, noise, a beam that is not as declared) is simulated and
// reconstructed with default parameters by this same program, as a user would run it, and its
// accuracy against the ground truth, its surface points and its time make one row of a
// Markdown table (docs/validation.md, "The validation set"), printed and written to
// DIR/validation.md with every row's report.json beside it.
#pragma once

#include <string>
#include <vector>

namespace sonarcarve::cli {

struct BenchValidateOptions {
  std::string out;
  int max_frames = 0;             ///< each mission's first this many frames; 0: all
  std::vector<std::string> only;  ///< mission names; empty: all
  std::string program;            ///< this program's path, to run simulate and reconstruct
};

/// The names of the missions of the set, in the table's order.
std::vector<std::string> validationMissions();

int benchValidate(const BenchValidateOptions& o);

}  // namespace sonarcarve::cli
