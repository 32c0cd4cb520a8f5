#include "sim/trajectory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include "common/angles.h"
#include "common/error.h"
#include "io/mission/nav_csv.h"
#include "sonar/attitude.h"

namespace sonarcarve {
namespace {

// The sonar sits 0.5 m ahead of and 0.2 m below the vehicle's reference point.
Mounting defaultMounting(double tilt_rad) {
  return Mounting{{0.5, 0.0, 0.2}, {0.0, tilt_rad, 0.0}};
}

// Vehicle pose that puts the sonar at `sonar_position` with the vehicle level at `yaw`.
NavSample vehicleFor(double time_s, const Eigen::Vector3d& sonar_position, double yaw,
                     const Mounting& mounting) {
  const Eigen::Quaterniond q = quaternionFromRollPitchYaw({0.0, 0.0, yaw});
  return NavSample{time_s, sonar_position - q * mounting.translation_m, q};
}

void requireSpan(const InspectionTarget& t, const std::string& kind) {
  if (!(t.bottom_down_m > t.top_down_m)) {
    throw Error("trajectory", kind, "the target has no depth span to cover");
  }
}

// How far above the depth it inspects the sonar sits: pitched by `view_tilt_deg`, its axis
// meets the structure's axis there, `standoff_m` away.
double aimRaise(const TrajectorySpec& spec) {
  return spec.standoff_m * std::tan(-degToRad(spec.view_tilt_deg));
}

// The deepest depth a vertical descent or an orbit inspects: the target's bottom, kept
// `seabed_clearance_m` above a seabed.
double inspectedBottom(const TrajectorySpec& spec, const InspectionTarget& target) {
  return target.seabed_down_m > 0.0
             ? std::min(target.bottom_down_m, target.seabed_down_m - spec.seabed_clearance_m)
             : target.bottom_down_m;
}

// The position facing the axis from `heading` (the direction the sonar looks), `standoff_m`
// away, at `depth`.
Eigen::Vector3d facingAxis(const TrajectorySpec& spec, const InspectionTarget& target,
                           double heading, double depth) {
  return {target.axis_point_m.x() - spec.standoff_m * std::cos(heading),
          target.axis_point_m.y() - spec.standoff_m * std::sin(heading), depth};
}

// One vertical descent looking along `heading`, from `start_time_s`, appended to `traj`.
void addDescent(const TrajectorySpec& spec, const InspectionTarget& target, double heading,
                double start_time_s, Trajectory& traj) {
  // Start above the top by the clearance, so that views from above carve the water over it.
  const double top = target.top_down_m - spec.top_clearance_m;
  const double bottom = inspectedBottom(spec, target);
  const double raise = aimRaise(spec);
  const int frames = static_cast<int>(std::floor((bottom - top) / spec.step_m + 1e-9)) + 1;
  for (int i = 0; i < frames; ++i) {
    const Eigen::Vector3d sonar = facingAxis(spec, target, heading, top + i * spec.step_m - raise);
    traj.poses.push_back(
        vehicleFor(start_time_s + i * spec.step_m / spec.speed_mps, sonar, heading, traj.mounting));
  }
}

Trajectory vertical(const TrajectorySpec& spec, const InspectionTarget& target) {
  requireSpan(target, "vertical");
  Trajectory traj{{}, defaultMounting(degToRad(spec.view_tilt_deg))};
  addDescent(spec, target, 0.0, spec.start_time_s, traj);
  return traj;
}

Trajectory descents(const TrajectorySpec& spec, const InspectionTarget& target) {
  requireSpan(target, "descents");
  Trajectory traj{{}, defaultMounting(degToRad(spec.view_tilt_deg))};
  const double turn = 2.0 * std::numbers::pi / spec.descents;
  // Between descents the vehicle climbs back and moves round to the next heading.
  const double climb = target.top_down_m - spec.top_clearance_m - inspectedBottom(spec, target);
  double time = spec.start_time_s;
  for (int d = 0; d < spec.descents; ++d) {
    addDescent(spec, target, d * turn, time, traj);
    time = traj.poses.back().time_s + (std::abs(climb) + turn * spec.standoff_m) / spec.speed_mps;
  }
  return traj;
}

// Level circles of `laps` turns, aimed at depths `level_spacing_m` apart around the target's
// axis point, the top one first; the sonar stays `seabed_clearance_m` above a seabed.
Trajectory levelOrbits(const TrajectorySpec& spec, const InspectionTarget& target) {
  Trajectory traj{{}, defaultMounting(degToRad(spec.view_tilt_deg))};
  const double circumference = 2.0 * std::numbers::pi * spec.standoff_m;
  const int per_level =
      std::max(3, static_cast<int>(std::round(spec.laps * circumference / spec.step_m)));
  const double angle_step = 2.0 * std::numbers::pi * spec.laps / per_level;
  double time = spec.start_time_s;
  for (int level = 0; level < spec.orbit_levels; ++level) {
    const double aim =
        target.axis_point_m.z() + (level - 0.5 * (spec.orbit_levels - 1)) * spec.level_spacing_m;
    double depth = aim - aimRaise(spec);
    if (target.seabed_down_m > 0.0) {
      depth = std::min(depth, target.seabed_down_m - spec.seabed_clearance_m);
    }
    for (int i = 0; i < per_level; ++i) {
      const double angle = i * angle_step;  // position angle around the axis
      traj.poses.push_back(
          vehicleFor(time, facingAxis(spec, target, angle, depth), angle, traj.mounting));
      time += spec.step_m / spec.speed_mps;
    }
    time += spec.level_spacing_m / spec.speed_mps;  // down to the next level
  }
  return traj;
}

Trajectory orbit(const TrajectorySpec& spec, const InspectionTarget& target) {
  requireSpan(target, "orbit");
  if (spec.orbit_levels > 0) {
    return levelOrbits(spec, target);
  }
  Trajectory traj{{}, defaultMounting(degToRad(spec.view_tilt_deg))};
  const double top = target.top_down_m;
  const double bottom = inspectedBottom(spec, target);
  const double raise = aimRaise(spec);
  const double circumference = 2.0 * std::numbers::pi * spec.standoff_m;
  // The last frame closes the last lap; with `frames` set, as many laps as those frames make.
  const int frames =
      spec.frames > 0
          ? spec.frames
          : std::max(2, static_cast<int>(std::round(spec.laps * circumference / spec.step_m)));
  const double laps =
      spec.frames > 0 ? std::max(1, frames - 1) * spec.step_m / circumference : spec.laps;
  for (int i = 0; i < frames; ++i) {
    const double u = frames > 1 ? static_cast<double>(i) / (frames - 1) : 0.0;
    const double angle = 2.0 * std::numbers::pi * laps * u;  // position angle around the axis
    const Eigen::Vector3d sonar(target.axis_point_m.x() - spec.standoff_m * std::cos(angle),
                                target.axis_point_m.y() - spec.standoff_m * std::sin(angle),
                                top + u * (bottom - top) - raise);
    traj.poses.push_back(vehicleFor(spec.start_time_s + i * spec.step_m / spec.speed_mps, sonar,
                                    angle, traj.mounting));
  }
  return traj;
}

Trajectory lawnmower(const TrajectorySpec& spec, const InspectionTarget& target) {
  if (!(target.seabed_down_m > 0.0)) {
    throw Error("trajectory", "lawnmower", "the target has no seabed to survey");
  }
  Trajectory traj{{}, defaultMounting(degToRad(spec.tilt_deg))};
  const double half = 0.5 * spec.line_length_m;  // the lines' square: survey_width_m wide
  const double depth = target.seabed_down_m - spec.altitude_m;
  const int per_line = static_cast<int>(std::floor(spec.line_length_m / spec.step_m + 1e-9)) + 1;
  const int lines =
      spec.frames > 0 ? (spec.frames + per_line - 1) / per_line
                      : static_cast<int>(std::floor(spec.survey_width_m / spec.line_spacing_m)) + 1;
  const std::size_t frames = spec.frames > 0 ? static_cast<std::size_t>(spec.frames)
                                             : static_cast<std::size_t>(lines) * per_line;
  double time = spec.start_time_s;
  for (int l = 0; l < lines; ++l) {
    const bool north = l % 2 == 0;
    const double east =
        target.axis_point_m.y() - 0.5 * spec.survey_width_m + l * spec.line_spacing_m;
    for (int i = 0; i < per_line && traj.poses.size() < frames; ++i) {
      // The sonar looks ahead, so start each line that far behind the square.
      const double along = -half - 3.0 + i * spec.step_m;
      const double northing = target.axis_point_m.x() + (north ? along : -along);
      traj.poses.push_back(
          vehicleFor(time, {northing, east, depth}, north ? 0.0 : std::numbers::pi, traj.mounting));
      time += spec.step_m / spec.speed_mps;
    }
    time += spec.line_spacing_m / spec.speed_mps;  // the turn
  }
  return traj;
}

}  // namespace

Trajectory makeTrajectory(const TrajectorySpec& spec, const InspectionTarget& target) {
  if (!(spec.step_m > 0.0) || !(spec.speed_mps > 0.0) || !(spec.standoff_m > 0.0)) {
    throw Error("trajectory", spec.kind, "expected positive step, speed and standoff");
  }
  if (!(spec.line_length_m > 0.0) || !(spec.line_spacing_m > 0.0) ||
      !(spec.survey_width_m >= 0.0) || !(spec.laps > 0.0) || spec.frames < 0) {
    throw Error("trajectory", spec.kind,
                "expected positive line length, line spacing and laps, and no negative survey "
                "width or frames");
  }
  if (spec.orbit_levels < 0 || spec.orbit_levels > 100 || spec.descents < 1 ||
      spec.descents > 360 || !(spec.level_spacing_m > 0.0) ||
      !(std::abs(spec.view_tilt_deg) < 80.0)) {
    throw Error("trajectory", spec.kind,
                "expected 0 to 100 orbit levels, 1 to 360 descents, a positive level spacing "
                "and a view tilt within +-80 degrees");
  }
  if (spec.kind == "vertical") {
    return vertical(spec, target);
  }
  if (spec.kind == "orbit") {
    return orbit(spec, target);
  }
  if (spec.kind == "descents") {
    return descents(spec, target);
  }
  if (spec.kind == "lawnmower") {
    return lawnmower(spec, target);
  }
  if (std::filesystem::path(spec.kind).extension() == ".csv") {
    const NavTrack track = readNavCsv(spec.kind);
    return Trajectory{track.samples(), defaultMounting(0.0)};
  }
  throw Error("trajectory", spec.kind,
              "unknown trajectory: expected vertical, orbit, descents, lawnmower or a .csv of "
              "poses");
}

unsigned navAxesFromNames(const std::string& names) {
  if (names == "all") {
    return kAllNavAxes;
  }
  unsigned axes = 0;
  std::size_t begin = 0;
  while (begin <= names.size()) {
    const std::size_t end = std::min(names.find(',', begin), names.size());
    const std::string word = names.substr(begin, end - begin);
    const std::optional<NavAxis> axis = enumFromString<NavAxis>(word);
    if (!axis) {
      throw Error("navigation error", "axes",
                  "expected all, or a comma-separated list of north, east, down, roll, pitch "
                  "and yaw, found '" +
                      word + "'");
    }
    axes |= *axis;
    begin = end + 1;
  }
  return axes;
}

std::string navAxesNames(unsigned axes) {
  if ((axes & kAllNavAxes) == kAllNavAxes) {
    return "all";
  }
  std::string names;
  for (const EnumName<NavAxis>& n : kNavAxisNames) {
    if ((axes & n.value) != 0) {
      names += (names.empty() ? "" : ",") + std::string(n.name);
    }
  }
  return names;
}

bool NavErrorSpec::any() const {
  return position_sigma_m != 0.0 || attitude_sigma_deg != 0.0 || position_bias_m != 0.0 ||
         attitude_bias_deg != 0.0 || position_noise_m != 0.0 || attitude_noise_deg != 0.0;
}

std::vector<NavSample> withNavigationError(const std::vector<NavSample>& truth,
                                           const NavErrorSpec& spec) {
  // One stream per kind of error (the random walk's is the seed's own, as it always was).
  std::mt19937_64 walk_rng(spec.seed);
  std::mt19937_64 bias_rng(spec.seed ^ 0x6a09e667f3bcc909ULL);
  std::mt19937_64 noise_rng(spec.seed ^ 0xbb67ae8584caa73bULL);
  std::normal_distribution<double> normal(0.0, 1.0);
  const auto draw = [&](std::mt19937_64& rng, double sigma) -> Eigen::Vector3d {
    return sigma * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  };
  const Eigen::Vector3d position_bias = draw(bias_rng, spec.position_bias_m);
  const Eigen::Vector3d attitude_bias = draw(bias_rng, degToRad(spec.attitude_bias_deg));
  Eigen::Vector3d position_walk = Eigen::Vector3d::Zero();
  Eigen::Vector3d attitude_walk = Eigen::Vector3d::Zero();  // roll, pitch, yaw (rad)
  std::vector<NavSample> recorded;
  recorded.reserve(truth.size());
  for (const NavSample& t : truth) {
    position_walk += draw(walk_rng, spec.position_sigma_m);
    attitude_walk += draw(walk_rng, degToRad(spec.attitude_sigma_deg));
    Eigen::Vector3d position_error =
        position_walk + position_bias + draw(noise_rng, spec.position_noise_m);
    Eigen::Vector3d attitude_error =
        attitude_walk + attitude_bias + draw(noise_rng, degToRad(spec.attitude_noise_deg));
    constexpr std::array<unsigned, 3> kPositionAxes = {kNavNorth, kNavEast, kNavDown};
    constexpr std::array<unsigned, 3> kAttitudeAxes = {kNavRoll, kNavPitch, kNavYaw};
    for (std::size_t a = 0; a < 3; ++a) {
      if ((spec.axes & kPositionAxes[a]) == 0) {
        position_error[static_cast<int>(a)] = 0.0;
      }
      if ((spec.axes & kAttitudeAxes[a]) == 0) {
        attitude_error[static_cast<int>(a)] = 0.0;
      }
    }
    NavSample r = t;
    r.position_m += position_error;
    r.q_world_vehicle =
        t.q_world_vehicle *
        quaternionFromRollPitchYaw({attitude_error.x(), attitude_error.y(), attitude_error.z()});
    recorded.push_back(r);
  }
  return recorded;
}

}  // namespace sonarcarve
