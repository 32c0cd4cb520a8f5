// Class "messages that name the real cause" (issue 44): a frame selection that holds no frame,
// frames outside the navigation's clock, a region of interest outside the views, a range window
// emptied by the parameters, a negative or missing frame index, a map to start from of another
// grid or for another engine. Each message names the parameter or the file and what was
// expected, not a later symptom ("no frame can be placed", "merge", an index of 2^64 - 1).
#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {
namespace {

CatalogueCase reconstructWith(const std::string& name, const std::string& flags,
                              const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [flags](const Workspace&) { return "reconstruct mission " + flags + " --out out"; },
          .message = message,
          .absent = {"out"}};  // made by the run, removed when it failed (failed_run_cases.cpp)
}

// A run that starts from the example mission's saved map (carved at the default 2 cm).
CatalogueCase fromSavedMap(const std::string& name, const std::string& flags,
                           const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [flags](const Workspace& ws) {
                runCliIn(ws, "reconstruct mission --save-map --out first");
                return "reconstruct mission --load-map first/map.scmap " + flags + " --out out";
              },
          .message = message,
          .absent = {"out"}};
}

CatalogueCase frameIndex(const std::string& name, const std::string& index,
                         const std::vector<std::string>& message) {
  return {
      .name = name,
      .prepare =
          [index](const Workspace&) { return "frame mission --index " + index + " --fan fan.png"; },
      .message = message,
      .absent = {"fan.png"}};
}

}  // namespace

std::vector<CatalogueCase> messageCases() {
  const std::string selection = "parameters: frames: the selection from frame ";
  return {
      // A SonarCarve file of another kind given as --params is named as what it is, not by its
      // `format` key as unknown.
      {.name = "ParamsFileThatIsASession",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "session.yaml",
                        "format: sonarcarve-session\nversion: 1\nmission: mission\nframe: 2\n"
                        "params: {voxel_size_m: 0.05}\n");
             return std::string("reconstruct mission --params session.yaml --out out");
           },
       .message = {"session.yaml: line 1: format: the file says it is a sonarcarve-session file, "
                   "not a parameters file: expected a parameters YAML",
                   "a session holds one as its params"},
       .absent = {"out"}},
      reconstructWith("ParamsFileThatIsAMission", "--params mission/mission.yaml",
                      {"mission.yaml: line 2: format: the file says it is a sonarcarve-mission "
                       "file, not a parameters file"}),
      // A parameter the chosen engine does not apply is said, not left out without a word.
      {.name = "FitAskedOfTheReferenceEngineIsSaid",
       .prepare =
           [](const Workspace&) {
             return std::string("reconstruct mission --engine reference --fit true --out out");
           },
       .outcome = Outcome::Succeeds,
       .message = {"warning: fit: off: fit.enabled asks it, but the fit works on the fast "
                   "engine's map: the reference engine's surface is kept"},
       .holds = {{"out/report.json", "\"name\": \"fit\""}}},
      reconstructWith("SelectionPastTheLastFrame", "--first-frame 20",
                      {selection + "20 to the end (exclusive) holds none of the mission's 10 "
                                   "frames",
                       "expected frames.first (--first-frame) below 10"}),
      reconstructWith(
          "SelectionOfNoFrame", "--first-frame 5 --last-frame 5",
          {selection + "5 to 5 (exclusive) holds none", "and below frames.last (--last-frame)"}),
      reconstructWith("SelectionEndingAtZero", "--last-frame 0",
                      {selection + "0 to 0 (exclusive) holds none"}),
      reconstructWith("FramesOffTheNavigationClock", "--time-offset 1000",
                      {"mission: navigation: no selected frame lies within the navigation track "
                       "(t = 99.75 to 104.75 s)",
                       "expected frame times on the navigation's clock (--time-offset)"}),
      reconstructWith("RegionOutsideEveryView", "--region 100 100 100 101 101 101",
                      {"parameters: region: the region of interest [100 100 100] to [101 101 101] "
                       "m is outside every frame's view (they span [",
                       "expected a region that overlaps them"}),
      reconstructWith("RangeMinPastTheSonar", "--range-min 7",
                      {"parameters: range window: with range_min_m 7, nothing is left of the "
                       "sonar's ranges 1 to 6 m",
                       "expected range_min_m below range_max_m"}),
      reconstructWith("RangeMaxBeforeTheSonar", "--range-max 0.5",
                      {"with range_max_m 0.5, nothing is left of the sonar's ranges 1 to 6 m"}),
      reconstructWith("RangeMinAboveRangeMax", "--range-min 4 --range-max 3",
                      {"parameters: range_max_m: expected 0 (the sonar's) or above range_min_m"}),
      frameIndex("FrameIndexNegative", "-1",
                 {"--index: expected a frame index of 0 or more, got -1"}),
      frameIndex("FrameIndexPastTheEnd", "10",
                 {"mission: frame 10: no such frame: the mission has 10"}),
      fromSavedMap("LoadMapOfAnotherVoxelSize", "--voxel-size 0.05",
                   {"first/map.scmap: voxel_size_m: the map has voxels of 0.02 m, this run "
                    "carves 0.05 m: expected the same voxel size (--voxel-size 0.02)"}),
      fromSavedMap("LoadMapWithTheReferenceEngine", "--engine reference",
                   {"first/map.scmap: engine: a run can start from a saved map with the fast "
                    "engine only, not reference: expected --engine fast"}),
      {.name = "LoadMapNotAMap",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "map.scmap", "not a map\n");
             return std::string("reconstruct mission --load-map map.scmap --out out");
           },
       .message = {"map.scmap: byte 0: not a SonarCarve map file: expected it to start with SCMAP"},
       .absent = {"out"}},
      reconstructWith("SurfaceOnlyWithoutAMap", "--surface-only",
                      {"--surface-only: needs --load-map"}),
  };
}

}  // namespace sonarcarve::test
