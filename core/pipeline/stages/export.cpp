// export: the run's outputs in its folder (docs/formats.md), each written atomically, and the
// run manifest that lists them: "running" before the first file, then "complete",
// "cancelled" or "failed". It runs after a cancellation too: a cancelled run keeps what it
// finished, and says so.
#include "carve/map_file.h"
#include "carve/occupancy_export.h"
#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/mission/nav_csv.h"
#include "io/run/run_manifest.h"
#include "mesh/mesh_export.h"
#include "occlusion/surface_points.h"
#include "pipeline/refined_track.h"
#include "pipeline/report_page.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

// report.json, then report.html, which lists the files written before it with checksums.
void writeReports(const RunContext& run, const std::filesystem::path& out, RunManifest& manifest) {
  writeFileAtomically(out / "report.json", run.result.report);
  manifest.wrote("report.json");
  writeReportPage(run, out, manifest.files());
  manifest.wrote("report.html");
}

void writeOutputs(const RunContext& run, const OutputSettings& settings, RunManifest& manifest) {
  const std::filesystem::path& out = settings.folder;
  const ReconstructionResult& result = run.result;
  if (settings.report_only) {
    writeReports(run, out, manifest);
    return;
  }
  const Eigen::Vector3d& origin = run.mission.origin_ned_m;
  const std::string& crs = run.mission.crs;
  writeSurfacePointsPly(result.surface, out / "surface_points.ply", origin, crs);
  manifest.wrote("surface_points.ply");
  const bool bt = result.map_bt_skipped.empty();  // else the read stage said why
  if (result.evicted && bt) {
    writeOccupancyBt(result.occupancy.sorted(), run.params.carve.voxel_size_m, out / "map.bt",
                     origin, crs);
    manifest.wrote("map.bt");
  } else if (result.map) {
    if (bt) {
      writeOccupancyBt(*result.map, out / "map.bt", origin, crs);
      manifest.wrote("map.bt");
    }
    if (settings.save_map) {
      saveMap(*result.map, out / "map.scmap");
      manifest.wrote("map.scmap");
    }
  }
  if (!result.mesh.triangles.empty()) {
    ExportOptions ply;
    ply.mission_origin_ned_m = origin;
    ply.mission_crs = crs;
    exportMesh(result.mesh, out / "mesh.ply", ply);
    manifest.wrote("mesh.ply");
    ExportOptions stl;
    stl.format = "stl";
    exportMesh(result.mesh, out / "mesh.stl", stl);
    manifest.wrote("mesh.stl");
  }
  if (!result.refinement.empty()) {
    writeFileAtomically(out / "refined_nav.csv",
                        navCsvText(translatedTrack(refinedTrack(run.mission, result.refinement),
                                                   run.mission.origin_ned_m)));
    manifest.wrote("refined_nav.csv");
  }
  writeFileAtomically(out / "params.yaml", run.params.toYaml());
  manifest.wrote("params.yaml");
  writeReports(run, out, manifest);  // last: the page lists the others with checksums
}

class ExportStage : public Stage {
 public:
  explicit ExportStage(OutputSettings settings)
      : Stage("export", 0.03), settings_(std::move(settings)) {}
  bool runsAfterCancel() const override { return true; }

  void run(RunContext& run, Progress&) const override {
    RunManifest manifest(settings_.folder, settings_.arguments, runOutputFiles());
    try {
      writeOutputs(run, settings_, manifest);
    } catch (const Error& e) {
      try {
        manifest.finish("failed", e.what());
      } catch (const Error&) {
        // The manifest cannot be written either (a full disk): it still says "running".
      }
      tellRemoved(manifest);
      throw;
    }
    manifest.finish(run.result.cancelled ? "cancelled" : "complete");
    tellRemoved(manifest);
  }

 private:
  void tellRemoved(const RunManifest& manifest) const {
    if (settings_.removed) {
      for (const std::filesystem::path& path : manifest.removed()) {
        settings_.removed(path);
      }
    }
  }

  OutputSettings settings_;
};

}  // namespace

const std::vector<std::string>& runOutputFiles() {
  static const std::vector<std::string> files = {
      "surface_points.ply", "map.bt",      "mesh.ply",        "mesh.stl", "params.yaml",
      "report.json",        "report.html", "refined_nav.csv", "map.scmap"};
  return files;
}

std::unique_ptr<Stage> makeExportStage(OutputSettings settings) {
  return std::make_unique<ExportStage>(std::move(settings));
}

}  // namespace sonarcarve
