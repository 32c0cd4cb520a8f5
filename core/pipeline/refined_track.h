// The vehicle's track as pose refinement corrected it, and how far a track lies from the
// truth (simulated missions keep their true poses in ground_truth_poses.csv).
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "io/mission/mission.h"
#include "pipeline/carve_stage.h"

namespace sonarcarve {

/// One vehicle pose per refined frame, at the frame's time (the mission's mounting undone).
/// Throws Error if `refinement` is empty.
NavTrack refinedTrack(const Mission& mission, const std::vector<FramePoseRefinement>& refinement);

/// RMS position error (m) and RMS heading error (degrees) of vehicle poses against a track
/// that covers their times (poses it does not cover are left out and not counted).
struct TrackError {
  double rms_position_m = 0.0;
  double rms_heading_deg = 0.0;
  std::size_t poses = 0;
};
TrackError trackError(const NavTrack& track, const NavTrack& truth);

/// The report's `pose_refinement` block: the correction of every frame and their summary,
/// and, when the mission holds ground_truth_poses.csv, the raw and refined tracks' errors.
nlohmann::json poseRefinementReport(const Mission& mission,
                                    const std::vector<FramePoseRefinement>& refinement);

}  // namespace sonarcarve
