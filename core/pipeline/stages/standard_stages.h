// The pipeline's stages, each in a file of its own here (pipeline/stage.h), in the order a
// run takes them: read -> denoise -> beam check -> choose -> seabed relief -> carve -> surface ->
// mesh, then, for a run that writes its outputs to a folder, report -> export.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/stage.h"

namespace sonarcarve {

struct ReconstructionResult;

std::unique_ptr<Stage> makeReadStage();
std::unique_ptr<Stage> makeDenoiseStage();
std::unique_ptr<Stage> makeBeamCheckStage();
std::unique_ptr<Stage> makeChooseStage();
/// seabed relief: the seabed's heightfield fitted to the frames, for carving (before carve).
std::unique_ptr<Stage> makeSeabedReliefStage();
std::unique_ptr<Stage> makeCarveStage();
std::unique_ptr<Stage> makeSectorStage();
std::unique_ptr<Stage> makeSurfaceStage();
std::unique_ptr<Stage> makeMeshStage();
/// fit: only in runs with fit.enabled, after surface (Pipeline adds it).
std::unique_ptr<Stage> makeFitStage();

/// Where and how a run writes its outputs (reconstruct --out).
struct OutputSettings {
  std::filesystem::path folder;        ///< made ready and locked by the caller
  std::vector<std::string> arguments;  ///< the command line, for the run manifest
  bool save_map = false;               ///< also map.scmap, the whole carved map
  /// Told of each file of an earlier run that this run removed (io/run/run_manifest.h).
  std::function<void(const std::filesystem::path&)> removed;
  /// Told of the run's result before its report and outputs are written (the CLI prints its
  /// choices and warnings then, so that they show even when writing fails).
  std::function<void(const ReconstructionResult&)> announce;
  /// Only report.json and report.html (and the manifest): the workbench's runs, whose
  /// deliverables the analyst exports when wanted.
  bool report_only = false;
};

/// Every file a run can write: one of an earlier run that this run does not rewrite is
/// removed when this run ends, so that `export` cannot take it for this run's.
const std::vector<std::string>& runOutputFiles();

/// report.json's text, from the run and its mission's ground truth when there is one; first,
/// so that a broken ground truth fails the run before any file is written.
std::unique_ptr<Stage> makeReportStage(
    std::function<void(const ReconstructionResult&)> announce = {});
/// Writes the outputs and the run manifest into `settings.folder`.
std::unique_ptr<Stage> makeExportStage(OutputSettings settings);

/// read, denoise, beam check, choose, carve, surface, mesh.
std::vector<std::shared_ptr<const Stage>> standardStages();

}  // namespace sonarcarve
