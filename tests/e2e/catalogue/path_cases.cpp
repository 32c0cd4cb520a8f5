// Class "paths" (issue 44): a mission's frames reached through symbolic links, and paths whose
// bytes are not UTF-8. Containment is checked on the path a frame's links resolve to: a
// `frames` folder that is a link to "/" (or anywhere outside the mission) is refused like
// "../", unless the mission allows files outside its folder; links that stay inside are
// followed. A run into, or from, a path that is not UTF-8 keeps its results: the JSON it writes
// holds U+FFFD for each byte that is not UTF-8.
#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {
namespace {

constexpr const char* kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

// Replaces the mission's frames folder by a link to `target` (made by `make` first).
CatalogueCase linkedFrames(const std::string& name, const std::string& target,
                           std::function<void(const Workspace&)> make, Outcome outcome,
                           const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [target, make](const Workspace& ws) {
                make(ws);
                std::filesystem::remove_all(ws.mission() / "frames");
                std::filesystem::create_symlink(target, ws.mission() / "frames");
                return std::string("info mission");
              },
          .outcome = outcome,
          .message = message};
}

void moveFramesTo(const Workspace& ws, const std::string& relative) {
  std::filesystem::create_directories((ws / relative).parent_path());
  std::filesystem::copy(ws.mission() / "frames", ws / relative,
                        std::filesystem::copy_options::recursive);
}

// The mission renamed "mission\xE9" (Latin-1 e acute: not UTF-8), then `command` on it.
std::string renamedMission(const Workspace& ws, const std::string& command,
                           const std::string& flags) {
  std::filesystem::rename(ws.mission(), ws / "mission\xE9");
  return command + " 'mission\xE9'" + flags;
}

const std::string kLeadsOut =
    "', outside the mission folder, through a symbolic link: expected a path inside it (or "
    "frames.files_outside_folder: allowed in mission.yaml)";

}  // namespace

std::vector<CatalogueCase> pathCases() {
  return {
      linkedFrames("FramesFolderLinkedToRoot", "/", [](const Workspace&) {}, Outcome::Fails,
                   {"frames.csv: line 2: column 'file': 'frames/000000.png' leads to "
                    "'/000000.png" +
                    kLeadsOut}),
      linkedFrames("FramesFolderLinkedOutside", "../elsewhere",
                   [](const Workspace& ws) { moveFramesTo(ws, "elsewhere"); }, Outcome::Fails,
                   {"frames.csv: line 2: column 'file': 'frames/000000.png' leads to '",
                    "elsewhere/000000.png" + kLeadsOut}),
      linkedFrames("FramesFolderLinkedInside", "data/frames",
                   [](const Workspace& ws) { moveFramesTo(ws, "mission/data/frames"); },
                   Outcome::Succeeds, {"10 frames"}),
      {.name = "FramesFolderLinkedOutsideAllowed",
       .prepare =
           [](const Workspace& ws) {
             moveFramesTo(ws, "elsewhere");
             std::filesystem::remove_all(ws.mission() / "frames");
             std::filesystem::create_symlink("../elsewhere", ws.mission() / "frames");
             replaceIn(ws.mission() / "mission.yaml", "encoding: png16}",
                       "encoding: png16, files_outside_folder: allowed}");
             return std::string("info mission");
           },
       .outcome = Outcome::Succeeds,
       .message = {"10 frames"}},
      {.name = "FrameFileLinkedOutside",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "outside.png", readText(ws.mission() / "frames/000003.png"));
             std::filesystem::remove(ws.mission() / "frames/000003.png");
             std::filesystem::create_symlink(ws / "outside.png",
                                             ws.mission() / "frames/000003.png");
             return std::string("reconstruct mission --out out");
           },
       .message = {"frames.csv: line 5: column 'file': 'frames/000003.png' leads to '",
                   "outside.png" + kLeadsOut},
       .absent = {"out"}},
      {.name = "ReconstructIntoANonUtf8Folder",
       .prepare =
           [](const Workspace&) { return std::string("reconstruct mission --out 'out\xE9'"); },
       .outcome = Outcome::Succeeds,
       .message = {"\"frames_used\""},
       .holds = {{"out\xE9/report.json", "\"frames_used\""},
                 {"out\xE9/manifest.json", std::string("\"out") + kReplacement + "\""},
                 {"out\xE9/manifest.json", "\"complete\""}}},
      {.name = "ReconstructANonUtf8Mission",
       .prepare =
           [](const Workspace& ws) { return renamedMission(ws, "reconstruct", " --out out"); },
       .outcome = Outcome::Succeeds,
       .message = {"\"frames_used\""},
       .holds = {{"out/report.json", "\"frames_used\""},
                 {"out/manifest.json", std::string("\"mission") + kReplacement + "\""}}},
      {.name = "InfoJsonOfANonUtf8Mission",
       .prepare = [](const Workspace& ws) { return renamedMission(ws, "info --json", ""); },
       .outcome = Outcome::Succeeds,
       .message = {"\"failed\": []"}},
  };
}

}  // namespace sonarcarve::test
