// Class "inputs are what they claim", by content: frame paths that leave the mission, byte-order
// marks, NaN and infinite coordinates, faces that name vertices that do not exist.
#include <cstring>

#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {
namespace {

constexpr const char* kBom = "\xEF\xBB\xBF";

CatalogueCase escapingFrame(const std::string& name, const std::string& file) {
  return {.name = name,
          .prepare =
              [file](const Workspace& ws) {
                writeBytes(ws / "outside.png", readText(ws.mission() / "frames/000003.png"));
                setFrameFile(ws.mission(), 3, file);
                return std::string("info mission");
              },
          .message = {"frames.csv: line 5: column 'file': '" + file + "' leaves the mission folder",
                      "files_outside_folder: allowed"}};
}

CatalogueCase withBom(const std::string& name, const std::string& file) {
  return {.name = name,
          .prepare =
              [file](const Workspace& ws) {
                writeBytes(ws.mission() / file, kBom + readText(ws.mission() / file));
                return std::string("info --json mission");
              },
          .outcome = Outcome::Succeeds,
          .message = {"\"failed\": []"}};
}

CatalogueCase badNavValue(const std::string& name, const std::string& value) {
  return {
      .name = name,
      .prepare =
          [value](const Workspace& ws) {
            replaceIn(ws.mission() / "nav.csv", "100.25,0,0,10.05", "100.25," + value + ",0,10.05");
            return std::string("info mission");
          },
      .message = {"nav.csv: line 3: column 'north_m': expected a finite number, found '" + value +
                  "'"}};
}

// evaluate with one input replaced by `bytes`; the message names `file`.
CatalogueCase badEvaluateInput(const std::string& name, const std::string& file,
                               const std::string& bytes, const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [file, bytes](const Workspace& ws) {
                writeBytes(ws / "reference.ply", tetrahedronPly());
                writeBytes(ws / "points.ply", asciiPly({{2, 0, 10}, {2.05, 0.01, 10}}));
                writeBytes(ws / "visible.ply", asciiPly({{2, 0, 10}}));
                writeBytes(ws / file, bytes);
                const bool is_reference = file.rfind("reference", 0) == 0;
                return "evaluate --json --reference " + (is_reference ? file : "reference.ply") +
                       " --reconstruction points.ply --visible visible.ply";
              },
          .message = message};
}

std::string binaryPlyWithNan() {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  const float values[6] = {2, 0, 10, NAN, 0, 10};
  ply.append(reinterpret_cast<const char*>(values), sizeof values);
  return ply;
}

std::string meshWithFace(long a, long b, long c) {
  return asciiPly({{2, 0, 10}, {2.1, 0, 10}, {2, 0.1, 10}}, {{0, 1, 2}, {a, b, c}});
}

// A binary STL of one triangle whose first corner is `x`.
std::string stlWithCorner(float x) {
  std::string stl(80, ' ');
  const std::uint32_t one = 1;
  stl.append(reinterpret_cast<const char*>(&one), 4);
  const float values[12] = {0, 0, 1, x, 0, 10, 2.1f, 0, 10, 2, 0.1f, 10};
  stl.append(reinterpret_cast<const char*>(values), sizeof values);
  stl.append(2, '\0');
  return stl;
}

}  // namespace

