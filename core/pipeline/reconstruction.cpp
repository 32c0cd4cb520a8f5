#include "pipeline/reconstruction.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>

#include "common/available_memory.h"
#include "common/error.h"
#include "common/number_text.h"
#include "denoise/noise_model.h"
#include "pipeline/run_context.h"

namespace sonarcarve {
namespace {

const ReconstructionParams& validated(const ReconstructionParams& params) {
  params.validate();
  return params;
}

// A stage's progress: its steps under their own names, and the run's overall share.
class StageProgress : public Progress {
 public:
  StageProgress(Progress& run, double start, double share)
      : run_(run), start_(start), share_(share) {}
  // A stage's steps each count from 0 and its workers report out of order: the run's
  // progress takes the furthest any has reached.
  void report(const std::string& step, std::size_t done, std::size_t total) override {
    run_.report(step, done, total);
    if (total == 0) {
      return;
    }
    const double at =
        start_ + share_ * static_cast<double>(std::min(done, total)) / static_cast<double>(total);
    const std::lock_guard lock(mutex_);
    if (at > furthest_) {
      furthest_ = at;
      run_.overall(at);
    }
  }
  bool cancelled() const override { return run_.cancelled(); }

 private:
  Progress& run_;
  double start_;
  double share_;
  std::mutex mutex_;
  double furthest_ = 0.0;
};

}  // namespace

FrameSelection frameSelection(const ReconstructionParams& params) {
  return {params.first_frame, params.last_frame, params.stride};
}

SonarModel carvingSonar(const Mission& mission, const ReconstructionParams& params) {
  SonarModel sonar = params.vertical_aperture_rad > 0.0
                         ? mission.sonar.withVerticalAperture(params.vertical_aperture_rad)
                         : mission.sonar;
  return params.horizontal_beam_width_rad > 0.0
             ? sonar.withHorizontalBeamWidth(params.horizontal_beam_width_rad)
             : sonar;
}

std::vector<std::size_t> selectedFrames(const Mission& mission,
                                        const ReconstructionParams& params) {
  return selectFrames(mission.frames.size(), frameSelection(params));
}

std::vector<std::size_t> placedFrames(const Mission& mission, const ReconstructionParams& params) {
  return indicesOf(placeFrames(mission, frameSelection(params), [](const FrameProblem&) {}));
}

void Pipeline::startFrom(std::shared_ptr<const VoxelMap> earlier_map, bool carve_frames,
                         const std::string& source) {
  if (params_.engine != Engine::Fast) {
    throw Error(source, "engine",
                "a run can start from a saved map with the fast engine only, not " +
                    std::string(toString(params_.engine)) + ": expected --engine fast");
  }
  if (earlier_map->voxelSize() != params_.carve.voxel_size_m) {
    throw Error(source, "voxel_size_m",
                "the map has voxels of " + shortestNumber(earlier_map->voxelSize()) +
                    " m, this run carves " + shortestNumber(params_.carve.voxel_size_m) +
                    " m: expected the same voxel size (--voxel-size " +
                    shortestNumber(earlier_map->voxelSize()) + ")");
  }
  earlier_map_ = std::move(earlier_map);
  carve_frames_ = carve_frames;
}

void RunContext::skip(const FrameProblem& problem) {
  result.skipped.push_back(problem);
  if (observer) {
    observer->frameSkipped(problem);
  }
}

Pipeline::Pipeline(const Mission& mission, ReconstructionParams params, ThreadPool& pool)
    : mission_(mission),
      params_(validated(params)),
      sonar_(carvingSonar(mission, params_)),
      noise_model_(params_.noise_model.empty()
                       ? nullptr
                       : std::make_shared<const NoiseModel>(NoiseModel::load(params_.noise_model))),
      pool_(pool),
      stages_(standardStages()) {
  if (params_.fit.enabled && params_.engine == Engine::Fast) {
    addStage(makeFitStage(), "surface");
  }
}

bool Pipeline::evicts() const {
  return params_.evict_blocks && params_.engine == Engine::Fast && !earlier_map_ && carve_frames_ &&
         !keep_whole_map_ && !params_.occlusion_aware_carving && !params_.pose_refinement.enabled &&
         !params_.fit.enabled;
}

void Pipeline::addStage(std::shared_ptr<const Stage> stage, std::string_view after) {
  auto at = std::find_if(stages_.begin(), stages_.end(),
                         [after](const auto& s) { return !after.empty() && s->name() == after; });
  stages_.insert(at == stages_.end() ? at : std::next(at), std::move(stage));
}

void Pipeline::writeOutputsTo(OutputSettings settings) {
  addStage(makeReportStage(settings.announce));
  addStage(makeExportStage(std::move(settings)));
}

std::vector<std::string> Pipeline::stageNames() const {
  std::vector<std::string> names;
  for (const auto& stage : stages_) {
    names.emplace_back(stage->name());
  }
  return names;
}

ReconstructionResult Pipeline::run(Progress& progress, ReconstructionObserver* observer,
                                   std::size_t update_every) const {
  const auto t_start = std::chrono::steady_clock::now();
  const MemoryWatch memory(memoryBudget(params_.memory_budget_mb, availableMemory()));
  RunContext run{.mission = mission_,
                 .params = params_,
                 .sonar = sonar_,
                 .pool = pool_,
                 .memory = memory,
                 .observer = observer,
                 .update_every = update_every,
                 .given_noise_model = noise_model_,
                 .earlier_map = earlier_map_,
                 .carve_frames = carve_frames_,
                 .evicting = evicts() && observer == nullptr};
  double shares = 0.0;
  for (const auto& stage : stages_) {
    shares += stage->progressShare();
  }
  double done = 0.0;
  bool stopped = false;  // a stage was cancelled: only those that finish a run follow
  for (const auto& stage : stages_) {
    const double share = stage->progressShare() / shares;
    if (!stopped || stage->runsAfterCancel()) {
      if (const std::optional<MemoryNeed> need = stage->memoryNeed(run)) {
        memory.require(need->parts, need->when);
      }
      StageProgress part(progress, done, share);
      try {
        stage->run(run, part);
      } catch (const Cancelled&) {
        run.result.cancelled = stopped = true;
      }
    }
    done += share;
    progress.overall(done);
    run.result.total_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  }
  return std::move(run.result);
}

}  // namespace sonarcarve
