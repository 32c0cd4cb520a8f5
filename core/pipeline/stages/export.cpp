// export: the run's outputs in its folder (docs/formats.md), each written atomically, and the
// run manifest that lists them. They are written apart first (io/run/staged_outputs.h): a run
// that fails while writing leaves the folder as it was. Then the manifest says "running", the
// files are moved in, and it says "complete" or "cancelled" ("failed" if a move fails). It
// runs after a cancellation too: a cancelled run keeps what it finished, and says so.
#include "carve/map_file.h"
#include "carve/occupancy_export.h"
#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/mission/nav_csv.h"
#include "io/run/run_manifest.h"
#include "io/run/staged_outputs.h"
#include "mesh/mesh_export.h"
#include "occlusion/surface_points.h"
#include "pipeline/refined_track.h"
#include "pipeline/report_page.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

// The files written into the staging folder, in order, with their sizes and checksums.
class Written {
 public:
  explicit Written(std::filesystem::path folder) : folder_(std::move(folder)) {}
  void wrote(const std::string& name) { files_.push_back(describeRunFile(folder_, name)); }
  const std::vector<RunManifestFile>& files() const { return files_; }

 private:
  std::filesystem::path folder_;
  std::vector<RunManifestFile> files_;
};

// report.json, then report.html, which lists the files written before it with checksums.
void writeReports(const RunContext& run, const std::filesystem::path& out, Written& manifest) {
  writeFileAtomically(out / "report.json", run.result.report);
  manifest.wrote("report.json");
  writeReportPage(run, out, manifest.files());
  manifest.wrote("report.html");
}

void writeOutputs(const RunContext& run, const OutputSettings& settings,
                  const std::filesystem::path& out, Written& manifest) {
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
    const StagedOutputs staged(settings_.folder);
    Written written(staged.staging());
    try {
      writeOutputs(run, settings_, staged.staging(), written);
    } catch (const Error& e) {
      throw staged.nothingChanged(e);
    }
    RunManifest manifest(settings_.folder, settings_.arguments, runOutputFiles());
    try {
      for (const RunManifestFile& file : written.files()) {
        staged.publish(file.name);
        manifest.wrote(file);
      }
      staged.sync();
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
