// The carving stage: every placed frame, denoised, integrated by the chosen engine into a map
// that covers what the frames can see (within the region of interest), with map updates for
// viewers as it grows; optionally a second, occlusion-aware pass.
#pragma once

#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "carve/carver.h"
#include "carve/pose_refiner.h"
#include "common/progress.h"
#include "pipeline/frame_stage.h"
#include "pipeline/map_updates.h"

namespace sonarcarve {

struct CarveStageParams {
  CarverEngine engine = CarverEngine::Fast;
  CarveParams carve;
  /// Second pass in which each frame carves only what it sees past the first pass's surface.
  bool occlusion_aware = false;
  /// Fast engine: frames aligned to the map so far before they carve.
  PoseRefinementParams refinement;
  /// A map carved before (reconstruct --load-map), fused into this run's map before its
  /// frames carve; the map covers its box too. Null: start from nothing.
  std::shared_ptr<const VoxelMap> earlier_map;
  /// False: the frames do not carve (the earlier map is final: the last step of a sharded run
  /// resolves its surface over every frame); they are placed and used as they are.
  bool carve_frames = true;
};

/// A frame's pose as navigation gave it and as carving used it.
struct FramePoseRefinement {
  std::size_t index = 0;  ///< in the mission
  Eigen::Isometry3d T_world_sonar_prior = Eigen::Isometry3d::Identity();
  PoseCorrection correction;
};

struct CarveStageResult {
  std::unique_ptr<Carver> carver;
  std::vector<PosedFrame> used;  ///< frames that loaded and were carved, at the poses used
  /// Pose refinement, one per used frame (empty when it is off).
  std::vector<FramePoseRefinement> refinement;
  std::vector<double> carve_ms;  ///< per used frame (both passes)
  CarveParams carve;             ///< the parameters as used: region = the map's bounds
  bool cancelled = false;
};

/// Where the carving stage is after a frame, and what its maps hold, for a check of the run's
/// memory budget that throws to stop the run between frames (pipeline/memory_budget.h).
struct CarvedSoFar {
  std::string_view pass;  ///< "carving", or "occlusion-aware carving" (the second pass)
  std::size_t frame = 0;  ///< frames of the pass done, skipped ones included
  std::size_t frames = 0;
  /// The maps' memory (Carver::memoryBytes); in the second pass also the first pass's map
  /// and surface it carves against.
  double map_bytes = 0.0;
};
using CarvedFrameCheck = std::function<void(const CarvedSoFar&)>;
/// Hears of each frame carved: its place in the carving order, the pose it carved at, and the
/// carver (which it may let release finished parts of its map, pipeline/evicting_surface.h).
using FrameCarved = std::function<void(std::size_t position, const Eigen::Isometry3d&, Carver&)>;
/// Hears of each frame of the carving order before it is loaded and carved (`starting`: its
/// place and the carver, called for frames that then fail to load too) and after (`carved`).
struct CarveHooks {
  std::function<void(std::size_t position, Carver&)> starting;
  FrameCarved carved;
};

class CarveStage {
 public:
  CarveStage(const SonarModel& sonar, CarveStageParams params, ThreadPool& pool);

  /// The box the map must cover: the union of the frames' frustums, clipped to the region of
  /// interest. Throws Error if that is empty.
  Eigen::AlignedBox3d mapBounds(const std::vector<PosedFrame>& frames) const;

  /// Carves `frames` read through `source` into a map covering `bounds` (mapBounds(frames)).
  /// A frame that fails to load is passed to `skip`; `updates`, when set, receives each
  /// carved frame and the map's changes; `check`, when set, is called after each frame and
  /// may throw to stop the run; `hooks`, when set, hear of each frame before it is loaded and
  /// after it is carved (before the check). Cancellable between frames.
  CarveStageResult run(const std::vector<PosedFrame>& frames, const Eigen::AlignedBox3d& bounds,
                       const DenoisedFrames& source, Progress& progress, MapUpdateSink* updates,
                       const std::function<void(const FrameProblem&)>& skip,
                       const CarvedFrameCheck& check = {}, const CarveHooks& hooks = {}) const;

 private:
  void refine(CarveStageResult& result, const DenoisedFrames& source, Progress& progress,
              MapUpdateSink* updates, const CarvedFrameCheck& check) const;

  const SonarModel& sonar_;
  CarveStageParams params_;
  ThreadPool& pool_;
};

}  // namespace sonarcarve
