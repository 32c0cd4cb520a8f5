// Class "inputs are what they claim": a directory, a FIFO or a device where each reader expects
// a file. Every one is refused with the file's name and what was expected; none blocks.
#include "e2e/catalogue/catalogue.h"
#include "support/cli_runner.h"

namespace sonarcarve::test {
namespace {

struct Input {
  std::string name;
  std::string file;  ///< under the workspace, replaced by the non-file
  /// Writes the other inputs; returns the arguments.
  std::function<std::string(const Workspace&)> prepare;
  Outcome outcome = Outcome::Fails;
  std::vector<std::string> absent = {};
  bool directory_is_a_folder_input = false;  ///< a directory there means something else
};

std::string evaluateArgs(const Workspace& ws) {
  writeBytes(ws / "reference.ply", tetrahedronPly());
  writeBytes(ws / "points.ply", asciiPly({{2, 0, 10}, {2.05, 0.01, 10}}));
  writeBytes(ws / "visible.ply", asciiPly({{2, 0, 10}}));
  return "evaluate --reference reference.ply --reconstruction points.ply --visible visible.ply";
}

std::string recordingArgs(const Workspace& ws, const std::string& extra) {
  std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "ping.raw");
  std::filesystem::copy_file(ws.mission() / "nav.csv", ws / "nav.csv");
  return "info ping.raw --nav nav.csv" + extra;
}

std::vector<Input> inputs() {
  const auto info = [](const Workspace&) { return std::string("info mission"); };
  return {
      {"FrameWithFrame",
       "mission/frames/000003.png",
       [](const Workspace&) {
         return std::string("frame mission --index 3 --polar polar.png --fan fan.png");
       },
       Outcome::Fails,
       {"polar.png", "fan.png"}},
      // info and reconstruct report a frame that cannot be read and use the others.
      {"FrameWithInfo", "mission/frames/000003.png", info, Outcome::Succeeds},
      {"FrameWithReconstruct", "mission/frames/000003.png",
       [](const Workspace&) { return std::string("reconstruct mission --out out"); },
       Outcome::Succeeds},
      {"NavCsv", "mission/nav.csv", info},
      {"FrameIndex", "mission/frames.csv", info},
      {"MissionYaml", "mission/mission.yaml", info},
      {"ParamsYaml",
       "params.yaml",
       [](const Workspace&) {
         return std::string("reconstruct mission --params params.yaml --out out");
       },
       Outcome::Fails,
       {"out/report.json"}},
      {"NoiseModel",
       "noise.yaml",
       [](const Workspace&) {
         return std::string("reconstruct mission --noise-model noise.yaml --out out");
       },
       Outcome::Fails,
       {"out/report.json", "out/surface_points.ply"}},
      {"GroundTruthOfReconstruct",
       "mission/ground_truth.ply",
       [](const Workspace&) { return std::string("reconstruct mission --out out"); },
       Outcome::Fails,
       {"out/report.json", "out/surface_points.ply", "out/mesh.ply"}},
      {"EvaluateReference", "reference.ply", evaluateArgs},
      {"EvaluateReconstruction", "points.ply", evaluateArgs},
      {"EvaluateVisible", "visible.ply", evaluateArgs},
      {"SimulateScene",
       "scene.ply",
       [](const Workspace&) {
         return std::string("simulate --scene scene.ply --max-frames 1 --out sim");
       },
       Outcome::Fails,
       {"sim/mission.yaml"}},
      {"ExportMesh",
       "rec/mesh.ply",
       [](const Workspace& ws) {
         std::filesystem::create_directories(ws / "rec");
         return std::string("export rec --out mesh.obj");
       },
       Outcome::Fails,
       {"mesh.obj"}},
      {"Recording",
       "ping.raw",
       [](const Workspace& ws) { return recordingArgs(ws, ""); },
       Outcome::Fails,
       {},
       true},
      {"RecordingNav", "nav.csv", [](const Workspace& ws) { return recordingArgs(ws, ""); }},
      {"NavMapping", "map.yaml",
       [](const Workspace& ws) { return recordingArgs(ws, " --nav-map map.yaml"); }},
      {"Mounting", "mounting.yaml",
       [](const Workspace& ws) { return recordingArgs(ws, " --mounting mounting.yaml"); }},
      {"ImportedLog",
       "ping.raw",
       [](const Workspace& ws) {
         recordingArgs(ws, "");
         return std::string("import --format oculus ping.raw --nav nav.csv --out imported");
       },
       Outcome::Fails,
       {"imported/mission.yaml"}},
      {"ReconstructedRecordingNav",
       "nav.csv",
       [](const Workspace& ws) {
         recordingArgs(ws, "");
         return std::string("reconstruct ping.raw --nav nav.csv --out out");
       },
       Outcome::Fails,
       {"out/report.json"}},
      {"FrameNoiseModel",
       "noise.yaml",
       [](const Workspace&) {
         return std::string(
             "frame mission --index 0 --noise-model noise.yaml --detected detected.png");
       },
       Outcome::Fails,
       {"detected.png"}},
  };
}

std::string kindName(NotAFile kind) {
  static const char* const kNames[] = {"Directory", "Fifo", "Device"};
  return kNames[static_cast<int>(kind)];
}

}  // namespace

std::vector<CatalogueCase> fileKindCases() {
  std::vector<CatalogueCase> cases;
  for (const Input& input : inputs()) {
    for (const NotAFile kind : {NotAFile::Directory, NotAFile::Fifo, NotAFile::Device}) {
      if (kind == NotAFile::Directory && input.directory_is_a_folder_input) {
        continue;
      }
      const std::string file_name = std::filesystem::path(input.file).filename().string();
      cases.push_back({.name = input.name + "Is" + kindName(kind),
                       .prepare =
                           [input, kind](const Workspace& ws) {
                             const std::string args = input.prepare(ws);
                             putNotAFile(ws / input.file, kind);
                             return args;
                           },
                       .outcome = input.outcome,
                       .message = {file_name + ": " + describe(kind), "expected a regular file"},
                       .absent = input.absent});
    }
  }
  return cases;
}

}  // namespace sonarcarve::test
