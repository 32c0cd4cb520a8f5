// beam check: whether the frames show the returns the declared elevation beam puts past its
// aperture (pipeline/beam_check.h), for a run that carves beam-aware. A first surface is carved
// inside the aperture only from up to kCheckFrames frames in the middle of the mission (a few
// metres of track: its map stays small whatever the mission); where the tails are missing, the
// run carves inside the aperture too, as for a sonar declared `clipped`.
#include <algorithm>

#include "carve/carving_geometry.h"
#include "common/error.h"
#include "denoise/noise_model.h"
#include "pipeline/beam_check.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"
#include "pipeline/surface_stage.h"

namespace sonarcarve {
namespace {

constexpr std::size_t kCheckFrames = 24;

// The middle of the mission: every other frame of its middle 2 kCheckFrames, or every frame of
// a mission shorter than that, at most kCheckFrames of them.
std::vector<PosedFrame> middleFrames(const std::vector<PosedFrame>& posed) {
  const std::size_t span = std::min(posed.size(), 2 * kCheckFrames);
  const std::size_t stride = span > kCheckFrames ? 2 : 1;
  const std::size_t first = (posed.size() - span) / 2;
  std::vector<PosedFrame> middle;
  for (std::size_t i = first; i < first + span; i += stride) {
    middle.push_back(posed[i]);
  }
  return middle;
}

class BeamCheckStage : public Stage {
 public:
  BeamCheckStage() : Stage("beam check", 0.03) {}

  void run(RunContext& run, Progress& progress) const override {
    if (!carvesMainLobe(run.sonar, run.carving.carve) || !run.carve_frames) {
      return;
    }
    const SonarModel clipped = run.sonar.withElevationBeam(ElevationBeam::Clipped);
    CarveStageParams params = run.carving;
    params.occlusion_aware = false;
    params.refinement.enabled = false;
    params.earlier_map = nullptr;
    const CarveStage first(clipped, params, run.pool);
    const std::vector<PosedFrame> frames = middleFrames(run.posed);
    RenamedProgress checking(progress, "beam check");
    const CarveStageResult carved = first.run(frames, first.mapBounds(frames), *run.frames,
                                              checking, nullptr, [](const FrameProblem&) {});
    if (carved.cancelled) {
      throw Cancelled();
    }
    if (carved.used.empty()) {
      return;  // the carve stage reports the frames that do not load
    }
    const SurfaceStageResult surface =
        resolveSurface(*carved.carver, carved.used, clipped, carved.carve, run.params.min_views,
                       run.pool, checking);
    if (surface.cancelled) {
      throw Cancelled();
    }
    const NoiseModel* background = run.noise.model.get();
    const auto excess = [&](std::size_t i) -> std::optional<cv::Mat> {
      try {
        cv::Mat image = loadFrame(run.mission, carved.used[i].index).image;
        return background ? cv::Mat(image - background->mean()) : image;
      } catch (const Error&) {
        return std::nullopt;
      }
    };
    const BeamTailCheck check =
        checkBeamTails(positionsOf(surface.surface), carved.used, excess, run.sonar,
                       background ? background->stddev() : cv::Mat());
    run.choose(beamTailChoice(check));
    if (!check.tails_present) {
      run.sonar = clipped;
    }
  }
};

}  // namespace

std::unique_ptr<Stage> makeBeamCheckStage() {
  return std::make_unique<BeamCheckStage>();
}

}  // namespace sonarcarve
