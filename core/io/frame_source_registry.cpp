#include <mutex>

#include "common/angles.h"
#include "common/error.h"
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
      return reader.open(path, options);
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
                  {}};
  for (std::size_t k = 0; k < times_s.size(); ++k) {
    mission.frames.push_back({times_s[k], sonar.id(), label(k), 0});
  }
  return mission;
}

void applyOpenOptions(Mission& mission, const OpenOptions& options) {
  if (!options.nav_csv.empty()) {
    mission.nav = importNavCsv(options.nav_csv, options.nav_mapping);
    mission.nav_file = options.nav_csv.string();
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
