// surface: the front surface of the carved map. A run that let finished blocks go has
// resolved most of it already, as the track left them, and finishes the rest; otherwise
// occlusion resolution runs over the whole map (pipeline/surface_stage.h).
#include <algorithm>

#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"
#include "pipeline/surface_stage.h"

namespace sonarcarve {
namespace {

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
    ReconstructionResult& result = run.result;
    if (run.evicting_surface) {
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
      return;
    }
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
