// Class "readers": every reader given an empty file, a file cut off in the middle and bytes
// that are not its format: navigation and frame index CSVs, mission and parameter YAML, PNG
// frames, noise models, and PLY, OBJ and STL meshes. Each names the file, the place and what
// was expected; none crashes, and nothing partial is written.
#include "e2e/catalogue/catalogue.h"
#include "support/cli_runner.h"

namespace sonarcarve::test {
namespace {

const std::string kBinary("\x00\x01\xff\xfe garbage \x89\x00\x7f", 16);

// `file` under the workspace replaced by `bytes(original)`, then `args`.
CatalogueCase replaced(const std::string& name, const std::string& file,
                       std::function<std::string(const std::string&)> bytes,
                       const std::string& args, const std::vector<std::string>& message,
                       Outcome outcome = Outcome::Fails, std::vector<std::string> absent = {}) {
  return {.name = name,
          .prepare =
              [file, bytes, args](const Workspace& ws) {
                std::error_code ec;
                const std::string original =
                    std::filesystem::exists(ws / file, ec) ? readText(ws / file) : "";
                writeBytes(ws / file, bytes(original));
                return args;
              },
          .outcome = outcome,
          .message = message,
          .absent = std::move(absent)};
}

std::string empty(const std::string&) {
  return "";
}
std::string binary(const std::string&) {
  return kBinary;
}
std::function<std::string(const std::string&)> cutAt(std::size_t size) {
  return [size](const std::string& original) { return original.substr(0, size); };
}
std::function<std::string(const std::string&)> text(const std::string& content) {
  return [content](const std::string&) { return content; };
}

std::string evaluateWith(const std::string& reference) {
  return "evaluate --json --reference " + reference + " --reconstruction points.ply";
}

// evaluate with the reference mesh `file` holding `bytes` (points.ply is a valid cloud).
CatalogueCase badReference(const std::string& name, const std::string& file,
                           const std::string& bytes, const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [file, bytes](const Workspace& ws) {
                writeBytes(ws / "points.ply", asciiPly({{2, 0, 10}, {2.05, 0.01, 10}}));
                writeBytes(ws / file, bytes);
                return evaluateWith(file);
              },
          .message = message};
}

// A binary STL header of `declared` triangles followed by `present` of them.
std::string stl(std::uint32_t declared, std::uint32_t present) {
  std::string out(80, ' ');
  out.append(reinterpret_cast<const char*>(&declared), 4);
  const float triangle[12] = {0, 0, 1, 2, 0, 10, 2.1f, 0, 10, 2, 0.1f, 10};
  for (std::uint32_t k = 0; k < present; ++k) {
    out.append(reinterpret_cast<const char*>(triangle), sizeof triangle);
    out.append(2, '\0');
  }
  return out;
}

const std::string kPlyHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float "
    "y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";

std::string frameArgs() {
  return "frame mission --index 3 --polar polar.png";
}

}  // namespace

