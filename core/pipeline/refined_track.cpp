#include "pipeline/refined_track.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>

#include "common/angles.h"
#include "common/error.h"
#include "io/mission/nav_csv.h"

namespace sonarcarve {
namespace {

NavSample vehicleSample(double time_s, const Eigen::Isometry3d& T_world_vehicle) {
  return {time_s, T_world_vehicle.translation(), Eigen::Quaterniond(T_world_vehicle.linear())};
}

NavTrack vehicleTrack(const Mission& mission, const std::vector<FramePoseRefinement>& refinement,
                      bool refined) {
  if (refinement.empty()) {
    throw Error("pose refinement", "", "no frame was refined");
  }
  const Eigen::Isometry3d T_sonar_vehicle = mission.mounting.T_vehicle_sonar().inverse();
  std::vector<NavSample> samples;
  for (const FramePoseRefinement& r : refinement) {
    const Eigen::Isometry3d T_world_sonar =
        refined ? r.correction.applied(r.T_world_sonar_prior) : r.T_world_sonar_prior;
    const double t = mission.frames.at(r.index).time_s;
    if (samples.empty() || t > samples.back().time_s) {
      samples.push_back(vehicleSample(t, T_world_sonar * T_sonar_vehicle));
    }
  }
  return NavTrack(std::move(samples));
}

double headingOf(const Eigen::Matrix3d& R_world_vehicle) {
  const Eigen::Vector3d forward = R_world_vehicle.col(0);
  return std::atan2(forward.y(), forward.x());
}

}  // namespace

NavTrack refinedTrack(const Mission& mission, const std::vector<FramePoseRefinement>& refinement) {
  return vehicleTrack(mission, refinement, true);
}

TrackError trackError(const NavTrack& track, const NavTrack& truth) {
  TrackError e;
  double position = 0.0, heading = 0.0;
  for (const NavSample& s : track.samples()) {
    if (!truth.covers(s.time_s)) {
      continue;
    }
    const Eigen::Isometry3d T_true = truth.T_world_vehicle(s.time_s);
    position += (s.position_m - T_true.translation()).squaredNorm();
    const double d =
        std::remainder(headingOf(s.q_world_vehicle.toRotationMatrix()) - headingOf(T_true.linear()),
                       2.0 * std::numbers::pi);
    heading += d * d;
    ++e.poses;
  }
  if (e.poses > 0) {
    e.rms_position_m = std::sqrt(position / static_cast<double>(e.poses));
    e.rms_heading_deg = radToDeg(std::sqrt(heading / static_cast<double>(e.poses)));
  }
  return e;
}

nlohmann::json poseRefinementReport(const Mission& mission,
                                    const std::vector<FramePoseRefinement>& refinement) {
  nlohmann::json frames = nlohmann::json::array();
  std::size_t aligned = 0;
  double max_shift = 0.0, max_turn = 0.0, sum_shift = 0.0, sum_turn = 0.0;
  for (const FramePoseRefinement& r : refinement) {
    const PoseCorrection& c = r.correction;
    const double shift = c.translation_world_m.norm();
    const double turn = radToDeg(c.rotation_sonar_rad.norm());
    aligned += c.aligned ? 1 : 0;
    max_shift = std::max(max_shift, shift);
    max_turn = std::max(max_turn, turn);
    sum_shift += shift;
    sum_turn += turn;
    frames.push_back({{"index", r.index},
                      {"aligned", c.aligned},
                      {"north_m", c.translation_world_m.x()},
                      {"east_m", c.translation_world_m.y()},
                      {"down_m", c.translation_world_m.z()},
                      {"roll_deg", radToDeg(c.rotation_sonar_rad.x())},
                      {"pitch_deg", radToDeg(c.rotation_sonar_rad.y())},
                      {"yaw_deg", radToDeg(c.rotation_sonar_rad.z())},
                      {"voxels", c.voxels},
                      {"score_before", c.score_before},
                      {"score_after", c.score_after}});
  }
  const auto n = static_cast<double>(std::max<std::size_t>(refinement.size(), 1));
  nlohmann::json report = {{"frames", refinement.size()},
                           {"frames_aligned", aligned},
                           {"mean_shift_m", sum_shift / n},
                           {"max_shift_m", max_shift},
                           {"mean_turn_deg", sum_turn / n},
                           {"max_turn_deg", max_turn},
                           {"per_frame", frames}};
  std::error_code ec;
  const auto truth_file = mission.folder / "ground_truth_poses.csv";
  if (!refinement.empty() && std::filesystem::is_regular_file(truth_file, ec)) {
    // The truth is in the world frame, as the mission's navigation was read.
    std::string crs = mission.crs;  // a georeferenced mission's truth may be geodetic too
    const NavTrack truth = translatedTrack(
        crs.empty() ? readNavCsv(truth_file) : readNavCsv(truth_file, crs), -mission.origin_ned_m);
    const auto block = [](const TrackError& e) {
      return nlohmann::json{{"rms_position_m", e.rms_position_m},
                            {"rms_heading_deg", e.rms_heading_deg},
                            {"poses", e.poses}};
    };
    report["track_error"] = {
        {"navigation", block(trackError(vehicleTrack(mission, refinement, false), truth))},
        {"refined", block(trackError(refinedTrack(mission, refinement), truth))}};
  }
  return report;
}

}  // namespace sonarcarve
