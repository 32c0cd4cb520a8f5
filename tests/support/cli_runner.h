// Running sonarcarve-cli from a test, as a user would from a shell.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace sonarcarve::test {

struct RunResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs `sonarcarve-cli ARGS` (arguments as a shell would split them).
RunResult runCli(const std::string& args);
/// Runs a shell command line, capturing what it prints; `command` redirects stderr if needed.
RunResult runShell(const std::string& command);
/// A JSON file a run wrote (report.json, manifest.json), parsed.
nlohmann::json readJsonFile(const std::filesystem::path& path);
/// Whether a report.json's `choices` hold one named `name`.
bool hasChoice(const nlohmann::json& report, const std::string& name);
/// The scores of `evaluate --json` for a reconstruction's points against a reference mesh and
/// its visible points; {"error": what evaluate printed} if it failed.
nlohmann::json evaluateRun(const std::filesystem::path& reference,
                           const std::filesystem::path& visible,
                           const std::filesystem::path& reconstruction);
/// Its F-score; NaN (which fails every comparison) if evaluate failed.
double evaluatedFscore(const std::filesystem::path& reference, const std::filesystem::path& visible,
                       const std::filesystem::path& reconstruction);
/// A path quoted for the shell.
std::string quoted(const std::filesystem::path& path);

}  // namespace sonarcarve::test
