// MissionWriter: writes a mission folder in format v1, frame by frame.
// Each file is written atomically; mission.yaml is written last, by finish(), so a folder
// without it is an unfinished write, never a mission that reads as complete.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/mission/mission.h"

namespace sonarcarve {

class MissionWriter {
 public:
  /// Creates `folder` and its frames/ subfolder (throws Error if it cannot).
  MissionWriter(std::filesystem::path folder, std::string name, SonarModel sonar,
                Mounting mounting);

  /// Writes the frame's image as frames/NNNNNN.png. Throws Error if its size does not match
  /// the sonar model or a value cannot be stored (NaN, negative, above 65535).
  void addFrame(const Frame& frame);
  /// Writes nav.csv, frames.csv and mission.yaml; a `crs` (Mission::crs: the grid the world
  /// NED navigation is on) goes into mission.yaml, so that the mission reads back on it.
  void finish(const NavTrack& nav, const std::string& crs = "");

  std::size_t frameCount() const { return records_.size(); }

 private:
  std::filesystem::path folder_;
  std::string name_;
  SonarModel sonar_;
  Mounting mounting_;
  std::vector<FrameRecord> records_;
};

}  // namespace sonarcarve
