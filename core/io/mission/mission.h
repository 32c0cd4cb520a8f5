// Mission format v1: a folder a person can read and edit (docs/formats.md):
//   mission.yaml   format name and version, sonar model, mounting, file names
//   nav.csv        navigation samples (see nav_csv.h)
//   frames.csv     frame index: time_s, sonar_id, file
//   frames/*.png   polar images, 16-bit PNG (see frame_png.h)
// readMission() reads the header, the navigation and the frame index eagerly and throws an
// Error for any problem in them; frame images are read on demand by loadFrame(), so a corrupt
// frame is reported and skipped by the caller, never fatal to a run.
//
// A Mission is also what any other recording opens as (io/frame_source.h: an Oculus log with a
// navigation CSV beside it): its `source` reads the frames, wherever they are.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sonar/frame.h"
#include "sonar/mission_origin.h"
#include "sonar/mounting.h"
#include "sonar/nav_track.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

inline constexpr int kMissionFormatVersion = 1;
inline constexpr const char* kMissionFileName = "mission.yaml";

class FrameSource;

struct FrameRecord {
  double time_s = 0.0;  ///< on the navigation's clock: authoritative over the source's
  std::string sonar_id;
  std::string file;    ///< relative to the mission folder; for other recordings, where in it
  int index_line = 0;  ///< line in the frame index, for messages
};

struct Mission {
  std::filesystem::path folder;
  std::string name;
  SonarModel sonar;
  Mounting mounting;
  NavTrack nav;
  std::vector<FrameRecord> frames;
  std::string nav_file = "nav.csv";
  std::string frame_index_file = "frames.csv";
  /// Reads the frames (a mission folder's PNGs, a vendor log's pings).
  std::shared_ptr<const FrameSource> source;
  /// What the reader assumed or skipped that the user should know (printed by the CLI,
  /// logged by the GUI).
  std::vector<std::string> warnings;
  /// What the recording holds beyond its frames, one line each (a bag's topics with their
  /// types and message counts, and the conventions assumed), for `info`.
  std::vector<std::string> contents;
  /// Subtracted from the navigation when it was read (sonar/mission_origin.h): the track, the
  /// map and every output are local to it; world NED = local + origin. Zero near zero.
  Eigen::Vector3d origin_ned_m = Eigen::Vector3d::Zero();
  /// The projected CRS whose grid the world frame is (north = northing, east = easting, down =
  /// depth; docs/conventions.md, "Geodetic navigation and CRSs"): mission.yaml's `crs`, or the
  /// UTM zone geodetic navigation was placed on. Empty: NED navigation without a CRS.
  std::string crs{};
};

/// A frame that could not be used, with the reason.
struct FrameProblem {
  std::size_t index = 0;
  std::string message;
};

/// Reads a mission from its folder or its mission.yaml. Throws Error (file, line, what was
/// expected) on a missing file, an unknown version, a missing column or key, a NaN, or times
/// going backwards.
Mission readMission(const std::filesystem::path& folder_or_yaml);

/// Loads frame `index` through the mission's source, as power (sonar/intensity_scale.h); throws
/// Error naming the file if the image is unreadable, truncated, corrupt, over the sonar's full
/// scale or does not match the sonar model's size.
Frame loadFrame(const Mission& mission, std::size_t index);

/// The source that reads a mission folder's PNG frames (readMission attaches it).
std::shared_ptr<const FrameSource> makeMissionFolderSource(const Mission& mission);

/// The mission's navigation in the world frame (its origin added back), as read.
NavTrack worldTrack(const Mission& mission);

/// Tries to load every frame; returns those that fail, in index order.
std::vector<FrameProblem> checkFrames(const Mission& mission);

}  // namespace sonarcarve
