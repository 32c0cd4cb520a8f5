// The verbs of sonarcarve-cli. Each add*Command registers a CLI11 subcommand whose callback
// runs it; the exit code of the run is stored in `exit_code`.
#pragma once

#include <CLI/CLI.hpp>

namespace sonarcarve::cli {

void addInfoCommand(CLI::App& app, int& exit_code);
void addSimulateCommand(CLI::App& app, int& exit_code);
void addBenchCommand(CLI::App& app, int& exit_code);
void addFrameCommand(CLI::App& app, int& exit_code);
void addReconstructCommand(CLI::App& app, int& exit_code);
void addEvaluateCommand(CLI::App& app, int& exit_code);
void addNoiseModelCommand(CLI::App& app, int& exit_code);
void addExportCommand(CLI::App& app, int& exit_code);
void addImportCommand(CLI::App& app, int& exit_code);
void addParamsCommand(CLI::App& app, int& exit_code);

}  // namespace sonarcarve::cli
