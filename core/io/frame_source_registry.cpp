#include <mutex>

#include "common/angles.h"
#include "common/error.h"
#include "common/number_text.h"
#include "io/files/input_file.h"
#include "io/frame_source.h"
#include "io/import.h"
#include "io/mission/nav_import.h"

namespace sonarcarve {
namespace {

// Function-local: readers register from static initialisers of other files.
struct Registry {
  std::mutex mutex;
  std::vector<FrameSourceReader> readers;
};

Registry& registry() {
  static Registry instance;
  return instance;
}

std::vector<FrameSourceReader> readers() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  return r.readers;
}

}  // namespace

bool registerFrameSourceReader(FrameSourceReader reader) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.readers.push_back(std::move(reader));
  return true;
}

std::vector<std::string> frameSourceReaderNames() {
  std::vector<std::string> names;
  for (const FrameSourceReader& reader : readers()) {
    names.push_back(reader.name);
  }
  return names;
}

std::optional<std::string> recognisingReader(const std::filesystem::path& path) {
  for (const FrameSourceReader& reader : readers()) {
    if (reader.recognises(path)) {
      return reader.name;
    }
  }
  return std::nullopt;
}

Mission openMission(const std::filesystem::path& path, const OpenOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw Error(path.string(), "", "no such file or folder");
  }
  if (!std::filesystem::is_directory(path, ec)) {
    requireRegularFile(path, "a mission folder or a recording file");
  }
  std::string known;
  for (const FrameSourceReader& reader : readers()) {
    if (reader.recognises(path)) {
      Mission mission = reader.open(path, options);
      placeMissionNearOrigin(mission);
      return mission;
    }
    known += (known.empty() ? "" : ", ") + reader.name;
  }
  throw Error(path.string(), "",
              "not a recording this build reads (expected one of: " + known + ")");
}

Mission recordingMission(const std::filesystem::path& path, const SonarModel& sonar,
                         const std::vector<double>& times_s,
                         const std::function<std::string(std::size_t)>& label) {
  Mission mission{path,
                  path.filename().string(),
                  sonar,
                  Mounting{},
                  stationaryTrack(times_s),
                  {},
                  "",
                  "",
                  nullptr,
                  {},
                  {},
                  Eigen::Vector3d::Zero(),
                  {}};
  for (std::size_t k = 0; k < times_s.size(); ++k) {
    mission.frames.push_back({times_s[k], sonar.id(), label(k), 0});
  }
  return mission;
}

void placeMissionNearOrigin(Mission& mission) {
  // The navigation file when it is one (nav.csv, --nav), else the recording and its source.
  std::error_code ec;
  const std::filesystem::path joined = mission.folder / mission.nav_file;
  const std::string file =
      !mission.nav_file.empty() && std::filesystem::is_regular_file(joined, ec)
          ? joined.string()
          : mission.folder.string() + " (navigation: " + mission.nav_file + ")";
  const std::vector<NavSample>& samples = mission.nav.samples();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    requirePlausiblePosition(samples[i].position_m, file,
                             "navigation sample " + std::to_string(i) +
                                 " (t = " + shortestNumber(samples[i].time_s) + " s)");
  }
  if (const auto problem = mountingOffsetProblem(mission.mounting.translation_m)) {
    throw Error(mission.folder.string(), "mounting translation_m", *problem);
  }
  const Eigen::Vector3d origin = chooseMissionOrigin(mission.nav);
  if (origin.isZero()) {
    return;
  }
  mission.nav = translatedTrack(mission.nav, -origin);
  mission.origin_ned_m += origin;
}

void applyOpenOptions(Mission& mission, const OpenOptions& options) {
  if (!options.nav_csv.empty()) {
    mission.nav = importNavCsv(options.nav_csv, options.nav_mapping, &mission.crs);
    mission.nav_file = options.nav_csv.string();
    mission.origin_ned_m = Eigen::Vector3d::Zero();  // the recording's own navigation's
  }
  if (!options.mounting.empty()) {
    mission.mounting = readMountingYaml(options.mounting);
  }
  if (options.time_offset_s != 0.0) {
    for (FrameRecord& record : mission.frames) {
      record.time_s += options.time_offset_s;
    }
  }
  if (options.vertical_aperture_deg) {
    mission.sonar = mission.sonar.withVerticalAperture(degToRad(*options.vertical_aperture_deg));
  }
  if (options.elevation_beam) {
    mission.sonar = mission.sonar.withElevationBeam(*options.elevation_beam);
  }
}

void applyNavigationAndMounting(Mission& mission, const OpenOptions& options) {
  OpenOptions rest = options;
  rest.time_offset_s = 0.0;
  rest.vertical_aperture_deg.reset();
  applyOpenOptions(mission, rest);
}

}  // namespace sonarcarve
