// Trajectories for the simulator: the vehicle's true poses (one per frame) and the sonar's
// mounting, plus navigation error for the poses a mission records.
//   vertical   the seed paper's inspection: sonar level, facing the structure's axis from
//              `standoff_m`, moved down in `step_m` steps over the target's depth span
//   orbit      a descending circle of radius `standoff_m` around the axis, sonar facing in,
//              one turn over the depth span, `step_m` apart along the circle
//   lawnmower  parallel north-south lines `line_spacing_m` apart at `altitude_m` above the
//              seabed, sonar pitched down `tilt_deg`, `step_m` apart along the lines
//   CSV        vehicle poses from a navigation CSV (docs/formats.md), one frame per row
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/scene.h"
#include "sonar/mounting.h"
#include "sonar/nav_track.h"

namespace sonarcarve {

struct TrajectorySpec {
  std::string kind = "vertical";  ///< vertical | orbit | lawnmower | path to a CSV
  double standoff_m = 4.5;        ///< horizontal distance from sonar to the target's axis
  double step_m = 0.1;            ///< distance between consecutive frames
  double speed_mps = 0.1;         ///< vehicle speed, sets the time between frames
  double altitude_m = 3.0;        ///< lawnmower: height above the seabed
  double line_spacing_m = 2.0;    ///< lawnmower: distance between lines
  double tilt_deg = -30.0;        ///< lawnmower: sonar pitch on the vehicle (negative = down)
  double start_time_s = 0.0;
};

struct Trajectory {
  std::vector<NavSample> poses;  ///< true vehicle poses, one per frame
  Mounting mounting;
};

/// Throws Error for an unknown kind, an unreadable CSV or a target the kind cannot cover.
Trajectory makeTrajectory(const TrajectorySpec& spec, const InspectionTarget& target);

struct NavErrorSpec {
  double position_sigma_m = 0.0;    ///< random-walk step, per frame, in each axis
  double attitude_sigma_deg = 0.0;  ///< random-walk step, per frame, in roll, pitch and yaw
  std::uint64_t seed = 1;
};

/// The poses a navigation system would record: the true ones plus a random walk.
std::vector<NavSample> withNavigationError(const std::vector<NavSample>& truth,
                                           const NavErrorSpec& spec);

}  // namespace sonarcarve
