// `sonarcarve-cli reconstruct MISSION --out DIR`: carve, resolve occlusions, export.
// Writes DIR/surface_points.ply, DIR/mesh.ply and DIR/mesh.stl (world NED, metres), DIR/map.bt
// (fast engine), DIR/params.yaml (what was used) and DIR/report.json; a simulated mission's
// ground truth, when present, is evaluated too.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "carve/occupancy_export.h"
#include "cli/commands.h"
#include "cli/param_flags.h"
#include "cli/terminal_progress.h"
#include "common/error.h"
#include "eval/evaluator.h"
#include "io/atomic_file.h"
#include "io/mission.h"
#include "mesh/mesh_export.h"
#include "pipeline/reconstruction.h"
#include "sim/scene_io.h"

namespace sonarcarve::cli {
namespace {

struct ReconstructOptions {
  std::string mission;
  std::string out;
  std::string params_file;
  std::shared_ptr<ParamFlags> flags;
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

int runReconstruct(const ReconstructOptions& o) {
  const Mission mission = readMission(o.mission);
  const ReconstructionParams params = paramsFrom(o);
  const std::filesystem::path out(o.out);
  std::filesystem::create_directories(out);

  TerminalProgress progress;
  const ReconstructionResult result = reconstruct(mission, params, progress);
  progress.finish();
  for (const FrameProblem& p : result.skipped) {
    std::cerr << "skipped: " << p.message << "\n";
  }
  writeSurfacePointsPly(result.surface, out / "surface_points.ply");
  if (result.map) {
    writeOccupancyBt(*result.map, out / "map.bt");
  }
  if (!result.mesh.triangles.empty()) {
    ExportOptions ply;
    exportMesh(result.mesh, out / "mesh.ply", ply);
    ExportOptions stl;
    stl.format = "stl";
    exportMesh(result.mesh, out / "mesh.stl", stl);
  }
  writeFileAtomically(out / "params.yaml", params.toYaml());

  nlohmann::json report = {{"mission", mission.folder.string()},
                           {"engine", toString(params.engine)},
                           {"detector", toString(params.resolvedDetectorMode())},
                           {"smoothing", params.detector.smoothing},
                           {"z", params.detector.z},
                           {"frames_used", result.frames_used},
                           {"frames_skipped", result.skipped.size()},
                           {"cancelled", result.cancelled},
                           {"occupied_voxels", result.occupied_voxels},
                           {"surface_points", result.surface.size()},
                           {"mesh_vertices", result.mesh.vertices.size()},
                           {"mesh_triangles", result.mesh.triangles.size()},
                           {"map_megabytes", static_cast<double>(result.map_bytes) / 1e6},
                           {"carve_ms_per_frame_median", result.carve_ms_median},
                           {"occlusion_ms_per_frame", result.occlusion_ms_per_frame},
                           {"total_s", result.total_s}};
  const auto truth = mission.folder / "ground_truth.ply";
  if (std::filesystem::exists(truth) && !result.surface.empty()) {
    const std::vector<Eigen::Vector3f> points = positionsOf(result.surface);
    // Ground truth read once, for the points and for the mesh.
    const Scene truth_mesh = loadSceneMesh(truth);
    const auto visible_file = mission.folder / "visible_points.ply";
    const std::vector<Eigen::Vector3f> visible = std::filesystem::exists(visible_file)
                                                     ? readPointsPly(visible_file)
                                                     : std::vector<Eigen::Vector3f>{};
    report["evaluation"] = nlohmann::json::parse(evaluate(points, truth_mesh, visible).toJson());
    if (!result.mesh.vertices.empty()) {
      // Mesh accuracy: distance from the mesh vertices to the ground truth.
      report["mesh_evaluation"] =
          nlohmann::json::parse(evaluate(result.mesh.vertices, truth_mesh, visible).toJson());
    }
  }
  writeFileAtomically(out / "report.json", report.dump(2) + "\n");
  std::cout << report.dump(2) << "\n";
  return result.cancelled ? 130 : 0;
}

}  // namespace

void addReconstructCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("reconstruct", "Carve a 3D map from a mission and export it");
  auto o = std::make_shared<ReconstructOptions>();
  cmd->add_option("mission", o->mission, "Mission folder")->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_option("--params", o->params_file,
                  "Parameters YAML (as saved by the GUI or params.yaml)");
  o->flags = addParamFlags(*cmd);
  cmd->callback([o, &exit_code] { exit_code = runReconstruct(*o); });
}

}  // namespace sonarcarve::cli
