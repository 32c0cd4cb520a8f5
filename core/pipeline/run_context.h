// What the stages of one run share (pipeline/stage.h): the run's inputs, which no stage
// changes, what each stage leaves for the ones after it, and the result the run returns.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/thread_pool.h"
#include "io/mission/mission.h"
#include "pipeline/carve_stage.h"
#include "pipeline/evicting_surface.h"
#include "pipeline/frame_stage.h"
#include "pipeline/map_updates.h"
#include "pipeline/memory_budget.h"
#include "pipeline/reconstruction.h"
#include "pipeline/size_limits.h"
#include "pipeline/survey_plan.h"

namespace sonarcarve {

struct RunContext {
  // The run's inputs.
  const Mission& mission;
  const ReconstructionParams& params;
  /// As carving sees it (carvingSonar); the beam check may narrow its elevation beam.
  SonarModel sonar;
  ThreadPool& pool;
  const MemoryWatch& memory;
  ReconstructionObserver* observer = nullptr;
  std::size_t update_every = 1;
  std::shared_ptr<const NoiseModel> given_noise_model{};  ///< the params' file, or null
  std::shared_ptr<const VoxelMap> earlier_map{};          ///< Pipeline::startFrom's, or null
  bool carve_frames = true;  ///< false: the frames only resolve the earlier map's surface
  bool evicting = false;     ///< finished blocks are let go as the track leaves them

  // What the stages leave for the next ones, in the order they run.
  std::vector<PosedFrame> posed{};  ///< read: the selected frames the navigation places
  CarveStageParams carving{};       ///< read; choose sets the shadow rule and keep level
  Eigen::AlignedBox3d bounds{};     ///< read: the box the map covers
  MemoryEstimate buffers{};         ///< read: the per-thread buffers' estimate
  NoiseChoice noise{};              ///< denoise
  /// beam check: up to 4,000 points of a first surface carved inside the aperture
  std::vector<Eigen::Vector3f> first_surface{};
  std::size_t first_surface_frames = 0;  ///< the frames it was carved from
  /// beam check: the keep level measured on the mission's frames, which choose then uses
  std::optional<KeepLevel> measured_keep_level{};
  std::optional<DenoisedFrames> frames{};             ///< denoise: what carving reads
  CarveStageResult carved{};                          ///< carve
  std::optional<EvictingSurface> evicting_surface{};  ///< carve, in an evicting run
  SurveyPlan survey{};                                ///< report: the track and fans in plan

  ReconstructionResult result{};

  /// A frame left out: kept in the result and told to the observer.
  void skip(const FrameProblem& problem);
  /// An automatic decision: kept in the result, in the order made.
  void choose(RunChoice choice) { result.choices.push_back(std::move(choice)); }
  /// " of N threads", for memory messages.
  std::string threads() const { return " of " + std::to_string(pool.size()) + " threads"; }
};

}  // namespace sonarcarve
