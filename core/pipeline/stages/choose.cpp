// choose: the carving rules the mission calls for. Shadow-aware carving where the views look
// at the scene from several sides (fast engine); beam-aware carving's keep level, measured on
// the mission's own denoised frames, and what a dark pixel means after the detector.
#include "pipeline/heading_sectors.h"
#include "pipeline/keep_level.h"
#include "pipeline/run_context.h"
#include "pipeline/shadow_carving.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

class ChooseStage : public Stage {
 public:
  ChooseStage() : Stage("choose", 0.05) {}

  void run(RunContext& run, Progress& progress) const override {
    CarveParams& carve = run.carving.carve;
    if (run.params.engine == Engine::Fast) {
      const ShadowCarvingChoice shadow =
          chooseShadowCarving(run.params.shadow_aware_carving, run.posed);
      carve.shadow_aware = shadow.on;
      run.choose(shadow.choice);
      // Heading sectors (stage "heading sectors") set voxels back into the whole map.
      if (run.evicting && run.params.heading_sectors &&
          !sectorsToCarve(run.posed, run.sonar.range().maxRange()).empty()) {
        run.evicting = false;
      }
    }
    // A run that only resolves a loaded map's surface reads no frame for the keep level.
    if (!carvesMainLobe(run.sonar, carve) || !run.carve_frames) {
      return;
    }
    KeepLevel& level = run.result.keep_level;
    level = run.measured_keep_level
                ? *run.measured_keep_level
                : measureKeepLevel(*run.frames, run.posed, carve.dynamic_range_db, progress);
    level.unit = run.sonar.intensityScale().isLinear() ? "counts" : "power";
    setKeepLevel(carve, level.level, darkPixelsAreExact(run.noise.detector),
                 run.sonar.intensityScale().darkPower());
    level.raised_to_a_count = carve.keep_level > level.level;
    level.level = carve.keep_level;
    if (level.frames > 0) {
      run.choose(keepLevelChoice(level, carve.dynamic_range_db));
    }
  }
};

}  // namespace

std::unique_ptr<Stage> makeChooseStage() {
  return std::make_unique<ChooseStage>();
}

}  // namespace sonarcarve
