// surface: the front surface of the carved map. A run that let finished blocks go has
// resolved most of it already, as the track left them, and finishes the rest; otherwise
// occlusion resolution runs over the whole map (pipeline/surface_stage.h).
#include <algorithm>

#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"
#include "pipeline/surface_kept.h"
#include "pipeline/surface_stage.h"

namespace sonarcarve {
namespace {

// A run that keeps no surface says so, and why as far as the run can tell.
RunChoice emptySurfaceChoice(const RunContext& run) {
  RunChoice choice;
  choice.name = "surface";
  choice.value = "empty";
  choice.warning = true;
  const std::size_t voxels = run.result.occupied_voxels;
  if (voxels == 0) {
    choice.reason = "carving kept no voxel: every return was carved away by another view";
    choice.action =
        "check the navigation and the sonar's declared beam; beam_aware_carving: false carves "
        "by the paper's rule";
  } else {
    choice.reason = "no carved voxel was the first return in enough views";
    choice.action = "lower min_views, or check the navigation";
  }
  choice.detail = std::to_string(voxels) + " occupied voxels after carving " +
                  std::to_string(run.result.frames_used) + " frames; min_views " +
                  std::to_string(run.params.min_views);
  if (!run.first_surface.empty()) {
    choice.detail += "; a first carve inside the aperture from the middle of the mission kept " +
                     std::to_string(run.first_surface.size()) +
                     " surface points (looked at): the frames show structure that the run's "
                     "rules carved away";
  }
  return choice;
}

// Fewer surface points than the frames that carved it, or than one frame's beams: a structure
// the frames image leaves a point on every beam that sees it in enough views, so so few points
// mean that the views hardly agree anywhere (the navigation, its clock or the sonar's declared
// geometry). A structure seen by a few beams only gives this warning too: it asks for a look.
std::size_t nearlyEmptyBelow(const RunContext& run) {
  return std::max(run.result.frames_used, static_cast<std::size_t>(run.sonar.cols()));
}

RunChoice nearlyEmptySurfaceChoice(const RunContext& run) {
  RunChoice choice;
  choice.name = "surface";
  choice.value = "nearly empty";
  choice.warning = true;
  choice.reason =
      "the views agree on almost no surface: " + std::to_string(run.result.surface.size()) +
      " points from " + std::to_string(run.result.frames_used) + " frames of " +
      std::to_string(run.sonar.cols()) + " beams, fewer than one a frame or than one frame's beams";
  choice.action =
      "check the navigation (its offsets, its clock: --time-offset) and the sonar's declared "
      "geometry; lower min_views";
  choice.detail = std::to_string(run.result.occupied_voxels) + " occupied voxels after carving " +
                  std::to_string(run.result.frames_used) + " frames; min_views " +
                  std::to_string(run.params.min_views);
  return choice;
}

class SurfaceStage : public Stage {
 public:
  SurfaceStage() : Stage("surface", 0.2) {}

  std::optional<MemoryNeed> memoryNeed(const RunContext& run) const override {
    if (run.evicting_surface) {
      return std::nullopt;  // checked frame by frame while carving
    }
    const CarverStats stats = run.result.carver->stats();
    return MemoryNeed{{{"map", static_cast<double>(stats.memory_bytes)},
                       {"occlusion resolution", occlusionStageBytes(stats.occupied_voxels)},
                       {"z-buffers" + run.threads(), run.buffers.occlusion}},
                      "before occlusion resolution"};
  }

  void run(RunContext& run, Progress& progress) const override {
    if (run.evicting_surface) {
      finishEvictingSurface(run, progress);
    } else {
      resolveWholeMap(run, progress);
    }
    if (run.result.cancelled) {
      return;
    }
    if (run.result.surface.empty()) {
      run.choose(emptySurfaceChoice(run));
    } else if (run.result.surface.size() < nearlyEmptyBelow(run) && !run.params.carve.region) {
      // (a region of interest may hold little on purpose)
      run.choose(nearlyEmptySurfaceChoice(run));
    }
    if (!run.result.surface.empty() && !run.first_surface.empty() &&
        run.first_surface_frames >= kFirstSurfaceMinFrames) {
      run.choose(firstSurfaceKeptChoice(firstSurfaceKept(
          run.first_surface, positionsOf(run.result.surface), run.carving.carve.voxel_size_m)));
    }
  }

 private:
  // A run that let finished blocks go resolved most of the surface as the track left them.
  static void finishEvictingSurface(RunContext& run, Progress& progress) {
    ReconstructionResult& result = run.result;
    EvictingSurface& evicting = *run.evicting_surface;
    if (!result.cancelled) {
      evicting.finish(*result.carver->evictableMap());
    }
    result.evicted = true;
    result.pages_freed_early = evicting.pagesFreedEarly();
    result.pages_set_aside = evicting.pagesSetAside();
    result.aside_file_bytes = evicting.asideFileBytes();
    result.temporary_file_problem = evicting.temporaryFileProblem();
    result.surface = evicting.surface();
    result.occupancy = evicting.takeOccupancy();
    result.occupied_voxels = evicting.occupiedVoxels();
    result.map_bytes = evicting.peakBytes();
    result.occlusion_ms_per_frame =
        evicting.occlusionMs() / static_cast<double>(std::max<std::size_t>(1, run.posed.size()));
    progress.report("occlusion", run.posed.size(), run.posed.size());
  }

  // Occlusion resolution over the whole carved map.
  static void resolveWholeMap(RunContext& run, Progress& progress) {
    ReconstructionResult& result = run.result;
    result.map = result.carver->blockMap();
    const CarverStats stats = result.carver->stats();
    result.occupied_voxels = stats.occupied_voxels;
    result.map_bytes = stats.memory_bytes;
    SurfaceStageResult surface =
        resolveSurface(*result.carver, run.carved.used, run.sonar, run.carved.carve,
                       run.params.min_views, run.pool, progress);
    result.cancelled = result.cancelled || surface.cancelled;
    result.occlusion_ms_per_frame = surface.ms_per_frame;
    result.surface = std::move(surface.surface);
  }
};

}  // namespace

std::unique_ptr<Stage> makeSurfaceStage() {
  return std::make_unique<SurfaceStage>();
}

}  // namespace sonarcarve
