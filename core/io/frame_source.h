// FrameSource: where a mission's sonar frames come from, and the registry of readers that
// open a recording by its content. A mission folder (PNG frames), an Oculus log, ROS 2
// bags or ARIS files all become a Mission whose frames a FrameSource reads on demand, so the
// pipeline, the CLI and the GUI work on any of them without conversion.
//
// Adding a reader is one file and one registration line (docs/architecture.md):
//   [[maybe_unused]] const bool registered = registerFrameSourceReader({"name", recognise, open});
// openMission() asks each reader, in registration order, whether it recognises the path by
// its content (magic bytes, a mission.yaml), and opens it with the first that does.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/mission/mission.h"
#include "io/mission/nav_import.h"
#include "io/rosbag/bag_options.h"

namespace sonarcarve {

/// Random access to a recording's frames (streaming is access in index order). Frames are
/// numbered 0..size()-1 in time order; load() reads, decodes and checks one frame. Thread
/// safe: load() may run concurrently (the GUI reads frames while the pipeline carves).
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// What kind of recording this is, in words ("mission folder", "oculus messages", ...).
  virtual std::string kind() const = 0;
  virtual std::size_t size() const = 0;
  /// Frame `index` with its time on the navigation's clock, in the sonar's counts (loadFrame
  /// converts them to power by the sonar's intensity scale). Throws Error naming the file and
  /// the frame if it cannot be read or does not match the sonar.
  virtual Frame load(std::size_t index) const = 0;
};

/// What a recording without its own navigation needs, and overrides for those that have it.
struct OpenOptions {
  std::filesystem::path nav_csv;   ///< navigation CSV; empty: the recording's own, if any
  NavMapping nav_mapping;          ///< how to read nav_csv (default: nav.csv's own columns)
  std::filesystem::path mounting;  ///< mounting YAML; empty: the recording's own, or aligned
  double time_offset_s = 0.0;      ///< added to the recording's frame times
  std::optional<double> vertical_aperture_deg;  ///< override for sonars that do not say
  /// Override of the elevation beam (recordings do not say: a real array's is MainLobe, the
  /// default; a simulator's may be Clipped).
  std::optional<ElevationBeam> elevation_beam;
  BagOptions bag;  ///< topics and conventions of a ROS 2 bag
};

struct FrameSourceReader {
  std::string name;  ///< short, for messages: "mission folder", "oculus"
  /// True if `path` is this reader's kind, judged by content (cheap: first bytes, a file name
  /// inside a folder). Must not throw.
  std::function<bool(const std::filesystem::path& path)> recognises;
  /// Opens `path` as a Mission whose `source` reads the frames. Throws Error on bad input.
  std::function<Mission(const std::filesystem::path& path, const OpenOptions& options)> open;
};

/// Adds a reader after those registered before it. Returns true (for a registration line).
bool registerFrameSourceReader(FrameSourceReader reader);
/// The registered readers' names, in the order they are asked.
std::vector<std::string> frameSourceReaderNames();

/// The name of the first registered reader that recognises `path`, if any. Never throws.
std::optional<std::string> recognisingReader(const std::filesystem::path& path);

/// Opens a mission folder, its mission.yaml or any recording a registered reader recognises.
/// Throws Error naming the path and the kinds known when no reader recognises it.
Mission openMission(const std::filesystem::path& path, const OpenOptions& options = {});

/// The mission of a recording opened in place, before its navigation: named after the file,
/// with `sonar`, one frame record per time (labelled by `label(k)`: "ping 12") and a vehicle
/// stationary at the origin over those times. The reader then sets its source, warnings and
/// navigation.
Mission recordingMission(const std::filesystem::path& path, const SonarModel& sonar,
                         const std::vector<double>& times_s,
                         const std::function<std::string(std::size_t)>& label);

/// Refuses a navigation position that makes no physical sense (naming the navigation file and
/// the sample), then moves a mission whose navigation lies far from zero to its origin
/// (sonar/mission_origin.h): the track minus the origin, in double, and the origin added to
/// `origin_ned_m`. A mission near zero is left as it is; calling it again changes nothing.
/// openMission calls it for every reader.
void placeMissionNearOrigin(Mission& mission);

/// Applies the options' navigation, mounting and time offset to an opened mission (readers
/// call it; a navigation or mounting given by the user replaces the recording's own).
void applyOpenOptions(Mission& mission, const OpenOptions& options);
/// Only the options' navigation, mounting and elevation beam (for readers that apply the time
/// offset and the aperture while building the mission).
void applyNavigationAndMounting(Mission& mission, const OpenOptions& options);

}  // namespace sonarcarve
