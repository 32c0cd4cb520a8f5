#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {

std::vector<std::shared_ptr<const Stage>> standardStages() {
  return {makeReadStage(),   makeDenoiseStage(),      makeBeamCheckStage(),
          makeChooseStage(), makeSeabedReliefStage(), makeCarveStage(),
          makeSectorStage(), makeSurfaceStage(),      makeMeshStage()};
}

}  // namespace sonarcarve
