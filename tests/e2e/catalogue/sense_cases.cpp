// Class "inputs that make no sense, and runs that end empty" (issue 44): every sonar geometry
// key, the aperture flag and the parameters that set the map's geometry at 0, negative, 1e-300
// and 1e300; noise models of NaN means or negative deviations or an even smoothing; meshes with
// more data than their header declares; duplicate keys in every YAML a user writes; an ARIS
// recording whose frame headers carry no vehicle attitude; a run that ends with an empty or
// nearly empty surface. Each is refused naming the file, the place and what was expected, or,
// for a run's result, said on stderr and in report.json.
#include <cstring>
#include <limits>

#include "e2e/catalogue/catalogue.h"
#include "support/cli_runner.h"

namespace sonarcarve::test {
namespace {

// One mission.yaml key, its line and its range's words, at one value.
struct SonarKey {
  std::string name;      ///< for the case's name
  std::string from;      ///< the text replaced in mission.yaml
  std::string key_text;  ///< "resolution_m: " (the value follows it)
  std::string after;     ///< what follows the value: "," or "}"
  std::string message;   ///< "mission.yaml: line 7: sonar.range.resolution_m: expected ..."
};

const std::vector<SonarKey>& sonarKeys() {
  static const std::vector<SonarKey> keys = {
      {"RangeMin", "min_m: 1,", "min_m: ", ",",
       "mission.yaml: line 7: sonar.range.min_m: expected 0 to 1000 m"},
      {"RangeResolution", "resolution_m: 0.025,", "resolution_m: ", ",",
       "mission.yaml: line 7: sonar.range.resolution_m: expected 1e-04 to 10 m"},
      {"FieldOfView", "fov_deg: 60,", "fov_deg: ", ",",
       "mission.yaml: line 8: sonar.bearings.fov_deg: expected 0.1 to 360 (excluded) degrees"},
      {"VerticalAperture", "vertical_aperture_deg: 20\n", "vertical_aperture_deg: ", "\n",
       "mission.yaml: line 9: sonar.vertical_aperture_deg: expected 0.1 to 180 (excluded) "
       "degrees"},
      {"HorizontalBeamWidth", "beam_pattern: sinc\n",
       "beam_pattern: sinc\n  horizontal_beam_width_deg: ", "\n",
       "mission.yaml: line 11: sonar.horizontal_beam_width_deg: expected 0.01 to 360 (excluded) "
       "degrees"},
      {"MountingPitch", "roll_pitch_yaw_deg: [0, 0, 0]", "roll_pitch_yaw_deg: [0, ", ", 0]",
       "mission.yaml: line 13: mounting.roll_pitch_yaw_deg[1]: expected -360 to 360 degrees"},
  };
  return keys;
}

struct Value {
  std::string name;
  std::string text;   ///< as written in the file
  std::string shown;  ///< as the message gives it
};

const std::vector<Value>& absurdValues() {
  static const std::vector<Value> values = {{"Zero", "0", "0"},
                                            {"Negative", "-1", "-1"},
                                            {"Tiny", "1e-300", "1e-300"},
                                            {"Huge", "1e300", "1e+300"}};
  return values;
}

void appendSonarKeyCases(std::vector<CatalogueCase>& cases) {
  for (const SonarKey& key : sonarKeys()) {
    for (const Value& value : absurdValues()) {
      const bool valid = key.name == "RangeMin" && value.name != "Negative" &&
                         value.name != "Huge";  // 0 and 1e-300 m are nearest ranges
      const bool valid_angle = key.name == "MountingPitch" && value.name != "Huge";
      if (valid || valid_angle) {
        continue;
      }
      cases.push_back({.name = "Sonar" + key.name + value.name,
                       .prepare =
                           [key, value](const Workspace& ws) {
                             replaceIn(ws.mission() / "mission.yaml", key.from,
                                       key.key_text + value.text + key.after);
                             return std::string("info mission");
                           },
                       .message = {key.message, "got " + value.shown}});
    }
  }
  cases.push_back({.name = "SonarTableBearingOffTheCircle",
                   .prepare =
                       [](const Workspace& ws) {
                         replaceIn(ws.mission() / "mission.yaml", "{fov_deg: 60, beams: 64}",
                                   "{table_deg: [-10, 0, 1e300]}");
                         return std::string("info mission");
                       },
                   .message = {"mission.yaml: line 8: sonar.bearings.table_deg[2]: expected "
                               "-180 to 180 (excluded) degrees, got 1e+300"}});
  cases.push_back(
      {.name = "SonarFarRangeBeyondAnySonar",
       .prepare =
           [](const Workspace& ws) {
             replaceIn(ws.mission() / "mission.yaml", "resolution_m: 0.025, bins: 200",
                       "resolution_m: 10, bins: 16000");
             return std::string("info mission");
           },
       .message = {"mission.yaml: line 7: sonar.range: reaches 160001 m (min_m + bins x "
                   "resolution_m): expected at most 10000 m"}});
}

// A flag or a params YAML key of reconstruct at a value that makes no sense.
CatalogueCase badParameter(const std::string& name, const std::string& args,
                           const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [args](const Workspace& ws) {
                writeBytes(ws / "params.yaml", "voxel_size_m: 1e6\n");
                return args;
              },
          .message = message,
          .absent = {"out"}};
}

void appendParameterCases(std::vector<CatalogueCase>& cases) {
  for (const Value& value : absurdValues()) {
    cases.push_back(
        {.name = "ApertureFlag" + value.name,
         .prepare =
             [value](const Workspace&) { return "info mission --aperture-deg " + value.text; },
         .message = {"--aperture-deg: expected 0.1 to 180 (excluded) degrees, got " +
                     value.shown}});
  }
  cases.push_back(badParameter("VoxelSizeFlagHuge",
                               "reconstruct mission --voxel-size 1e6 --out out",
                               {"--voxel-size: expected a number, above 0 and at most 10, got "
                                "1e+06"}));
  cases.push_back(badParameter("VoxelSizeYamlHuge",
                               "reconstruct mission --params params.yaml --out out",
                               {"params.yaml: line 1: voxel_size_m", "at most 10, got 1e+06"}));
  cases.push_back(badParameter(
      "VerticalApertureParamTiny", "reconstruct mission --vertical-aperture 1e-300 --out out",
      {"--vertical-aperture: expected a number, 0 or at least 0.1 and below 180, got 1e-300"}));
  cases.push_back(badParameter(
      "HorizontalBeamWidthParamTiny",
      "reconstruct mission --horizontal-beam-width 1e-300 --out out",
      {"--horizontal-beam-width: expected a number, 0 or from 0.01 to 30, got 1e-300"}));
  cases.push_back(badParameter("RangeMaxParamHuge",
                               "reconstruct mission --range-max 1e300 --out out",
                               {"--range-max: expected a number, from 0 to 10000, got 1e+300"}));
}

// The example mission's noise model (noise-model), edited by `edit`, given to reconstruct.
CatalogueCase badNoiseModel(const std::string& name,
                            std::function<std::string(const std::string&)> edit,
                            const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [edit](const Workspace& ws) {
                runCliIn(ws, "noise-model mission --out learned.yaml");
                writeBytes(ws / "noise.yaml", edit(readText(ws / "learned.yaml")));
                return std::string("reconstruct mission --noise-model noise.yaml --out out");
              },
          .message = message,
          .absent = {"out"}};
}

