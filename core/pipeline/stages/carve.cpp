// carve: every placed frame, denoised, integrated into the map by the chosen engine
// (pipeline/carve_stage.h), with map updates for a viewer, the run's memory checked after each
// frame and, in a run that lets finished blocks go, their surface resolved as the track leaves
// them (pipeline/evicting_surface.h).
#include <algorithm>
#include <optional>

#include "common/error.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

// Seabed-aware carving: off and why, or in how many frames a seabed explained.
RunChoice seabedCarvingChoice(const RunContext& run, std::size_t seabed_frames,
                              std::size_t frames) {
  RunChoice choice;
  choice.name = "seabed-aware carving";
  choice.value = "off";
  if (run.params.engine != Engine::Fast) {
    choice.reason = "the reference engine carves by the paper's rule alone";
    choice.detail = "off (the reference engine)";
  } else if (!run.params.carve.seabed_aware) {
    choice.reason = "as the parameters set it";
    choice.detail = "off (seabed_aware_carving: false)";
  } else if (!carvesMainLobe(run.sonar, run.carving.carve)) {
    choice.reason = "it needs beam-aware carving, which is off or the sonar's beam does not allow";
    choice.detail = "off (it needs beam-aware carving on a sinc^2 beam)";
  } else {
    choice.value = "on";
    choice.reason = seabed_frames == 0
                        ? "no frame showed a seabed"
                        : "a seabed was found in " + std::to_string(seabed_frames) + " of " +
                              std::to_string(frames) + " frames and kept from being carved away";
    choice.detail = "on, a seabed explained " + std::to_string(seabed_frames) + " of " +
                    std::to_string(frames) + " frames";
  }
  return choice;
}

// The fit (fit.enabled) works on the fast engine's map: asked of the reference engine it does
// not run, and the run says so (it was left out without a word, exit 0).
std::optional<RunChoice> fitLeftOutChoice(const RunContext& run) {
  if (!run.params.fit.enabled || run.params.engine == Engine::Fast) {
    return std::nullopt;
  }
  RunChoice choice;
  choice.name = "fit";
  choice.value = "off";
  choice.reason =
      "fit.enabled asks it, but the fit works on the fast engine's map: the reference engine's "
      "surface is kept";
  choice.detail = "off (fit.enabled: true with engine: reference)";
  choice.action = "set engine: fast (--engine fast) to fit the map to the frames";
  choice.warning = true;
  return choice;
}

class CarvingStage : public Stage {
 public:
  CarvingStage() : Stage("carve", 0.6) {}

  void run(RunContext& run, Progress& progress) const override {
    const CarveStage carving(run.sonar, run.carving, run.pool);
    std::optional<MapUpdateSink> updates;
    if (run.observer) {
      updates.emplace(*run.observer, run.update_every);
    }
    const auto check_frame = [&run](const CarvedSoFar& at) {
      std::vector<MemoryPart> parts{{"map", at.map_bytes},
                                    {"frame buffers" + run.threads(), run.buffers.frames}};
      std::string when =
          "after frame " + std::to_string(at.frame) + " of " + std::to_string(at.frames);
      if (at.pass != "carving") {
        parts.push_back({"z-buffers" + run.threads(), run.buffers.occlusion});
        when += " of " + std::string(at.pass);
      }
      run.memory.require(parts, when);
    };
    CarveHooks hooks;
    if (run.evicting) {
      CarveParams as_carved = run.carving.carve;
      as_carved.region = run.bounds;
      run.evicting_surface.emplace(run.posed, run.sonar, as_carved, run.params.min_views, run.pool,
                                   run.params.set_aside_after_frames);
      hooks.starting = [&run](std::size_t position, Carver& carver) {
        run.evicting_surface->frameStarting(position, *carver.evictableMap());
      };
      hooks.carved = [&run](std::size_t position, const Eigen::Isometry3d& T_world_sonar,
                            Carver& carver) {
        run.evicting_surface->frameCarved(position, T_world_sonar, *carver.evictableMap());
      };
    }
    run.carved = carving.run(
        run.posed, run.bounds, *run.frames, progress, updates ? &*updates : nullptr,
        [&run](const FrameProblem& problem) { run.skip(problem); }, check_frame, hooks);
    ReconstructionResult& result = run.result;
    CarveStageResult& carved = run.carved;
    result.cancelled = carved.cancelled;
    result.frames_used = carved.used.size();
    result.refinement = std::move(carved.refinement);
    if (carved.used.empty()) {
      if (result.cancelled) {
        throw Cancelled();
      }
      throw Error(run.mission.folder.string(), "", "every selected frame failed to load");
    }
    result.carver = std::move(carved.carver);
    run.choose(seabedCarvingChoice(run, result.carver->stats().seabed_frames, carved.used.size()));
    if (auto fit = fitLeftOutChoice(run)) {
      run.choose(std::move(*fit));
    }
    std::sort(carved.carve_ms.begin(), carved.carve_ms.end());
    result.carve_ms_median =
        carved.carve_ms.empty() ? 0.0 : carved.carve_ms[carved.carve_ms.size() / 2];
  }
};

}  // namespace

std::unique_ptr<Stage> makeCarveStage() {
  return std::make_unique<CarvingStage>();
}

}  // namespace sonarcarve
