// The correction track of a mission from per-frame measurements against one map (issue 15):
// navigation drifts as a random walk, so the corrections of consecutive frames differ by about
// the walk's step, and the first frame's correction by about one step from none. The frames
// were measured against a map carved at poses that all share one unknown offset (the map's
// own), so each measurement sees the frame's correction plus that offset. The smoother solves,
// in one least-squares problem over every frame's six axes and the map's offset,
//   sum_i |c_i + b - m_i|^2_{H_i} + |c_0|^2_{Q^-1} + sum_i |c_i - c_{i-1}|^2_{Q^-1},
// with H_i the measurement's information (none for a frame without one) and Q the walk's
// step covariance. A direction no frame observes follows the prior alone: it stays where the
// navigation put it instead of creeping. Corrections come out clamped into the search window.
#pragma once

#include <vector>

#include "carve/pose_refiner.h"

namespace sonarcarve {

/// The correction of every frame (in measurement order, one frame per navigation step),
/// clamped by `refiner.clamped`-like bounds of `params`.
std::vector<Vector6d> smoothCorrectionTrack(const std::vector<PoseMeasurement>& measurements,
                                            const PoseRefinementParams& params);

}  // namespace sonarcarve
