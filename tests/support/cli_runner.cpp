#include "support/cli_runner.h"

#include <fstream>
#include <limits>

#include <sys/wait.h>
#include <array>
#include <cstdio>

namespace sonarcarve::test {

RunResult runCli(const std::string& args) {
  return runShell(std::string("'") + SONARCARVE_CLI + "' " + args + " 2>&1");
}

RunResult runShell(const std::string& command) {
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    return result;
  }
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) {
    result.output += buffer.data();
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string quoted(const std::filesystem::path& path) {
  return "'" + path.string() + "'";
}

nlohmann::json evaluateRun(const std::filesystem::path& reference,
                           const std::filesystem::path& visible,
                           const std::filesystem::path& reconstruction) {
  const RunResult run =
      runCli("evaluate --reference " + quoted(reference) + " --visible " + quoted(visible) +
             " --reconstruction " + quoted(reconstruction) + " --json");
  const std::size_t json = run.output.find('{');
  if (run.exit_code != 0 || json == std::string::npos) {
    return {{"error", run.output}};
  }
  return nlohmann::json::parse(run.output.substr(json));
}

double evaluatedFscore(const std::filesystem::path& reference, const std::filesystem::path& visible,
                       const std::filesystem::path& reconstruction) {
  const nlohmann::json score = evaluateRun(reference, visible, reconstruction);
  return score.contains("fscore") ? score["fscore"].get<double>()
                                  : std::numeric_limits<double>::quiet_NaN();
}

bool hasChoice(const nlohmann::json& report, const std::string& name) {
  for (const auto& choice : report.at("choices")) {
    if (choice.at("name") == name) {
      return true;
    }
  }
  return false;
}

nlohmann::json readJsonFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace sonarcarve::test
