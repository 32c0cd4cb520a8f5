// sonarcarve-cli: the headless tool. Every verb drives the same core as the GUI.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "common/error.h"

int main(int argc, char** argv) {
  CLI::App app{"SonarCarve: 3D maps of underwater structures from 2D imaging sonar",
               "sonarcarve-cli"};
  app.set_version_flag("--version", std::string("sonarcarve-cli ") + SONARCARVE_VERSION);
  app.require_subcommand(1);
  int exit_code = 0;
  sonarcarve::ThreadPool pool;  // sized to the machine; the verbs that compute in parallel share it
  sonarcarve::cli::addInfoCommand(app, exit_code);
  sonarcarve::cli::addFrameCommand(app, exit_code);
  sonarcarve::cli::addSimulateCommand(app, pool, exit_code);
  const std::vector<std::string> arguments(argv, argv + argc);
  sonarcarve::cli::addReconstructCommand(app, pool, arguments, exit_code);
  sonarcarve::cli::addParamsCommand(app, exit_code);
  sonarcarve::cli::addEvaluateCommand(app, pool, exit_code);
  sonarcarve::cli::addExportCommand(app, exit_code);
  sonarcarve::cli::addNoiseModelCommand(app, exit_code);
  sonarcarve::cli::addNavErrorCommand(app, exit_code);
  sonarcarve::cli::addMergeCommand(app, exit_code);
  sonarcarve::cli::addImportCommand(app, exit_code);
  sonarcarve::cli::addBenchCommand(app, pool, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const sonarcarve::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    // Every known failure is a sonarcarve::Error naming its input; this is a bug, but it still
    // ends with a message and an exit code rather than an abort.
    std::cerr << "error: unexpected failure (please report): " << e.what() << "\n";
    return 70;
  }
  return exit_code;
}