// The text with the first number of `key`'s matrix data replaced by `value`.
std::function<std::string(const std::string&)> firstDatum(const std::string& key,
                                                          const std::string& value) {
  return [key, value](std::string text) {
    const auto data = text.find("data: [", text.find("\n" + key + ":")) + 7;
    text.replace(data, text.find(',', data) - data, value);
    return text;
  };
}

std::function<std::string(const std::string&)> replacing(const std::string& from,
                                                         const std::string& to) {
  return [from, to](std::string text) {
    text.replace(text.find(from), from.size(), to);
    return text;
  };
}

void appendNoiseModelCases(std::vector<CatalogueCase>& cases) {
  cases.push_back(badNoiseModel("NoiseModelMeanNaN", firstDatum("mean", ".Nan"),
                                {"noise.yaml: mean, row 0 column 0", "expected finite numbers"}));
  cases.push_back(
      badNoiseModel("NoiseModelNegativeDeviation", firstDatum("stddev", "-1.5"),
                    {"noise.yaml: stddev, row 0 column 0: -1.5: expected finite numbers >= 0"}));
  cases.push_back(badNoiseModel(
      "NoiseModelNegativeRayleighSigma", firstDatum("rayleigh_sigma", "-2"),
      {"noise.yaml: rayleigh_sigma, row 0 column 0: -2: expected finite numbers >= 0"}));
  cases.push_back(badNoiseModel(
      "NoiseModelEvenSmoothing", replacing("\nsmoothing: 3", "\nsmoothing: 2"),
      {"noise.yaml: smoothing: expected an odd whole number of pixels, from 1 to 255, got 2"}));
  cases.push_back({.name = "NoiseModelCommandEvenSmoothing",
                   .prepare =
                       [](const Workspace&) {
                         return std::string("noise-model mission --smoothing 2 --out noise.yaml");
                       },
                   .message = {"--smoothing: expected an odd whole number, from 1 to 255, got 2"},
                   .absent = {"noise.yaml"}});
}

