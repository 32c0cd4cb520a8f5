#include "io/mission/staged_mission.h"

#include <algorithm>

#include "common/error.h"
#include "io/mission/mission.h"

namespace sonarcarve {
namespace {

// The staged entries but mission.yaml, sorted: the order they are moved in.
std::vector<std::string> stagedNames(const StagedOutputs& staged) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(staged.staging())) {
    const std::string name = entry.path().filename().string();
    if (name != kMissionFileName) {
      names.push_back(name);
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

std::vector<std::filesystem::path> publishStagedMission(
    const StagedOutputs& staged, const std::vector<std::string>& earlier_files) {
  const std::vector<std::string> names = stagedNames(staged);
  // What is in the way of a move (a FIFO, a file where a folder goes) is refused before
  // anything moves: the earlier mission stays whole.
  for (const std::string& name : names) {
    staged.requireTarget(name);
  }
  staged.requireTarget(kMissionFileName);
  const std::filesystem::path mission_file = staged.folder() / kMissionFileName;
  std::error_code ec;
  if (std::filesystem::is_regular_file(std::filesystem::symlink_status(mission_file, ec))) {
    std::filesystem::remove(mission_file, ec);
  }
  try {
    for (const std::string& name : names) {
      if (std::filesystem::is_directory(staged.staging() / name, ec)) {
        staged.publishFolder(name);
      } else {
        staged.publish(name);
      }
    }
    staged.publish(kMissionFileName);
  } catch (const Error& e) {
    throw Error(e.source(), e.place(),
                e.message() + "; " + staged.folder().string() +
                    " holds no mission.yaml: part of the new mission may have been moved in");
  }
  std::vector<std::filesystem::path> removed;
  for (const std::string& name : earlier_files) {
    const std::filesystem::path path = staged.folder() / name;
    if (name != kMissionFileName && std::find(names.begin(), names.end(), name) == names.end() &&
        std::filesystem::exists(std::filesystem::symlink_status(path, ec)) &&
        std::filesystem::remove_all(path, ec) > 0) {
      removed.push_back(path);
    }
  }
  staged.sync();
  return removed;
}

}  // namespace sonarcarve
