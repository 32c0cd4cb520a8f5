#include "io/import.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <tuple>

#include "common/angles.h"
#include "common/error.h"
#include "io/files/output_folder.h"
#include "io/files/yaml_fields.h"
#include "io/mission/mission_writer.h"
#include "io/mission/sonar_yaml.h"

namespace sonarcarve {
namespace {

std::string kilohertz(double hz) {
  return std::isfinite(hz) && hz > 0.0 && hz < 1e9
             ? std::to_string(static_cast<long>(std::lround(hz / 1000.0))) + "khz"
             : "unknown";
}

}  // namespace

double oculusVerticalApertureDeg(const OculusPing& ping) {
  return ping.frequency_hz > 0.0 && ping.frequency_hz < 1.5e6 ? 20.0 : 12.0;
}

IntensityScale oculusIntensityScale(const OculusPing& ping) {
  const double full_scale = ping.sample_bytes == 2 ? 65535.0 : 255.0;
  return ping.gamma == 0
             ? IntensityScale::linear()
             : IntensityScale::gamma(std::round(ping.gamma / 255.0 * 1000.0) / 1000.0, full_scale);
}

OculusPingFormat oculusPingFormat(const OculusPing& ping) {
  IntensityScale::Key scale{-1.0, ping.gamma, ping.sample_bytes};  // a gamma that cannot be taken
  try {
    scale = oculusIntensityScale(ping).key();
  } catch (const Error&) {
  }
  return {ping.n_ranges, ping.n_beams, ping.range_resolution_m, ping.bearings_rad, scale};
}

OculusPingFormat oculusPingFormat(const SonarModel& sonar) {
  return {sonar.rows(), sonar.cols(), sonar.range().resolution_m, sonar.bearings().centres(),
          sonar.intensityScale().key()};
}

SonarModel sonarModelFromPing(const OculusPing& ping, std::optional<double> aperture_deg) {
  return SonarModel("oculus-" + kilohertz(ping.frequency_hz),
                    RangeBins{0.0, ping.range_resolution_m, ping.n_ranges},
                    BearingTable::fromCentres(ping.bearings_rad),
                    degToRad(aperture_deg.value_or(oculusVerticalApertureDeg(ping))))
      .withIntensityScale(oculusIntensityScale(ping));
}

OculusImportPlan planOculusImport(const OculusLog& log, double time_offset_s,
                                  std::optional<double> aperture_deg) {
  const auto& pings = log.pings();
  // The most common geometry (the first one on a tie); each ping's format taken once.
  std::vector<OculusPingFormat> formats;
  formats.reserve(pings.size());
  std::map<OculusPingFormat, std::size_t> counts;
  for (const auto& entry : pings) {
    ++counts[formats.emplace_back(oculusPingFormat(entry.ping))];
  }
  std::size_t best = 0;
  for (std::size_t i = 0; i < pings.size(); ++i) {
    if (counts[formats[i]] > counts[formats[best]]) {
      best = i;
    }
  }
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < pings.size(); ++i) {
    if (formats[i] == formats[best]) {
      used.push_back(i);
    }
  }
  const OculusPing& first = pings[used.front()].ping;
  const auto sonarModel = [&] {
    try {
      return sonarModelFromPing(first, aperture_deg);
    } catch (const Error& e) {
      throw Error(log.source(), "ping " + std::to_string(used.front()),
                  "gammaCorrection " + std::to_string(first.gamma) + ": " + e.message());
    }
  };
  OculusImportPlan plan{sonarModel(),
                        {},
                        {},
                        pings.size() - used.size(),
                        first.frequency_hz,
                        first.speed_of_sound_mps,
                        {}};
  if (plan.other_geometry > 0) {
    plan.warnings.push_back(
        std::to_string(plan.other_geometry) + " of " + std::to_string(pings.size()) +
        " pings have another range window, bearing table or sample "
        "scale than the main one (" +
        std::to_string(first.n_beams) + " beams x " + std::to_string(first.n_ranges) + " ranges, " +
        plan.sonar.intensityScale().describe() + ") and are left out");
  }
  if (!plan.sonar.intensityScale().isLinear()) {
    plan.warnings.push_back("the sonar sent its samples " + plan.sonar.intensityScale().describe() +
                            " (the fire message's gammaCorrection " + std::to_string(first.gamma) +
                            "): read back to its linear scale, which carving takes for power");
  }
  if (!std::is_sorted(used.begin(), used.end(), [&](std::size_t a, std::size_t b) {
        return pings[a].time_s < pings[b].time_s;
      })) {
    std::stable_sort(used.begin(), used.end(), [&](std::size_t a, std::size_t b) {
      return pings[a].time_s < pings[b].time_s;
    });
    plan.warnings.push_back("ping times are not in file order: frames are sorted by time");
  }
  for (std::size_t i : used) {
    plan.frame_times_s.push_back(pings[i].time_s + time_offset_s);
  }
  if (!aperture_deg) {
    plan.warnings.push_back("vertical aperture " +
                            shortestNumber(oculusVerticalApertureDeg(first)) +
                            " deg assumed from the frequency (" + kilohertz(first.frequency_hz) +
                            "); override it with --aperture-deg if your model differs");
  }
  plan.pings = std::move(used);
  return plan;
}

NavTrack stationaryTrack(const std::vector<double>& times_s) {
  const auto [lo, hi] = std::minmax_element(times_s.begin(), times_s.end());
  NavSample start, end;
  start.time_s = (times_s.empty() ? 0.0 : *lo) - 1.0;
  end.time_s = (times_s.empty() ? 0.0 : *hi) + 1.0;
  return NavTrack({start, end});
}

