// Mission format v1: a folder a person can read and edit (docs/formats.md):
//   mission.yaml   format name and version, sonar model, mounting, file names
//   nav.csv        navigation samples (see nav_csv.h)
//   frames.csv     frame index: time_s, sonar_id, file
//   frames/*.png   polar images, 16-bit PNG (see frame_png.h)
// readMission() reads the header, the navigation and the frame index eagerly and throws an
// Error for any problem in them; frame images are read on demand by loadFrame(), so a corrupt
// frame is reported and skipped by the caller, never fatal to a run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sonar/frame.h"
#include "sonar/mounting.h"
#include "sonar/nav_track.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

inline constexpr int kMissionFormatVersion = 1;
inline constexpr const char* kMissionFileName = "mission.yaml";

struct FrameRecord {
  double time_s = 0.0;
  std::string sonar_id;
  std::string file;    ///< relative to the mission folder
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

/// Loads frame `index`; throws Error naming the file if the image is unreadable, truncated,
/// corrupt or does not match the sonar model's size.
Frame loadFrame(const Mission& mission, std::size_t index);

/// Tries to load every frame; returns those that fail, in index order.
std::vector<FrameProblem> checkFrames(const Mission& mission);

}  // namespace sonarcarve
