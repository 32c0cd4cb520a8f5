// `sonarcarve-cli reconstruct MISSION|RECORDING --out DIR`: carve, resolve occlusions, export.
// Writes DIR/surface_points.ply, DIR/mesh.ply and DIR/mesh.stl (world NED, metres), DIR/map.bt
// (fast engine), DIR/refined_nav.csv (the track as pose refinement corrected it, when on),
// DIR/params.yaml (what was used), DIR/report.json and DIR/manifest.json (the run and its
// files); a simulated mission's ground truth, when present, is evaluated too.
#include <iostream>
#include <string>
#include <vector>

#include "carve/map_file.h"
#include "carve/occupancy_export.h"
#include "cli/commands.h"
#include "cli/param_flags.h"
#include "cli/source_flags.h"
#include "cli/terminal_progress.h"
#include "common/error.h"
#include "io/atomic_file.h"
#include "io/frame_source.h"
#include "io/mission.h"
#include "io/nav_csv.h"
#include "io/output_folder.h"
#include "io/run_manifest.h"
#include "mesh/mesh_export.h"
#include "pipeline/reconstruction.h"
#include "pipeline/refined_track.h"
#include "pipeline/report.h"

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

// Every file a run can write: one of an earlier run that this run does not rewrite is removed
// when this run ends (io/run_manifest.h), so that `export` cannot take it for this run's.
const std::vector<std::string> kOutputs = {"surface_points.ply", "map.bt",      "mesh.ply",
                                           "mesh.stl",           "params.yaml", "report.json",
                                           "refined_nav.csv",    "map.scmap"};

void writeOutputs(const std::filesystem::path& out, const Mission& mission,
                  const ReconstructionParams& params, const ReconstructionResult& result,
                  const std::string& report, bool save_map, RunManifest& manifest) {
  writeSurfacePointsPly(result.surface, out / "surface_points.ply");
  manifest.wrote("surface_points.ply");
  if (result.evicted) {
    writeOccupancyBt(result.occupancy.sorted(), params.carve.voxel_size_m, out / "map.bt");
    manifest.wrote("map.bt");
  } else if (result.map) {
    writeOccupancyBt(*result.map, out / "map.bt");
    manifest.wrote("map.bt");
    if (save_map) {
      saveMap(*result.map, out / "map.scmap");
      manifest.wrote("map.scmap");
    }
  }
  if (!result.mesh.triangles.empty()) {
    ExportOptions ply;
    exportMesh(result.mesh, out / "mesh.ply", ply);
    manifest.wrote("mesh.ply");
    ExportOptions stl;
    stl.format = "stl";
    exportMesh(result.mesh, out / "mesh.stl", stl);
    manifest.wrote("mesh.stl");
  }
  if (!result.refinement.empty()) {
    writeFileAtomically(out / "refined_nav.csv",
                        navCsvText(refinedTrack(mission, result.refinement)));
    manifest.wrote("refined_nav.csv");
  }
  writeFileAtomically(out / "params.yaml", params.toYaml());
  manifest.wrote("params.yaml");
  writeFileAtomically(out / "report.json", report);
  manifest.wrote("report.json");
}

void reportRemoved(const RunManifest& manifest) {
  for (const std::filesystem::path& path : manifest.removed()) {
    std::cerr << "removed " << path.string() << " of an earlier run\n";
  }
}

int runReconstruct(const ReconstructOptions& o, ThreadPool& pool,
                   const std::vector<std::string>& arguments) {
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
    pipeline.startFrom(loadMap(o.load_map), !o.surface_only);
  }
  if (o.save_map) {
    pipeline.keepWholeMap();  // map.scmap is the whole map
  }
  const std::filesystem::path out(o.out);
  prepareOutputFolder(out);
  const OutputFolderLock lock(out);

  TerminalProgress progress;
  const ReconstructionResult result = pipeline.run(progress);
  progress.finish();
  for (const std::string& line : describeRunChoices(result, params.carve.dynamic_range_db)) {
    std::cerr << line << "\n";
  }
  if (!result.temporary_file_problem.empty()) {
    std::cerr << "warning: " << result.temporary_file_problem
              << "; what the run sets aside in temporary files was kept in memory instead\n";
  }
  for (const FrameProblem& p : result.skipped) {
    std::cerr << "skipped: " << p.message << "\n";
  }
  // The report first: it reads the ground truth, and a broken one must fail the run before any
  // file is written.
  const std::string report = reconstructionReport(mission, params, result, pool);
  RunManifest manifest(out, arguments, kOutputs);
  try {
    writeOutputs(out, mission, params, result, report, o.save_map, manifest);
  } catch (const Error& e) {
    try {
      manifest.finish("failed", e.what());
    } catch (const Error&) {
      // The manifest cannot be written either (a full disk): it still says "running".
    }
    reportRemoved(manifest);
    throw;
  }
  manifest.finish(result.cancelled ? "cancelled" : "complete");
  reportRemoved(manifest);
  std::cout << report;
  return result.cancelled ? 130 : 0;
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
  o->flags = addParamFlags(*cmd);
  addSourceFlags(*cmd, o->source);
  cmd->callback(
      [o, &pool, &arguments, &exit_code] { exit_code = runReconstruct(*o, pool, arguments); });
}

}  // namespace sonarcarve::cli
