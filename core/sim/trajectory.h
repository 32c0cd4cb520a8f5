// Trajectories for the simulator: the vehicle's true poses (one per frame) and the sonar's
// mounting, plus navigation error for the poses a mission records.
//   vertical   the seed paper's inspection: sonar level, facing the structure's axis from
//              `standoff_m`, moved down in `step_m` steps over the target's depth span,
//              down to `seabed_clearance_m` above the seabed
//   orbit      a descending circle of radius `standoff_m` around the axis, sonar facing in,
//              `laps` turns over the depth span, `step_m` apart along the circle; with
//              `orbit_levels` set, that many level circles instead, one above the other
//   descents   `descents` vertical descents like `vertical`, from headings 360/descents
//              degrees apart around the axis (one descent: `vertical` itself)
// vertical, orbit and descents pitch the sonar by `view_tilt_deg` and raise it so that its
// axis meets the structure's axis at the depth it inspects (tilted down, it looks down at it).
//   lawnmower  parallel north-south lines `line_length_m` long and `line_spacing_m` apart,
//              from the west of a `survey_width_m` square, at `altitude_m` above the
//              seabed, sonar pitched down `tilt_deg`, `step_m` apart along the lines
// With `frames` set, orbit and lawnmower go on for that many frames: more laps, or more lines
// to the east (a long survey over a seabed field, sim/seabed_field.h).
//   CSV        vehicle poses from a navigation CSV (docs/formats.md), one frame per row
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/enum_names.h"
#include "geometry/scene.h"
#include "sonar/mounting.h"
#include "sonar/nav_track.h"

namespace sonarcarve {

struct TrajectorySpec {
  std::string kind = "vertical";  ///< vertical | orbit | descents | lawnmower | path to a CSV
  double standoff_m = 4.5;        ///< horizontal distance from sonar to the target's axis
  double step_m = 0.1;            ///< distance between consecutive frames
  double speed_mps = 0.1;         ///< vehicle speed, sets the time between frames
  double altitude_m = 3.0;        ///< lawnmower: height above the seabed
  double line_spacing_m = 2.0;    ///< lawnmower: distance between lines
  double tilt_deg = -30.0;        ///< lawnmower: sonar pitch on the vehicle (negative = down)
  double line_length_m = 10.0;    ///< lawnmower: length of a line
  double survey_width_m = 10.0;   ///< lawnmower: east-west extent of the lines, without `frames`
  double laps = 1.0;              ///< orbit: turns around the axis (per level), without `frames`
  /// orbit: 0, one circle descending over the depth span; n >= 1, n level circles of `laps`
  /// turns each, aimed at depths `level_spacing_m` apart centred on the target's axis point,
  /// from the top one down (`frames` is then unused).
  int orbit_levels = 0;
  double level_spacing_m = 1.5;  ///< orbit levels: between the depths they aim at
  int descents = 4;              ///< descents: how many, from headings evenly around the axis
  /// vertical, orbit and descents: sonar pitch on the vehicle (negative = down), its axis
  /// aimed at the structure's axis.
  double view_tilt_deg = 0.0;
  /// orbit and lawnmower: the number of frames (0: what `laps` or the survey's square make).
  int frames = 0;
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

/// The axes of a navigation error, as bits of NavErrorSpec::axes: position north, east, down
/// (world) and attitude roll, pitch, yaw (the vehicle's).
enum NavAxis : unsigned {
  kNavNorth = 1u << 0,
  kNavEast = 1u << 1,
  kNavDown = 1u << 2,
  kNavRoll = 1u << 3,
  kNavPitch = 1u << 4,
  kNavYaw = 1u << 5,
  kAllNavAxes = (1u << 6) - 1u,
};
inline constexpr std::array<EnumName<NavAxis>, 6> kNavAxisNames{{
    {kNavNorth, "north"},
    {kNavEast, "east"},
    {kNavDown, "down"},
    {kNavRoll, "roll"},
    {kNavPitch, "pitch"},
    {kNavYaw, "yaw"},
}};
constexpr const auto& enumNamesOf(NavAxis) {
  return kNavAxisNames;
}

/// "north,east,yaw" as bits (kAllNavAxes for "all"). Throws Error naming the word that is not
/// an axis, or on an empty list.
unsigned navAxesFromNames(const std::string& names);
/// The bits as the names navAxesFromNames reads ("all" for kAllNavAxes).
std::string navAxesNames(unsigned axes);

/// Navigation error, in the manner of a DVL-aided INS or USBL fix: three seeded kinds, each on
/// the position (every axis, metres) and on the attitude (roll, pitch and yaw, degrees).
struct NavErrorSpec {
  double position_sigma_m = 0.0;    ///< random walk: step per navigation sample
  double attitude_sigma_deg = 0.0;  ///< random walk: step per navigation sample
  std::uint64_t seed = 1;
  double position_bias_m = 0.0;     ///< constant bias: one offset per axis, drawn once
  double attitude_bias_deg = 0.0;   ///< constant bias: one offset per angle, drawn once
  double position_noise_m = 0.0;    ///< white noise: independent per sample
  double attitude_noise_deg = 0.0;  ///< white noise: independent per sample
  /// The axes the errors reach (NavAxis bits); the others keep the true values. The draws are
  /// those of every axis, so an axis kept has the very error it has with all axes: which of a
  /// drift's axes spoil a map can be told apart with one seed.
  unsigned axes = kAllNavAxes;

  bool any() const;
};

/// The poses a navigation system would record: the true ones plus the errors of `spec`, each
/// the standard deviation of a normal draw. Each kind has its own stream of the seed, so that
/// adding one kind leaves the others' draws as they were.
std::vector<NavSample> withNavigationError(const std::vector<NavSample>& truth,
                                           const NavErrorSpec& spec);

}  // namespace sonarcarve
