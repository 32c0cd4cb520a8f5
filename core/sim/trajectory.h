// Trajectories for the simulator: the vehicle's true poses (one per frame) and the sonar's
// mounting, plus navigation error for the poses a mission records.
//   vertical   the seed paper's inspection: sonar level, facing the structure's axis from
//              `standoff_m`, moved down in `step_m` steps over the target's depth span,
//              down to `seabed_clearance_m` above the seabed
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

#include "geometry/scene.h"
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
  /// vertical and orbit: lowest sonar depth above the seabed. 1.8 m keeps the seabed out of
  /// a 10 m, 20 degree fan: seen at grazing incidence from a vertical track, a flat seabed
  /// cannot be localised in elevation (it leaves a slab of ~0.3 m uncarved).
  double seabed_clearance_m = 1.8;
  /// vertical: the first sonar depth above the structure's top. The elevation of a return
  /// is only resolved where views from above and below both see it: 1 m covers the upper
  /// half of a 20 degree fan at 4.5 m (0.8 m).
  double top_clearance_m = 1.0;
  double start_time_s = 0.0;
};

struct Trajectory {
  std::vector<NavSample> poses;  ///< true vehicle poses, one per frame
  Mounting mounting;

  /// The sonar's true pose at frame `frame`.
  Eigen::Isometry3d T_world_sonar(std::size_t frame) const {
    return poses[frame].T_world_vehicle() * mounting.T_vehicle_sonar();
  }
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
