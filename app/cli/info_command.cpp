// `sonarcarve-cli info MISSION|LOG [--json]`: what a mission, or a vendor log before import,
// holds and what is wrong with it. Both go through the same summary (MissionSummary): a log
// is summarised as `import` would write it, with a stationary vehicle when it has no
// navigation.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/source_flags.h"
#include "common/angles.h"
#include "common/error.h"
#include "geo/crs.h"
#include "io/files/json_text.h"
#include "io/frame_source.h"
#include "io/import.h"
#include "io/mission/mission.h"
#include "io/mission/mission_summary.h"
#include "io/oculus/oculus_log.h"
#include "io/rosbag/bag_summary.h"
#include "io/rosbag/ros_bag.h"
#include "pipeline/frame_stage.h"
#include "pipeline/reconstruction.h"
#include "sonar/bearing_deblur.h"
#include "sonar/mission_origin.h"

namespace sonarcarve::cli {
namespace {

nlohmann::json vectorJson(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

nlohmann::json summaryJson(const SonarModel& sonar, const MissionSummary& s) {
  nlohmann::json problems = nlohmann::json::array();
  for (const FrameProblem& p : s.frame_problems) {
    problems.push_back({{"index", p.index}, {"error", p.message}});
  }
  return {
      {"name", s.name},
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
        {"vertical_aperture_deg", radToDeg(sonar.verticalAperture())},
        {"horizontal_beam_width_deg",  // null: the mission does not say
         sonar.horizontalBeamWidth() > 0.0 ? nlohmann::json(radToDeg(sonar.horizontalBeamWidth()))
                                           : nlohmann::json(nullptr)},
        {"intensity_scale", sonar.intensityScale().describe()}}},
      {"navigation",
       {{"samples", s.nav_samples},
        {"start_s", s.nav_start_s},
        {"end_s", s.nav_end_s},
        {"min_ned_m", vectorJson(s.nav_min_m)},
        {"max_ned_m", vectorJson(s.nav_max_m)},
        {"path_length_m", s.nav_path_length_m}}},
  };
}

void printText(const SonarModel& sonar, const MissionSummary& s) {
  std::printf("Frames       %zu, %.3f s to %.3f s (%.3f s)\n", s.frame_count, s.first_frame_time_s,
              s.last_frame_time_s, s.duration_s);
  std::printf("Sonar        %s: %d beams x %d range bins\n", sonar.id().c_str(), sonar.cols(),
              sonar.rows());
  std::printf("  range      %.3f to %.3f m, resolution %.4g m\n", sonar.range().min_m,
              sonar.range().maxRange(), sonar.range().resolution_m);
  std::printf("  bearing    %s table, %.2f to %.2f deg (field of view %.2f deg)\n",
              sonar.bearings().isUniform() ? "uniform" : "explicit",
              radToDeg(sonar.bearings().centre(0)),
              radToDeg(sonar.bearings().centre(sonar.cols() - 1)),
              radToDeg(sonar.bearings().fieldOfView()));
  if (sonar.horizontalBeamWidth() > 0.0) {
    std::printf("  beams      %.2f deg wide (-3 dB)%s\n", radToDeg(sonar.horizontalBeamWidth()),
                BearingDeblur(sonar).active() ? ": their blur across bearing is taken out" : "");
  }
  std::printf("  aperture   %.2f deg vertical (-3 dB, %s)\n", radToDeg(sonar.verticalAperture()),
              sonar.elevationBeam() == ElevationBeam::Clipped ? "clipped" : "sinc");
  std::printf("  intensity  %s\n", sonar.intensityScale().describe().c_str());
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

// The first frames' times (all of a short recording), seconds on the navigation clock.
void printFrameTimes(const Mission& mission) {
  constexpr std::size_t kShown = 10;
  std::printf("Frame times ");
  for (std::size_t k = 0; k < mission.frames.size() && k < kShown; ++k) {
    std::printf(" %.6f", mission.frames[k].time_s);
  }
  std::printf("%s s\n", mission.frames.size() > kShown ? " ..." : "");
}

std::vector<std::string> linesOf(const std::vector<std::string>& a,
                                 const std::vector<std::string>& b) {
  std::vector<std::string> all = a;
  all.insert(all.end(), b.begin(), b.end());
  return all;
}

void infoOnLog(const std::string& path, bool json, double aperture_deg) {
  const OculusLog log = OculusLog::open(path);
  const OculusImportPlan plan = planOculusImport(
      log, 0.0, aperture_deg > 0.0 ? std::optional<double>(aperture_deg) : std::nullopt);
  const MissionSummary summary =
      summarizeFrames(std::filesystem::path(path).filename().string(), plan.frame_times_s,
                      stationaryTrack(plan.frame_times_s));
  const std::vector<std::string> warnings = linesOf(
      plan.warnings, {"no navigation in the log: the vehicle is summarised as stationary at the "
                      "origin"});
  if (json) {
    nlohmann::json j = summaryJson(plan.sonar, summary);
    j["log"] = {{"file", path},
                {"container", log.container()},
                {"time_base", log.timeBase()},
                {"pings", log.pings().size()},
                {"pings_other_geometry", plan.other_geometry},
                {"frequency_hz", plan.frequency_hz},
                {"speed_of_sound_mps", plan.speed_of_sound_mps},
                {"problems", log.problems()},
                {"skipped",
                 {{"bytes", log.skipped().bytes},
                  {"messages", log.skipped().messages},
                  {"resyncs", log.skipped().resyncs}}},
                {"notes", log.notes()},
                {"warnings", warnings}};
    std::cout << jsonText(j) << "\n";
    return;
  }
  std::printf("Log          %s (%s, %zu pings)\n", path.c_str(), log.container().c_str(),
              log.pings().size());
  printText(plan.sonar, summary);
  std::printf("  frequency  %.1f kHz, sound speed %.2f m/s\n", plan.frequency_hz / 1000.0,
              plan.speed_of_sound_mps);
  std::printf("Times        %s\n", log.timeBase().c_str());
  std::printf("Problems     %zu\n", log.problems().size());
  for (const std::string& p : log.problems()) {
    std::printf("  %s\n", p.c_str());
  }
  std::printf("Skipped      %zu bytes, %zu messages, %zu resyncs\n", log.skipped().bytes,
              log.skipped().messages, log.skipped().resyncs);
  for (const std::string& line : linesOf(log.notes(), warnings)) {
    std::printf("Note         %s\n", line.c_str());
  }
}

// A ROS 2 bag without a sonar topic is still listed (topics, types, message counts), with a
// note that it has nothing to reconstruct. Returns false if the bag has a sonar topic (its
// error when opening it as a mission is then the answer).
bool infoOnBagWithoutSonar(const std::string& path, bool json) {
  const std::unique_ptr<RosBag> bag = openRosBag(path);
  const BagTopicKinds kinds(*bag);
  if (kinds.anySonar()) {
    return false;
  }
  const std::vector<std::string> contents = bagTopicLines(*bag, kinds);
  std::vector<std::string> notes = bag->problems();
  notes.insert(notes.begin(),
               "no sonar topic (marine_acoustic_msgs/msg/ProjectedSonarImage, "
               "acoustic_msgs/msg/SonarImage or raw Oculus pings): nothing to reconstruct");
  if (json) {
    const nlohmann::json j = {{"folder", path},
                              {"source", "ROS 2 bag, " + bag->storage()},
                              {"frames", {{"count", 0}}},
                              {"contents", contents},
                              {"warnings", notes}};
    std::cout << jsonText(j) << "\n";
    return true;
  }
  std::printf("Bag          %s (ROS 2 bag, %s)\n", path.c_str(), bag->storage().c_str());
  for (const std::string& line : contents) {
    std::printf("Recording    %s\n", line.c_str());
  }
  for (const std::string& note : notes) {
    std::printf("Note         %s\n", note.c_str());
  }
  return true;
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "info", "Summarise a mission or a vendor log: frames, sonar, navigation, errors");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto source = std::make_shared<SourceFlags>();
  cmd->add_option("mission", *path,
                  "Mission folder or its mission.yaml, or a vendor log (Oculus messages, "
                  ".oculus or .aris recording, ROS 2 bag: .mcap, .db3 or its folder)")
      ->required();
  cmd->add_flag("--json", *json, "Print the summary as JSON for scripts");
  addSourceFlags(*cmd, *source);
  cmd->callback([path, json, source, &exit_code] {
    const OpenOptions options = openOptionsFrom(*source);
    if (looksLikeOculusLog(*path) && options.nav_csv.empty()) {
      infoOnLog(*path, *json, source->aperture_deg);
      exit_code = 0;
      return;
    }
    std::unique_ptr<const Mission> opened;
    try {
      opened = std::make_unique<const Mission>(openMission(*path, options));
    } catch (const Error&) {
      // A valid bag without a sonar topic is listed rather than refused.
      if (looksLikeRosBag(*path) && options.bag.sonar_topic.empty() &&
          infoOnBagWithoutSonar(*path, *json)) {
        exit_code = 0;
        return;
      }
      throw;
    }
    const Mission& mission = *opened;
    const MissionSummary summary = summarize(mission, true);
    // A mission that does not say how wide its beams are: what a run at the default
    // parameters reads from the frames it places.
    SilentProgress silent;
    const BeamWidthChoice beams = chooseBeamWidth(
        mission, mission.sonar, placedFrames(mission, ReconstructionParams{}), silent);
    if (*json) {
      nlohmann::json j = summaryJson(mission.sonar, summary);
      // Beside the sonar's own fields, which a log's summary shares (before import).
      j["beam_width"] = {{"read_deg",  // null: given, or none read
                          beams.reason.empty() || !(beams.sonar.horizontalBeamWidth() > 0.0)
                              ? nlohmann::json(nullptr)
                              : nlohmann::json(radToDeg(beams.sonar.horizontalBeamWidth()))},
                         {"reading", beams.reason}};
      j["folder"] = mission.folder.string();
      j["source"] = mission.source->kind();
      j["warnings"] = mission.warnings;
      j["contents"] = mission.contents;
      if (!mission.crs.empty()) {  // absent for NED navigation without a CRS, as before
        j["crs"] = mission.crs;
        j["origin_ned_m"] = vectorJson(mission.origin_ned_m);
      }
      std::cout << jsonText(j) << "\n";
    } else {
      std::printf("Mission      %s (%s, %s)\n", summary.name.c_str(),
                  mission.folder.string().c_str(), mission.source->kind().c_str());
      printText(mission.sonar, summary);
      if (!beams.reason.empty()) {
        std::printf("  beams      %s%s\n", beams.reason.c_str(),
                    BearingDeblur(beams.sonar).active()
                        ? "; a run takes their blur across bearing out"
                        : "");
      }
      printFrameTimes(mission);
      if (!mission.crs.empty()) {
        std::printf(
            "CRS          %s (%s): world north, east = its northing, easting; mission "
            "origin %s\n",
            mission.crs.c_str(), crsName(mission.crs).c_str(),
            nedText(mission.origin_ned_m).c_str());
      }
      for (const std::string& line : mission.contents) {
        std::printf("Recording    %s\n", line.c_str());
      }
      for (const std::string& warning : mission.warnings) {
        std::printf("Note         %s\n", warning.c_str());
      }
    }
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
