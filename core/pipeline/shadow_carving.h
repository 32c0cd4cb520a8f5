// Whether a run carves shadow-aware (CarveParams::shadow_aware), and why: `auto` turns it on
// for missions that view the scene from several sides, where a structure's acoustic shadow
// from one side would carve the faces another side sees (docs/reconstruction.md).
#pragma once

#include <string>
#include <vector>

#include "pipeline/frame_stage.h"
#include "pipeline/reconstruction_params.h"
#include "pipeline/run_choice.h"

namespace sonarcarve {

/// The headings of the views (the sonar's axis on the horizontal plane) span more than this
/// for `auto` to carve shadow-aware, degrees. Measured on the riser's two descents with their
/// headings this far apart (docs/validation.md): at 10 and 15 degrees the shadows carve little
/// and the rule costs more than it keeps (F 0.954 -> 0.946, 0.950 -> 0.948); at 30 degrees it
/// gains (0.903 -> 0.945); at 90 degrees, 0.424 -> 0.834.
inline constexpr double kMultiAspectHeadingSpread_deg = 20.0;

/// The smallest arc of compass headings, degrees (0 to 360), that holds the horizontal look
/// direction of every frame; frames looking within 10 degrees of straight up or down have none
/// and are left out (0 when none has one).
double headingSpreadDeg(const std::vector<PosedFrame>& frames);

struct ShadowCarvingChoice {
  bool on = false;
  RunChoice choice;  ///< the run's choice "shadow-aware carving"
};

ShadowCarvingChoice chooseShadowCarving(ShadowCarving mode, const std::vector<PosedFrame>& frames);

}  // namespace sonarcarve
