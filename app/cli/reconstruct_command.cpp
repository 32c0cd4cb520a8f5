// `sonarcarve-cli reconstruct MISSION|RECORDING --out DIR`: carve, resolve occlusions, export.
// Writes DIR/surface_points.ply, DIR/mesh.ply and DIR/mesh.stl (world NED, metres), DIR/map.bt
// (fast engine), DIR/params.yaml (what was used) and DIR/report.json; a simulated mission's
// ground truth, when present, is evaluated too.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "carve/occupancy_export.h"
#include "cli/commands.h"
#include "cli/source_flags.h"
#include "cli/terminal_progress.h"
#include "common/angles.h"
#include "common/error.h"
#include "io/atomic_file.h"
#include "io/frame_source.h"
#include "io/mission.h"
#include "mesh/mesh_export.h"
#include "pipeline/reconstruction.h"
#include "pipeline/report.h"

namespace sonarcarve::cli {
namespace {

struct ReconstructOptions {
  std::string mission;
  std::string out;
  std::string params_file;
  std::string engine;
  double voxel_size_m = -1.0;
  double threshold = -1.0;
  double elevation_step_deg = -1.0;
  int stride = -1;
  int min_views = -1;
  std::string noise_model;
  std::string detector;
  double z = -1.0;
  double cfar_pfa = -1.0;
  int smoothing = -1;
  std::vector<double> region;
  SourceFlags source;
};

ReconstructionParams paramsFrom(const ReconstructOptions& o) {
  ReconstructionParams p = o.params_file.empty()
                               ? ReconstructionParams{}
                               : ReconstructionParams::fromYamlFile(o.params_file);
  if (!o.engine.empty()) {
    p.engine = o.engine;
  }
  if (o.voxel_size_m > 0.0) {
    p.carve.voxel_size_m = o.voxel_size_m;
  }
  if (o.threshold >= 0.0) {
    p.carve.intensity_threshold = o.threshold;
  }
  if (o.elevation_step_deg > 0.0) {
    p.carve.elevation_step_rad = degToRad(o.elevation_step_deg);
  }
  if (!o.noise_model.empty()) {
    p.noise_model = o.noise_model;
  }
  if (!o.detector.empty()) {
    p.detector.mode = o.detector;
  }
  if (o.z > 0.0) {
    p.detector.z = o.z;
  }
  if (o.smoothing > 0) {
    p.detector.smoothing = o.smoothing;
  }
  if (o.cfar_pfa > 0.0) {
    p.detector.cfar_pfa = o.cfar_pfa;
  }
  if (o.min_views > 0) {
    p.min_views = static_cast<std::uint32_t>(o.min_views);
  }
  if (o.stride > 0) {
    p.stride = static_cast<std::size_t>(o.stride);
  }
  if (!o.region.empty()) {
    p.carve.region = Eigen::AlignedBox3d(Eigen::Vector3d(o.region[0], o.region[1], o.region[2]),
                                         Eigen::Vector3d(o.region[3], o.region[4], o.region[5]));
  }
  p.validate();
  return p;
}

int runReconstruct(const ReconstructOptions& o, ThreadPool& pool) {
  const Mission mission = openMission(o.mission, openOptionsFrom(o.source));
  for (const std::string& warning : mission.warnings) {
    std::cerr << "warning: " << warning << "\n";
  }
  const ReconstructionParams params = paramsFrom(o);
  const std::filesystem::path out(o.out);
  std::filesystem::create_directories(out);

  TerminalProgress progress;
  const ReconstructionResult result = Pipeline(mission, params, pool).run(progress);
  progress.finish();
  std::cerr << "denoising: " << result.detector << ", " << result.denoising << "\n";
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
  const std::string report = reconstructionReport(mission, params, result, pool);
  writeFileAtomically(out / "report.json", report);
  std::cout << report;
  return result.cancelled ? 130 : 0;
}

}  // namespace

void addReconstructCommand(CLI::App& app, ThreadPool& pool, int& exit_code) {
  auto* cmd = app.add_subcommand("reconstruct", "Carve a 3D map from a mission and export it");
  auto o = std::make_shared<ReconstructOptions>();
  cmd->add_option("mission", o->mission,
                  "Mission folder, or a recording read in place (an Oculus log: give --nav)")
      ->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_option("--params", o->params_file,
                  "Parameters YAML (as saved by the GUI or params.yaml)");
  cmd->add_option("--engine", o->engine, "fast | reference (the paper's arcs, slow)");
  cmd->add_option("--voxel-size", o->voxel_size_m, "Voxel size, m (default 0.02)");
  cmd->add_option("--threshold", o->threshold,
                  "Intensity at or below which a pixel is empty water");
  cmd->add_option("--elevation-step", o->elevation_step_deg, "Elevation step, deg (default 0.2)");
  cmd->add_option("--stride", o->stride, "Use every n-th frame");
  cmd->add_option("--noise-model", o->noise_model,
                  "Noise model (sonarcarve-cli noise-model --smoothing 3)");
  cmd->add_option("--detector", o->detector,
                  "auto (ztest with the noise model given, else one learned from the mission's own "
                  "frames) | none | ztest | cfar | probability");
  cmd->add_option("--z", o->z, "Z-test threshold in standard deviations (default 2)");
  cmd->add_option("--cfar-pfa", o->cfar_pfa, "CFAR false-alarm probability (default 0.05)");
  cmd->add_option("--smoothing", o->smoothing,
                  "Detector's box filter side (odd, default 3, 1 = none)");
  cmd->add_option("--min-views", o->min_views,
                  "Keep surface voxels that are the first return in at least this many views");
  cmd->add_option("--region", o->region, "Region of interest: N0 E0 D0 N1 E1 D1 (m)")->expected(6);
  addSourceFlags(*cmd, o->source);
  cmd->callback([o, &pool, &exit_code] { exit_code = runReconstruct(*o, pool); });
}

}  // namespace sonarcarve::cli
