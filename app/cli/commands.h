// The verbs of sonarcarve-cli. Each add*Command registers a CLI11 subcommand whose callback
// runs it; the exit code of the run is stored in `exit_code`. Verbs that compute in parallel
// run on `pool`, the program's one thread pool, which outlives the parse.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "common/thread_pool.h"

namespace sonarcarve::cli {

void addInfoCommand(CLI::App& app, int& exit_code);
void addSimulateCommand(CLI::App& app, ThreadPool& pool, int& exit_code);
void addBenchCommand(CLI::App& app, ThreadPool& pool, int& exit_code);
void addFrameCommand(CLI::App& app, int& exit_code);
/// `arguments`: the command line, recorded in the run's manifest.
void addReconstructCommand(CLI::App& app, ThreadPool& pool,
                           const std::vector<std::string>& arguments, int& exit_code);
void addEvaluateCommand(CLI::App& app, ThreadPool& pool, int& exit_code);
void addNoiseModelCommand(CLI::App& app, int& exit_code);
void addExportCommand(CLI::App& app, int& exit_code);
void addImportCommand(CLI::App& app, int& exit_code);
void addParamsCommand(CLI::App& app, int& exit_code);
void addNavErrorCommand(CLI::App& app, int& exit_code);
void addMergeCommand(CLI::App& app, int& exit_code);

}  // namespace sonarcarve::cli