// An ASCII or binary PLY cube of 8 vertices and 12 triangles whose header declares `faces`.
std::string cubePly(int faces, bool binary) {
  const float v[8][3] = {{2, 0, 10},   {2, 0, 10.1},   {2, 0.1, 10},   {2, 0.1, 10.1},
                         {2.1, 0, 10}, {2.1, 0, 10.1}, {2.1, 0.1, 10}, {2.1, 0.1, 10.1}};
  const int f[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                        {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  std::string ply = std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") +
                    " 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float "
                    "z\nelement face " +
                    std::to_string(faces) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : v) {
    if (binary) {
      ply.append(reinterpret_cast<const char*>(p), sizeof p);
    } else {
      ply += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    }
  }
  for (const auto& t : f) {
    if (binary) {
      ply += '\3';
      ply.append(reinterpret_cast<const char*>(t), sizeof t);
    } else {
      ply += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
             "\n";
    }
  }
  return ply;
}

CatalogueCase plyWithMoreData(const std::string& name, const std::string& role,
                              const std::string& bytes, const std::string& declared) {
  return {.name = name,
          .prepare =
              [role, bytes](const Workspace& ws) {
                writeBytes(ws / "cube.ply", cubePly(12, false));
                writeBytes(ws / "bad.ply", bytes);
                return role == "reference"
                           ? std::string("evaluate --reference bad.ply --reconstruction cube.ply")
                           : std::string("evaluate --reference cube.ply --reconstruction bad.ply");
              },
          .message = {"bad.ply: byte", "data goes on past the elements the header declares (" +
                                           declared + "): expected the file to end there"}};
}

void appendPlyCases(std::vector<CatalogueCase>& cases) {
  cases.push_back(plyWithMoreData("PlyMeshDeclaresFewerFacesAscii", "reference", cubePly(5, false),
                                  "vertex 8, face 5"));
  cases.push_back(plyWithMoreData("PlyMeshDeclaresFewerFacesBinary", "reference", cubePly(5, true),
                                  "vertex 8, face 5"));
  cases.push_back(plyWithMoreData("PlyPointsDeclareFewerVertices", "reconstruction",
                                  asciiPly({{2, 0, 10}, {2.1, 0, 10}}) + "2 0 10.1\n", "vertex 2"));
}

// A mesh without a surface: triangles whose corners lie on one point or one line, as a file of
// zeros (sparse, or filled with zeros) reads. As an evaluation's reference it gave an accuracy
// of "inf m" with exit 0; as a simulator's scene, frames of nothing.
CatalogueCase meshWithoutSurface(const std::string& name, const std::string& file,
                                 const std::string& bytes, bool as_scene,
                                 const std::string& triangles) {
  return {.name = name,
          .prepare =
              [file, bytes, as_scene](const Workspace& ws) {
                writeBytes(ws / file, bytes);
                writeBytes(ws / "cube.ply", cubePly(12, false));
                return as_scene ? "simulate --scene " + file + " --max-frames 1 --out sim"
                                : "evaluate --reference " + file + " --reconstruction cube.ply";
              },
          .message = {file + ": " + triangles +
                      " triangles, none of which has an area (the corners of each on one point "
                      "or line, as in a file of zeros): expected a surface"},
          .absent = {"sim"}};
}

void appendMeshWithoutSurfaceCases(std::vector<CatalogueCase>& cases) {
  // A binary STL declaring 1000 triangles, every byte after its count 0.
  std::string zeros(84 + 50 * 1000, '\0');
  const std::uint32_t count = 1000;
  std::memcpy(zeros.data() + 80, &count, sizeof count);
  cases.push_back(meshWithoutSurface("StlOfZerosAsReference", "zeros.stl", zeros, false, "1000"));
  cases.push_back(meshWithoutSurface("StlOfZerosAsScene", "zeros.stl", zeros, true, "1000"));
  const std::string on_a_line = asciiPly({{0, 0, 10}, {1, 0, 10}, {2, 0, 10}}, {{0, 1, 2}});
  cases.push_back(
      meshWithoutSurface("PlyOfCollinearTrianglesAsReference", "line.ply", on_a_line, false, "1"));
  cases.push_back(meshWithoutSurface("ObjOfOnePointAsScene", "point.obj",
                                     "v 2 0 10\nv 2 0 10\nv 2 0 10\nf 1 2 3\nf 3 2 1\n", true,
                                     "2"));
}

// A YAML file made to hold a key twice by `make`, then `args`.
CatalogueCase duplicateKey(const std::string& name, std::function<void(const Workspace&)> make,
                           const std::string& args, const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [make, args](const Workspace& ws) {
                make(ws);
                return args;
              },
          .message = message,
          .absent = {"out"}};
}