std::vector<CatalogueCase> readerCases() {
  const std::string info = "info mission";
  return {
      replaced("NavCsvEmpty", "mission/nav.csv", empty, info,
               {"mission/nav.csv: file is empty: expected a header line of column names"}),
      replaced("NavCsvHeaderOnly", "mission/nav.csv",
               text("time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n"), info,
               {"mission/nav.csv: no navigation samples after the header"}),
      replaced("NavCsvCutInARow", "mission/nav.csv", cutAt(85), info,
               {"mission/nav.csv: line 3: expected 7 values, found 2"}),
      replaced("NavCsvBinary", "mission/nav.csv", binary, info,
               {"mission/nav.csv: line 1: binary data in a text file"}),
      replaced("FramesCsvEmpty", "mission/frames.csv", empty, info,
               {"mission/frames.csv: file is empty: expected a header line of column names"}),
      replaced("FramesCsvCutInARow", "mission/frames.csv", cutAt(60), info,
               {"mission/frames.csv: line 3: expected 3 values, found 1"}),
      replaced("FramesCsvBinary", "mission/frames.csv", binary, info,
               {"mission/frames.csv: line 1: binary data in a text file"}),
      replaced("MissionYamlEmpty", "mission/mission.yaml", empty, info,
               {"mission/mission.yaml: expected a YAML mapping of keys (is the file empty?)"}),
      replaced("MissionYamlCutInTheSonar", "mission/mission.yaml", cutAt(230), info,
               {"mission/mission.yaml: line 7: not valid YAML: end of map flow not found"}),
      replaced("MissionYamlBinary", "mission/mission.yaml", binary, info,
               {"mission/mission.yaml: expected a YAML mapping of keys"}),
      replaced("FramePngEmpty", "mission/frames/000003.png", empty, frameArgs(),
               {"000003.png: byte 0: empty file: expected a PNG image"}, Outcome::Fails,
               {"polar.png"}),
      replaced(
          "FramePngCutInTheData", "mission/frames/000003.png", cutAt(2000), frameArgs(),
          {"000003.png: byte 2000: truncated PNG: expected the IEND chunk at the end of the file"},
          Outcome::Fails, {"polar.png"}),
      replaced("FramePngCutInTheHeader", "mission/frames/000003.png", cutAt(20), frameArgs(),
               {"000003.png: byte 20: truncated PNG: expected the IEND chunk"}, Outcome::Fails,
               {"polar.png"}),
      replaced(
          "FramePngCutIsSkippedByReconstruct", "mission/frames/000003.png", cutAt(2000),
          "reconstruct mission --out out",
          {"skipped: ",
           "000003.png: byte 2000: truncated PNG: expected the IEND chunk at the end of the file"},
          Outcome::Succeeds),
      replaced("ParamsYamlEmpty", "params.yaml", empty,
               "reconstruct mission --params params.yaml --out out",
               {"params.yaml: expected a YAML mapping of keys (is the file empty?)"},
               Outcome::Fails, {"out"}),
      replaced("ParamsYamlCutInAList", "params.yaml", text("voxel_size_m: 0.05\nregion: [1, 2"),
               "reconstruct mission --params params.yaml --out out",
               {"params.yaml: line 2: not valid YAML: end of sequence flow not found"},
               Outcome::Fails, {"out"}),
      replaced("ParamsYamlBinary", "params.yaml", binary,
               "reconstruct mission --params params.yaml --out out",
               {"params.yaml: expected a YAML mapping of keys"}, Outcome::Fails, {"out"}),
      replaced("NoiseModelEmpty", "noise.yaml", empty,
               "reconstruct mission --noise-model noise.yaml --out out",
               {"noise.yaml: cannot read the noise model (empty or not YAML)"}, Outcome::Fails,
               {"out"}),
      replaced("NoiseModelBinary", "noise.yaml", binary,
               "reconstruct mission --noise-model noise.yaml --out out",
               {"noise.yaml: corrupt noise model"}, Outcome::Fails, {"out"}),
      {.name = "NoiseModelCutInTheMiddle",
       .prepare =
           [](const Workspace& ws) {
             runCliIn(ws, "noise-model mission --out whole.yaml");
             const std::string whole = readText(ws / "whole.yaml");
             writeBytes(ws / "noise.yaml", whole.substr(0, whole.size() / 2));
             return std::string("reconstruct mission --noise-model noise.yaml --out out");
           },
       .message = {"noise.yaml: corrupt noise model", "Missing , between the elements"},
       .absent = {"out"}},
      badReference("ReferencePlyEmpty", "reference.ply", "",
                   {"reference.ply: byte 0: empty file: expected an STL, OBJ or PLY mesh"}),
      badReference("ReferencePlyHeaderCut", "reference.ply",
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
                   {"reference.ply: line 4: truncated PLY header: expected 'end_header'"}),
      badReference("ReferencePlyBinaryDataCut", "reference.ply", kPlyHeader + std::string(20, '\0'),
                   {"reference.ply: byte 189: truncated PLY: the header declares at least 100 "
                    "bytes of data after byte 169"}),
      badReference("ReferenceObjEmpty", "reference.obj", "", {"reference.obj: byte 0: empty file"}),
      badReference("ReferenceObjVertexOfTwoNumbers", "reference.obj",
                   "v 2 0 10\nv 2.1 0\nv 2 0.1 10\nf 1 2 3\n", {"reference.obj: line 2"}),
      badReference("ReferenceObjBinary", "reference.obj", kBinary,
                   {"reference.obj: no triangles in the mesh"}),
      badReference("ReferenceStlEmpty", "reference.stl", "", {"reference.stl: byte 0: empty file"}),
      badReference(
          "ReferenceStlCut", "reference.stl", stl(10, 1),
          {"reference.stl: byte 134: truncated binary STL: the header declares 10 triangles"}),
      badReference("ReferenceStlHeaderOnly", "reference.stl", std::string(60, 's'),
                   {"reference.stl: byte 60: truncated binary STL: expected an 80-byte header"}),
      {.name = "ExportOfACutMesh",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "rec/mesh.ply", kPlyHeader + std::string(30, '\0'));
             return std::string("export rec --out mesh.obj");
           },
       .message = {"rec/mesh.ply: byte 199: truncated PLY: the header declares at least 100 bytes"},
       .absent = {"mesh.obj"}},
      {.name = "SimulateSceneObjEmpty",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "scene.obj", "");
             return std::string("simulate --scene scene.obj --max-frames 1 --out sim");
           },
       .message = {"scene.obj: byte 0: empty file: expected an STL, OBJ or PLY mesh"},
       .absent = {"sim/mission.yaml"}},
  };
}

}  // namespace sonarcarve::test
