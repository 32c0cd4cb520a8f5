// `sonarcarve-cli info MISSION [--json]`: what a mission holds and what is wrong with it.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "common/angles.h"
#include "io/mission.h"
#include "io/mission_summary.h"

namespace sonarcarve::cli {
namespace {

nlohmann::json vectorJson(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

nlohmann::json summaryJson(const Mission& mission, const MissionSummary& s) {
  const SonarModel& sonar = mission.sonar;
  nlohmann::json problems = nlohmann::json::array();
  for (const FrameProblem& p : s.frame_problems) {
    problems.push_back({{"index", p.index}, {"error", p.message}});
  }
  return {
      {"name", s.name},
      {"folder", mission.folder.string()},
      {"frames",
       {{"count", s.frame_count},
        {"first_time_s", s.first_frame_time_s},
        {"last_time_s", s.last_frame_time_s},
        {"duration_s", s.duration_s},
        {"failed", problems},
        {"outside_navigation", s.frames_outside_nav}}},
      {"sonar",
       {{"id", sonar.id()},
        {"beams", sonar.cols()},
        {"range_bins", sonar.rows()},
        {"range_min_m", sonar.range().min_m},
        {"range_max_m", sonar.range().maxRange()},
        {"range_resolution_m", sonar.range().resolution_m},
        {"bearing_table", sonar.bearings().isUniform() ? "uniform" : "explicit"},
        {"bearing_min_deg", radToDeg(sonar.bearings().centre(0))},
        {"bearing_max_deg", radToDeg(sonar.bearings().centre(sonar.cols() - 1))},
        {"field_of_view_deg", radToDeg(sonar.bearings().fieldOfView())},
        {"vertical_aperture_deg", radToDeg(sonar.verticalAperture())}}},
      {"navigation",
       {{"samples", s.nav_samples},
        {"start_s", s.nav_start_s},
        {"end_s", s.nav_end_s},
        {"min_ned_m", vectorJson(s.nav_min_m)},
        {"max_ned_m", vectorJson(s.nav_max_m)},
        {"path_length_m", s.nav_path_length_m}}},
  };
}

void printText(const Mission& mission, const MissionSummary& s) {
  const SonarModel& sonar = mission.sonar;
  std::printf("Mission      %s (%s)\n", s.name.c_str(), mission.folder.string().c_str());
  std::printf("Frames       %zu, %.3f s to %.3f s (%.3f s)\n", s.frame_count, s.first_frame_time_s,
              s.last_frame_time_s, s.duration_s);
  std::printf("Sonar        %s: %d beams x %d range bins\n", sonar.id().c_str(), sonar.cols(),
              sonar.rows());
  std::printf("  range      %.3f to %.3f m, resolution %.4f m\n", sonar.range().min_m,
              sonar.range().maxRange(), sonar.range().resolution_m);
  std::printf("  bearing    %s table, %.2f to %.2f deg (field of view %.2f deg)\n",
              sonar.bearings().isUniform() ? "uniform" : "explicit",
              radToDeg(sonar.bearings().centre(0)),
              radToDeg(sonar.bearings().centre(sonar.cols() - 1)),
              radToDeg(sonar.bearings().fieldOfView()));
  std::printf("  aperture   %.2f deg vertical (-3 dB, sinc)\n", radToDeg(sonar.verticalAperture()));
  std::printf("Navigation   %zu samples, %.3f s to %.3f s, path %.2f m\n", s.nav_samples,
              s.nav_start_s, s.nav_end_s, s.nav_path_length_m);
  std::printf("  extent     north %.2f..%.2f  east %.2f..%.2f  down %.2f..%.2f m\n",
              s.nav_min_m.x(), s.nav_max_m.x(), s.nav_min_m.y(), s.nav_max_m.y(), s.nav_min_m.z(),
              s.nav_max_m.z());
  std::printf("Outside nav  %zu frames\n", s.frames_outside_nav.size());
  std::printf("Failed       %zu frames\n", s.frame_problems.size());
  for (const FrameProblem& p : s.frame_problems) {
    std::printf("  frame %zu: %s\n", p.index, p.message.c_str());
  }
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("info", "Summarise a mission: frames, sonar, navigation, errors");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("mission", *path, "Mission folder or its mission.yaml")->required();
  cmd->add_flag("--json", *json, "Print the summary as JSON for scripts");
  cmd->callback([path, json, &exit_code] {
    const Mission mission = readMission(*path);
    const MissionSummary summary = summarize(mission, true);
    if (*json) {
      std::cout << summaryJson(mission, summary).dump(2) << "\n";
    } else {
      printText(mission, summary);
    }
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