std::function<void(const Workspace&)> editing(const std::string& file, const std::string& from,
                                              const std::string& to) {
  return [file, from, to](const Workspace& ws) {
    if (file == "noise.yaml") {
      runCliIn(ws, "noise-model mission --out noise.yaml");
    }
    replaceIn(ws / file, from, to);
  };
}

std::function<void(const Workspace&)> writing(const std::string& file, const std::string& text) {
  return [file, text](const Workspace& ws) { writeBytes(ws / file, text); };
}

void appendDuplicateKeyCases(std::vector<CatalogueCase>& cases) {
  cases.push_back(duplicateKey(
      "DuplicateKeyMissionTopLevel",
      editing("mission/mission.yaml", "name: example pipe descent\n",
              "name: example pipe descent\nname: another\n"),
      "info mission",
      {"mission.yaml: line 5: name: the key appears twice (first on line 4): expected each key "
       "once"}));
  cases.push_back(duplicateKey(
      "DuplicateKeyMissionNested",
      editing("mission/mission.yaml", "bins: 200}", "bins: 200, bins: 100}"), "info mission",
      {"mission.yaml: line 7: sonar.range.bins: the key appears twice (first on line 7)"}));
  cases.push_back(
      duplicateKey("DuplicateKeyParams",
                   writing("params.yaml", "voxel_size_m: 0.05\nmin_views: 2\nvoxel_size_m: 0.03\n"),
                   "reconstruct mission --params params.yaml --out out",
                   {"params.yaml: line 3: voxel_size_m: the key appears twice (first on line 1)"}));
  cases.push_back(
      duplicateKey("DuplicateKeyNavMapping",
                   writing("map.yaml",
                           "columns: {time: time_s, north: north_m, east: east_m, down: down_m}\n"
                           "columns: {time: t}\n"),
                   "info mission --nav mission/nav.csv --nav-map map.yaml",
                   {"map.yaml: line 2: columns: the key appears twice (first on line 1)"}));
  cases.push_back(
      duplicateKey("DuplicateKeyNoiseModelTopLevel",
                   editing("noise.yaml", "\nsmoothing: 3\n", "\nsmoothing: 3\nsmoothing: 5\n"),
                   "reconstruct mission --noise-model noise.yaml --out out",
                   {"noise.yaml: line 7: smoothing: the key appears twice (first on line 6)"}));
  cases.push_back(
      duplicateKey("DuplicateKeyNoiseModelNested",
                   editing("noise.yaml", "\n   rows: 200\n", "\n   rows: 200\n   rows: 100\n"),
                   "reconstruct mission --noise-model noise.yaml --out out",
                   {"noise.yaml: line", "rows: the key appears twice"}));
}

