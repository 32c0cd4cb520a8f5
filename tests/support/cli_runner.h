// Running sonarcarve-cli from a test, as a user would from a shell.
#pragma once

#include <filesystem>
#include <string>

namespace sonarcarve::test {

struct RunResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs `sonarcarve-cli ARGS` (arguments as a shell would split them).
RunResult runCli(const std::string& args);
/// A path quoted for the shell.
std::string quoted(const std::filesystem::path& path);

}  // namespace sonarcarve::test
