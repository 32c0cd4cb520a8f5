// MissionSummary: the figures `sonarcarve-cli info` reports, computed once for the CLI and the
// GUI alike: frame count and time span, sonar geometry, navigation extent, unusable frames.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/mission/mission.h"

namespace sonarcarve {

struct MissionSummary {
  std::string name;
  std::size_t frame_count = 0;
  double first_frame_time_s = 0.0;
  double last_frame_time_s = 0.0;
  double duration_s = 0.0;
  std::size_t nav_samples = 0;
  double nav_start_s = 0.0;
  double nav_end_s = 0.0;
  Eigen::Vector3d nav_min_m = Eigen::Vector3d::Zero();  ///< world NED bounding box
  Eigen::Vector3d nav_max_m = Eigen::Vector3d::Zero();
  double nav_path_length_m = 0.0;
  /// Frames whose time lies outside the navigation track: they cannot be placed in the world.
  std::vector<std::size_t> frames_outside_nav;
  /// Frames that fail to load (only filled when checking frames).
  std::vector<FrameProblem> frame_problems;
};

/// Summarises a mission; with `check_frames` every frame image is read and verified.
MissionSummary summarize(const Mission& mission, bool check_frames);
/// The same figures from frame times and a track, for data that is not (yet) a mission
/// folder, such as a vendor log (frame_problems is left empty).
MissionSummary summarizeFrames(std::string name, const std::vector<double>& frame_times_s,
                               const NavTrack& nav);

}  // namespace sonarcarve
