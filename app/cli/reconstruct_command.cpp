// `sonarcarve-cli reconstruct MISSION|RECORDING --out DIR`: carve, resolve occlusions, export.
// Writes DIR/surface_points.ply, DIR/mesh.ply and DIR/mesh.stl (world NED, metres), DIR/map.bt
// (fast engine), DIR/refined_nav.csv (the track as pose refinement corrected it, when on),
// DIR/params.yaml (what was used), DIR/report.json and DIR/manifest.json (the run and its
// files); a simulated mission's ground truth, when present, is evaluated too.
#include <iostream>
#include <string>
#include <vector>

#include "carve/map_file.h"
#include "cli/commands.h"
#include "cli/output_folder_run.h"
#include "cli/param_flags.h"
#include "cli/source_flags.h"
#include "cli/terminal_progress.h"
#include "common/error.h"
#include "io/files/output_folder.h"
#include "io/frame_source.h"
#include "io/mission/mission.h"
#include "pipeline/reconstruction.h"

namespace sonarcarve::cli {
namespace {

struct ReconstructOptions {
  std::string mission;
  std::string out;
  std::string params_file;
  std::shared_ptr<ParamFlags> flags;
  SourceFlags source;
  bool save_map = false;
  std::string load_map;
  bool surface_only = false;
  bool verbose = false;
};

// The --params file (or the defaults), then the flags on top.
ReconstructionParams paramsFrom(const ReconstructOptions& o) {
  ReconstructionParams p = o.params_file.empty()
                               ? ReconstructionParams{}
                               : ReconstructionParams::fromYamlFile(o.params_file);
  applyParamFlags(*o.flags, p);
  p.validate();
  return p;
}

// Runs the pipeline into its folder, made ready and held: the outputs, choices and warnings.
int carveInto(const std::filesystem::path& out, Pipeline& pipeline, const ReconstructOptions& o,
              const std::vector<std::string>& arguments) {
  TerminalProgress progress;
  const auto announce = [&progress, verbose = o.verbose](const ReconstructionResult& result) {
    progress.finish();
    for (const RunChoice& choice : result.choices) {
      std::cerr << choiceLine(choice) << "\n";
      if (verbose) {
        std::cerr << choiceDetail(choice) << "\n";
      }
    }
    if (!result.temporary_file_problem.empty()) {
      std::cerr << "warning: " << result.temporary_file_problem
                << "; what the run sets aside in temporary files was kept in memory instead\n";
    }
    for (const FrameProblem& p : result.skipped) {
      std::cerr << "skipped: " << p.message << "\n";
    }
  };
  const auto removed = [](const std::filesystem::path& path) {
    std::cerr << "removed " << path.string() << " of an earlier run\n";
  };
  pipeline.writeOutputsTo({out, arguments, o.save_map, removed, announce});
  const ReconstructionResult result = pipeline.run(progress);
  std::cout << result.report;
  return result.cancelled ? 130 : 0;
}

int runReconstruct(const ReconstructOptions& o, ThreadPool& pool,
                   const std::vector<std::string>& arguments) {
  requireOutputFolder(o.out);  // before the mission is read
  const Mission mission = openMission(o.mission, openOptionsFrom(o.source));
  for (const std::string& warning : mission.warnings) {
    std::cerr << "warning: " << warning << "\n";
  }
  const ReconstructionParams params = paramsFrom(o);
  // The pipeline checks its parameters and reads a given noise model: a bad one fails before
  // the output folder is made.
  Pipeline pipeline(mission, params, pool);
  if (o.surface_only && o.load_map.empty()) {
    throw Error("--surface-only", "", "needs --load-map: the map whose surface to resolve");
  }
  if (!o.load_map.empty()) {
    pipeline.startFrom(loadMap(o.load_map), !o.surface_only, o.load_map);
  }
  if (o.save_map) {
    pipeline.keepWholeMap();  // map.scmap is the whole map
  }
  const std::filesystem::path out(o.out);
  return runIntoOutputFolder(out, PartialOutput::Kept, [&] {
    const OutputFolderLock lock(out);
    return carveInto(out, pipeline, o, arguments);
  });
}

}  // namespace

void addReconstructCommand(CLI::App& app, ThreadPool& pool,
                           const std::vector<std::string>& arguments, int& exit_code) {
  auto* cmd = app.add_subcommand("reconstruct", "Carve a 3D map from a mission and export it");
  auto o = std::make_shared<ReconstructOptions>();
  cmd->add_option("mission", o->mission,
                  "Mission folder, or a recording read in place (an Oculus log: give --nav)")
      ->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_option("--params", o->params_file,
                  "Parameters YAML (as saved by the GUI or params.yaml)");
  cmd->add_flag("--save-map", o->save_map,
                "Also write DIR/map.scmap, the carved map itself (docs/formats.md), for `merge`");
  cmd->add_option("--load-map", o->load_map,
                  "Start from a map carved before (map.scmap of --save-map, or of merge): this "
                  "run's frames carve into it (fast engine)");
  cmd->add_flag("--surface-only", o->surface_only,
                "With --load-map: the frames do not carve, they only resolve the loaded map's "
                "surface (the last step of a sharded run, docs/scaling.md)");
  cmd->add_flag("--verbose", o->verbose,
                "Under each automatic choice of the run, how it was derived and what to do");
  o->flags = addParamFlags(*cmd);
  addSourceFlags(*cmd, o->source);
  cmd->callback(
      [o, &pool, &arguments, &exit_code] { exit_code = runReconstruct(*o, pool, arguments); });
}

}  // namespace sonarcarve::cli
