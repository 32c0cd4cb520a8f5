// The one orchestrator of a reconstruction: a loop over uniform stages (pipeline/stage.h,
// pipeline/stages/), read -> denoise -> beam check -> choose -> carve -> surface -> mesh, then
// report -> export for a run that writes a folder, with progress, cancellation (checked between
// frames and inside long loops), memory checks and map updates for viewers
// (pipeline/map_updates.h). The GUI and the CLI both run a Pipeline; neither re-implements a step.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "carve/carver.h"
#include "carve/occupancy_store.h"
#include "carve/voxel_map.h"
#include "common/progress.h"
#include "io/mission/mission.h"
#include "mesh/surface_mesher.h"
#include "occlusion/surface_points.h"
#include "pipeline/carve_stage.h"
#include "pipeline/keep_level.h"
#include "pipeline/map_updates.h"
#include "pipeline/reconstruction_params.h"
#include "pipeline/run_choice.h"
#include "pipeline/stage.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {

struct ReconstructionResult {
  SurfacePoints surface;
  Mesh mesh;                       ///< empty when meshing is off or there are too few points
  std::unique_ptr<Carver> carver;  ///< the carved map, whatever the engine
  /// The carver's block map (fast engine), or null; null too when the run let its finished
  /// blocks go (evicted): then `occupancy` holds what map.bt needs.
  const VoxelMap* map = nullptr;
  bool evicted = false;
  std::size_t pages_freed_early = 0;   ///< an evicting run's pages let go before its last frame
  std::size_t pages_set_aside = 0;     ///< ...and set aside while its survey was away
  std::uint64_t aside_file_bytes = 0;  ///< the most their temporary file held
  /// Why an evicting run kept in memory what it sets aside in temporary files (empty: it
  /// did not have to).
  std::string temporary_file_problem;
  OccupancyStore occupancy;  ///< an evicting run's .bt export blocks
  /// Why map.bt is not written (the map's box is beyond OctoMap's keys), or empty.
  std::string map_bt_skipped;
  std::size_t frames_used = 0;
  std::string detector;  ///< the detector that ran (`auto` made concrete)
  /// The run's automatic decisions, in the order made (pipeline/run_choice.h).
  std::vector<RunChoice> choices;
  KeepLevel keep_level;  ///< beam-aware carving's keep level (level 0 when not beam-aware)
  /// Pose refinement of each carved frame (empty when it is off).
  std::vector<FramePoseRefinement> refinement;
  std::vector<FrameProblem> skipped;
  bool cancelled = false;
  std::size_t occupied_voxels = 0;  ///< all occupied voxels of the carved map
  std::size_t map_bytes = 0;        ///< at the end; for an evicting run, the most it held
  double carve_ms_median = 0.0;     ///< per frame
  double occlusion_ms_per_frame = 0.0;
  double total_s = 0.0;
  std::string report;  ///< report.json's text, for a run that writes its outputs
};

class Pipeline {
 public:
  /// Validates the parameters (Error naming the parameter) and reads the noise model they
  /// name (Error naming the file). `mission` and `pool` must outlive the pipeline.
  Pipeline(const Mission& mission, ReconstructionParams params, ThreadPool& pool);

  /// Runs every stage. Throws Error if no frame can be used; on cancellation returns with
  /// `cancelled` set and whatever was finished. `observer` hears of frames and map updates
  /// (every `update_every` frames).
  ReconstructionResult run(Progress& progress, ReconstructionObserver* observer = nullptr,
                           std::size_t update_every = 1) const;

  /// The sonar as carving sees it (the parameters may narrow its vertical aperture).
  const SonarModel& sonar() const { return sonar_; }
  const ReconstructionParams& params() const { return params_; }
  /// Starts carving from a map carved before (reconstruct --load-map; carve/map_file.h): this
  /// run's frames carve into it, and the surface is resolved over this run's frames.
  /// With `carve_frames` false the frames only resolve the loaded map's surface (the last
  /// step of a sharded run, docs/scaling.md).
  /// Throws Error naming `source` (the map's file) when this run cannot start from it: another
  /// engine than the fast one, or voxels of another size than voxel_size_m.
  void startFrom(std::shared_ptr<const VoxelMap> earlier_map, bool carve_frames = true,
                 const std::string& source = "the earlier map");
  /// Keeps the whole carved map to the end (reconstruct --save-map writes it): no eviction.
  void keepWholeMap() { keep_whole_map_ = true; }
  /// Adds a stage after the one named `after` (at the end when empty or not found).
  void addStage(std::shared_ptr<const Stage> stage, std::string_view after = {});
  /// The run composes its report and writes its outputs into `settings.folder`, last.
  void writeOutputsTo(OutputSettings settings);
  /// The stages' names, in the order they run.
  std::vector<std::string> stageNames() const;
  /// Whether a run without a map viewer lets finished blocks go (evict_blocks, and nothing
  /// that needs the whole map).
  bool evicts() const;

 private:
  const Mission& mission_;
  ReconstructionParams params_;
  SonarModel sonar_;
  std::shared_ptr<const NoiseModel> noise_model_;  ///< the params' file, read once; or null
  std::shared_ptr<const VoxelMap> earlier_map_;    ///< startFrom's map, or null
  bool carve_frames_ = true;
  bool keep_whole_map_ = false;
  ThreadPool& pool_;
  std::vector<std::shared_ptr<const Stage>> stages_;
};

/// The sonar a run carves with: the mission's, with the parameters' vertical aperture and
/// horizontal beam width where they give one.
SonarModel carvingSonar(const Mission& mission, const ReconstructionParams& params);

/// The frames the parameters select: first, last, stride.
FrameSelection frameSelection(const ReconstructionParams& params);

/// Indices of the frames the parameters select (first, last, stride).
std::vector<std::size_t> selectedFrames(const Mission& mission, const ReconstructionParams& params);

/// The selected frames that the navigation places: those a run reads, its noise model and
/// the width of its beams among what it reads from them.
std::vector<std::size_t> placedFrames(const Mission& mission, const ReconstructionParams& params);

}  // namespace sonarcarve
