#include "support/cli_runner.h"

#include <fstream>

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

nlohmann::json readJsonFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace sonarcarve::test