Mounting readMountingYaml(const std::filesystem::path& path) {
  const YamlFields fields(path.string());
  const YAML::Node root = fields.load();
  return root["mounting"] ? mountingFromYaml(root["mounting"], fields)
                          : mountingFromYaml(root, fields, "mounting");
}

namespace {

// The mission's files, into a folder made ready and held.
void writeMissionFiles(const ImportRequest& request, const SonarModel& sonar,
                       const Mounting& mounting, const NavTrack& nav, const std::string& crs,
                       std::size_t count, const std::function<Frame(std::size_t)>& frame_at,
                       Progress& progress, ImportReport& report) {
  const std::string name = request.name.empty() ? request.log.filename().string() : request.name;
  MissionWriter writer(request.out, name, sonar, mounting);
  for (std::size_t k = 0; k < count; ++k) {
    if (progress.cancelled()) {
      throw Cancelled();
    }
    progress.report("writing frames", k, count);
    Frame frame;
    try {
      frame = frame_at(k);
    } catch (const Error& e) {
      report.problems.push_back(std::string(e.what()) + " (frame skipped)");
      continue;
    }
    writer.addFrame(frame);
  }
  if (writer.frameCount() == 0) {
    throw Error(request.log.string(), "", "no frame could be decoded");
  }
  writer.finish(nav, crs);
  progress.report("writing frames", count, count);
  report.frames_written = writer.frameCount();
}

// Writes a mission folder (new or empty) of `count` frames, each as power (loadFrame's); a
// frame that cannot be read is reported in `report` and left out.
void writeMissionFolder(const ImportRequest& request, const SonarModel& sonar,
                        const Mounting& mounting, const NavTrack& nav, const std::string& crs,
                        std::size_t count, const std::function<Frame(std::size_t)>& frame_at,
                        Progress& progress, ImportReport& report) {
  const std::vector<std::filesystem::path> created = prepareOutputFolder(request.out);
  // Held before it is found empty: a second import into it fails instead of mixing its frames.
  const OutputFolderLock lock(request.out);
  std::error_code ec;
  if (!std::filesystem::is_empty(request.out, ec)) {
    throw Error(request.out.string(), "",
                "output folder exists and is not empty: choose a new folder");
  }
  try {
    writeMissionFiles(request, sonar, mounting, nav, crs, count, frame_at, progress, report);
  } catch (const Error& e) {
    // A mission cut short is no mission: the folder is left as the import found it.
    const bool removed = !removeCreatedFolders(created, true).empty();
    for (const auto& entry : std::filesystem::directory_iterator(request.out, ec)) {
      std::filesystem::remove_all(entry.path(), ec);  // the folder was empty before
    }
    throw Error(e.source(), e.place(),
                e.message() + (removed ? "; removed " : "; emptied ") + request.out.string() +
                    ", which held the import's partial mission");
  }
}

}  // namespace

ImportReport importOculusToMission(const ImportRequest& request, Progress& progress) {
  progress.report("reading the log", 0, 1);
  const OculusLog log = OculusLog::open(request.log);
  OculusImportPlan plan =
      planOculusImport(log, request.time_offset_s, request.vertical_aperture_deg);
  ImportReport report;
  report.mission = request.out;
  report.container = log.container();
  report.time_base = log.timeBase();
  report.pings_in_log = log.pings().size();
  report.notes = log.notes();
  report.problems = log.problems();
  report.warnings = plan.warnings;
  if (!log.skippedSummary().empty()) {
    report.warnings.push_back(log.skippedSummary());
  }

  // Everything that can fail on the user's input is read before the first file is written.
  const Mounting mounting =
      request.mounting_yaml.empty() ? Mounting{} : readMountingYaml(request.mounting_yaml);
  std::optional<NavTrack> nav;
  std::string crs;  // of geodetic or projected navigation's grid
  if (request.nav_csv.empty()) {
    nav = stationaryTrack(plan.frame_times_s);
    report.warnings.push_back(
        "no navigation given: the vehicle is stationary at the origin with zero attitude");
  } else {
    nav = importNavCsv(request.nav_csv, request.nav_mapping, &crs);
  }
  for (double t : plan.frame_times_s) {
    report.frames_outside_nav += nav->covers(t) ? 0 : 1;
  }
  if (report.frames_outside_nav > 0) {
    report.warnings.push_back(std::to_string(report.frames_outside_nav) +
                              " frames lie outside the navigation's time span (check the time "
                              "offset): they cannot be placed in the world");
  }
  writeMissionFolder(
      request, plan.sonar, mounting, *nav, crs, plan.pings.size(),
      [&](std::size_t k) {
        // As power, which the writer turns back into the sonar's own counts.
        cv::Mat image = log.decode(plan.pings[k]).image;
        plan.sonar.intensityScale().countsToPower(image, request.log.string(),
                                                  "ping " + std::to_string(plan.pings[k]));
        return Frame{plan.frame_times_s[k], plan.sonar.id(), image};
      },
      progress, report);
  return report;
}

ImportReport importRecordingToMission(const ImportRequest& request, const OpenOptions& options,
                                      Progress& progress) {
  progress.report("reading the recording", 0, 1);
  const Mission mission = openMission(request.log, options);
  ImportReport report;
  report.mission = request.out;
  report.container = mission.source->kind();
  report.time_base = "the recording's own";
  report.pings_in_log = mission.frames.size();
  report.notes = mission.contents;
  report.warnings = mission.warnings;
  for (const FrameRecord& frame : mission.frames) {
    report.frames_outside_nav += mission.nav.covers(frame.time_s) ? 0 : 1;
  }
  writeMissionFolder(
      request, mission.sonar, mission.mounting, worldTrack(mission), mission.crs,
      mission.frames.size(), [&](std::size_t k) { return loadFrame(mission, k); }, progress,
      report);
  return report;
}

}  // namespace sonarcarve