std::vector<CatalogueCase> contentCases() {
  std::vector<CatalogueCase> cases = {
      escapingFrame("FramePathClimbsOut", "../outside.png"),
      escapingFrame("FramePathClimbsOutThroughAFolder", "frames/../../outside.png"),
      escapingFrame("FramePathIsAbsolute", "/etc/hostname"),
      {.name = "FramePathOutsideAllowedByTheMission",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "outside.png", readText(ws.mission() / "frames/000003.png"));
             setFrameFile(ws.mission(), 3, "../outside.png");
             replaceIn(ws.mission() / "mission.yaml", "encoding: png16}",
                       "encoding: png16, files_outside_folder: allowed}");
             return std::string("info --json mission");
           },
       .outcome = Outcome::Succeeds,
       .message = {"\"failed\": []"}},
      {.name = "FramesOutsideFolderUnknownValue",
       .prepare =
           [](const Workspace& ws) {
             replaceIn(ws.mission() / "mission.yaml", "encoding: png16}",
                       "encoding: png16, files_outside_folder: sometimes}");
             return std::string("info mission");
           },
       .message = {"mission.yaml: line",
                   "frames.files_outside_folder: expected 'allowed' or "
                   "'refused'"}},
      withBom("ByteOrderMarkInNavCsv", "nav.csv"),
      withBom("ByteOrderMarkInFrameIndex", "frames.csv"),
      withBom("ByteOrderMarkInMissionYaml", "mission.yaml"),
      // The first key is read as itself, not as an unknown key starting with the mark.
      {.name = "ByteOrderMarkInParamsYaml",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "params.yaml", std::string(kBom) + "voxel_size_m: -1\n");
             return std::string("reconstruct mission --params params.yaml --out out");
           },
       .message =
           {"params.yaml: line 1: voxel_size_m: expected a number, above 0 and at most 10, got -1"},
       .absent = {"out"}},
      {.name = "ByteOrderMarkInRecordingNav",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "ping.raw");
             writeBytes(ws / "nav.csv", kBom + readText(ws.mission() / "nav.csv"));
             return std::string("info ping.raw --nav nav.csv");
           },
       .outcome = Outcome::Succeeds,
       .message = {"Failed       0 frames"}},
      {.name = "ByteOrderMarkInMountingYaml",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "ping.raw");
             std::filesystem::copy_file(ws.mission() / "nav.csv", ws / "nav.csv");
             writeBytes(
                 ws / "mounting.yaml",
                 std::string(kBom) + "translation_m: [0, 0, 0]\nroll_pitch_yaw_deg: [0, 0, x]\n");
             return std::string("info ping.raw --nav nav.csv --mounting mounting.yaml");
           },
       .message =
           {"mounting.yaml: line 2: mounting.roll_pitch_yaw_deg[2]: expected a finite number"}},
      badNavValue("NavNan", "nan"),
      badNavValue("NavInfinite", "inf"),
      badNavValue("NavNegativeInfinite", "-inf"),
      badNavValue("NavHuge", "1e999"),
      badEvaluateInput("EvaluateNanPoint", "points.ply", asciiPly({{2, 0, 10}, {NAN, 0, 10}}),
                       {"points.ply: vertex 1: expected finite coordinates, found (nan, 0, 10)"}),
      badEvaluateInput("EvaluateInfinitePoint", "points.ply",
                       asciiPly({{2, 0, 10}, {2, INFINITY, 10}}),
                       {"points.ply: vertex 1: expected finite coordinates, found (2, inf, 10)"}),
      badEvaluateInput("EvaluateNanPointInBinaryPly", "points.ply", binaryPlyWithNan(),
                       {"points.ply: vertex 1: expected finite coordinates, found (nan, 0, 10)"}),
      badEvaluateInput("EvaluateNanVisiblePoint", "visible.ply", asciiPly({{NAN, 0, 10}}),
                       {"visible.ply: vertex 0: expected finite coordinates"}),
      badEvaluateInput("ReferencePlyNanVertex", "reference.ply",
                       asciiPly({{2, 0, 10}, {2.1, 0, NAN}, {2, 0.1, 10}}, {{0, 1, 2}}),
                       {"reference.ply: vertex 1: expected finite coordinates"}),
      badEvaluateInput("ReferencePlyFaceIndexTooLarge", "reference.ply", meshWithFace(0, 1, 7),
                       {"reference.ply: face 1: vertex index 7 out of range: expected 0 to 2"}),
      badEvaluateInput("ReferencePlyFaceIndexNegative", "reference.ply", meshWithFace(0, -1, 2),
                       {"reference.ply: face 1: vertex index -1 out of range"}),
      badEvaluateInput("ReferencePlyFaceIndexHuge", "reference.ply", meshWithFace(0, 1, 2000000000),
                       {"reference.ply: face 1: vertex index 2000000000 out of range"}),
      badEvaluateInput("ReferenceObjFaceIndexTooLarge", "reference.obj",
                       "v 2 0 10\nv 2.1 0 10\nv 2 0.1 10\nf 1 2 3\nf 1 2 9\n",
                       {"reference.obj: line 5: vertex index 9 out of range: expected 1 to 3"}),
      badEvaluateInput("ReferenceObjNanVertex", "reference.obj",
                       "v 2 0 10\nv nan 0 10\nv 2 0.1 10\nf 1 2 3\n",
                       {"reference.obj: line 2: expected finite coordinates, found (nan, 0, 10)"}),
      badEvaluateInput("ReferenceStlNanVertex", "reference.stl", stlWithCorner(NAN),
                       {"reference.stl: vertex 0: expected finite coordinates"}),
      {.name = "SimulateSceneFaceIndexTooLarge",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "scene.ply", meshWithFace(0, 1, 7));
             return std::string("simulate --scene scene.ply --max-frames 1 --out sim");
           },
       .message = {"scene.ply: face 1: vertex index 7 out of range"},
       .absent = {"sim/mission.yaml", "sim/ground_truth.ply"}},
      {.name = "ReconstructGroundTruthFaceIndexTooLarge",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws.mission() / "ground_truth.ply", meshWithFace(0, 1, 7));
             return std::string("reconstruct mission --out out");
           },
       .message = {"ground_truth.ply: face 1: vertex index 7 out of range"},
       .absent = {"out/surface_points.ply", "out/mesh.ply", "out/report.json"}},
      {.name = "ExportMeshFaceIndexTooLarge",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "rec/mesh.ply", meshWithFace(0, 1, 7));
             return std::string("export rec --out mesh.obj");
           },
       .message = {"mesh.ply: face 1: vertex index 7 out of range"},
       .absent = {"mesh.obj"}},
      {.name = "ExportMeshNanVertex",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "rec/mesh.ply",
                        asciiPly({{2, 0, 10}, {2.1, 0, 10}, {2, NAN, 10}}, {{0, 1, 2}}));
             return std::string("export rec --out mesh.stl");
           },
       .message = {"mesh.ply: vertex 2: expected finite coordinates"},
       .absent = {"mesh.stl"}},
      badEvaluateInput("ReferencePlyFaceIndexNotWhole", "reference.ply",
                       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                       "property float y\nproperty float z\nelement face 1\n"
                       "property list uchar int vertex_indices\nend_header\n"
                       "2 0 10\n2.1 0 10\n2 0.1 10\n3 0 1 1.5\n",
                       {"reference.ply: face 0: vertex index 1.5 out of range"}),
  };
  return cases;
}

}  // namespace sonarcarve::test
