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

Trajectory vertical(const TrajectorySpec& spec, const InspectionTarget& target) {
  requireSpan(target, "vertical");
  Trajectory traj{{}, defaultMounting(0.0)};
  const Eigen::Vector3d axis = target.axis_point_m;
  // Start above the top by the clearance, so that views from above carve the water over it.
  const double top = target.top_down_m - spec.top_clearance_m;
  const double bottom =
      target.seabed_down_m > 0.0
          ? std::min(target.bottom_down_m, target.seabed_down_m - spec.seabed_clearance_m)
          : target.bottom_down_m;
  const int frames = static_cast<int>(std::floor((bottom - top) / spec.step_m + 1e-9)) + 1;
  for (int i = 0; i < frames; ++i) {
    const Eigen::Vector3d sonar(axis.x() - spec.standoff_m, axis.y(), top + i * spec.step_m);
    traj.poses.push_back(vehicleFor(spec.start_time_s + i * spec.step_m / spec.speed_mps, sonar,
                                    0.0, traj.mounting));
  }
  return traj;
}

Trajectory orbit(const TrajectorySpec& spec, const InspectionTarget& target) {
  requireSpan(target, "orbit");
  Trajectory traj{{}, defaultMounting(0.0)};
  const double top = target.top_down_m;
  const double bottom =
      target.seabed_down_m > 0.0
          ? std::min(target.bottom_down_m, target.seabed_down_m - spec.seabed_clearance_m)
          : target.bottom_down_m;
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
                                top + u * (bottom - top));
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
  if (spec.kind == "vertical") {
    return vertical(spec, target);
  }
  if (spec.kind == "orbit") {
    return orbit(spec, target);
  }
  if (spec.kind == "lawnmower") {
    return lawnmower(spec, target);
  }
  if (std::filesystem::path(spec.kind).extension() == ".csv") {
    const NavTrack track = readNavCsv(spec.kind);
    return Trajectory{track.samples(), defaultMounting(0.0)};
  }
  throw Error("trajectory", spec.kind,
              "unknown trajectory: expected vertical, orbit, lawnmower or a .csv of poses");
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