// The sample ARIS recording with a vehicle field of frame 2's header set to `value`.
CatalogueCase arisVehicleField(const std::string& name, std::size_t field_at, float value,
                               const std::string& message) {
  return {.name = name,
          .prepare =
              [field_at, value](const Workspace& ws) {
                std::string bytes = readText(testData("aris/sample.aris"));
                constexpr std::size_t kFrame2 = 1024 + 2 * (1024 + 48 * 2000);
                const float depth = 5.0F;  // so that the headers carry navigation
                bytes.replace(kFrame2 + 128, 4, reinterpret_cast<const char*>(&depth), 4);
                bytes.replace(kFrame2 + field_at, 4, reinterpret_cast<const char*>(&value), 4);
                writeBytes(ws / "bad.aris", bytes);
                return std::string("info bad.aris");
              },
          .message = {"bad.aris: frame 2: vehicle field " + message, "expected a number within"}};
}

void appendArisCases(std::vector<CatalogueCase>& cases) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cases.push_back(arisVehicleField("ArisHeadingNaN", 152, nan,
                                   "Heading is nan: expected a number within +-360 degrees"));
  cases.push_back(arisVehicleField("ArisPitchHuge", 136, 1e30F, "Pitch is 1.00000001"));
  cases.push_back(arisVehicleField("ArisDepthHuge", 128, 1e20F, "Depth is 100000002"));
}

// A reconstruction whose navigation turns the sonar by `deg_per_sample` at every sample: the
// views agree on little (1 degree: 13 points instead of 498) or nothing.
CatalogueCase turningNavigation(const std::string& name, double deg_per_sample,
                                const std::string& warning, const std::string& value) {
  return {.name = name,
          .prepare =
              [deg_per_sample](const Workspace& ws) {
                std::string nav = "time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n";
                for (int i = 0; i < 11; ++i) {
                  nav += std::to_string(99.75 + 0.5 * i) + ",0,0," +
                         std::to_string(9.95 + 0.1 * i) + ",0,0," +
                         std::to_string(deg_per_sample * i) + "\n";
                }
                writeBytes(ws.mission() / "nav.csv", nav);
                return std::string("reconstruct mission --out out");
              },
          .outcome = Outcome::Succeeds,
          .message = {warning},
          .holds = {{"out/report.json", "\"value\": \"" + value + "\""}}};
}

}  // namespace

std::vector<CatalogueCase> senseCases() {
  std::vector<CatalogueCase> cases;
  appendSonarKeyCases(cases);
  appendParameterCases(cases);
  appendNoiseModelCases(cases);
  appendPlyCases(cases);
  appendMeshWithoutSurfaceCases(cases);
  appendDuplicateKeyCases(cases);
  appendArisCases(cases);
  cases.push_back(turningNavigation("SurfaceNearlyEmptyIsSaid", 1.0,
                                    "warning: surface: nearly empty: the views agree on almost "
                                    "no surface",
                                    "nearly empty"));
  cases.push_back(
      turningNavigation("SurfaceEmptyIsSaid", 10.0, "warning: surface: empty:", "empty"));
  return cases;
}

}  // namespace sonarcarve::test
