// denoise: the noise model the detector uses (given, or learned from the mission's own
// frames) and the width of the beams whose blur across bearing is taken out (declared, or
// read from the frames); from them, what carving reads of every frame (DenoisedFrames).
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

class DenoiseStage : public Stage {
 public:
  DenoiseStage() : Stage("denoise", 0.09) {}

  void run(RunContext& run, Progress& progress) const override {
    run.noise = chooseNoiseModel(run.mission, run.posed, run.params.detector,
                                 run.params.noise_model, run.given_noise_model, progress);
    run.result.detector = std::string(toString(run.noise.detector.mode));
    run.choose(run.noise.choice);
    if (run.observer) {
      run.observer->noiseModelChosen(run.noise.model);
    }
    // A run that reads no frame (startFrom without carving) reads none for the width either.
    const BeamWidthChoice beams =
        run.carve_frames ? chooseBeamWidth(run.mission, run.sonar, indicesOf(run.posed), progress)
                         : BeamWidthChoice{run.sonar, BeamWidthChoice::Source::Declared, ""};
    run.frames.emplace(run.mission, beams.sonar, run.noise);
    run.choose(bearingDeblurChoice(beams, *run.frames));
  }
};

}  // namespace

std::unique_ptr<Stage> makeDenoiseStage() {
  return std::make_unique<DenoiseStage>();
}

}  // namespace sonarcarve
