// Class "limits before allocation": sizes read from inputs or parameters are checked against
// the documented limits (core/common/input_limits.h) before anything is allocated from them.
#include "e2e/catalogue/catalogue.h"
#include "support/cli_runner.h"

namespace sonarcarve::test {
namespace {

CatalogueCase sonarSize(const std::string& name, const std::string& from, const std::string& to,
                        const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [from, to](const Workspace& ws) {
                replaceIn(ws.mission() / "mission.yaml", from, to);
                return std::string("info mission");
              },
          .message = message};
}

CatalogueCase hugeFrame(const std::string& name, std::uint32_t width, std::uint32_t height) {
  const std::string size = std::to_string(height) + " x " + std::to_string(width);
  return {.name = name,
          .prepare =
              [width, height](const Workspace& ws) {
                writeBytes(ws.mission() / "frames/000003.png", pngHeader(width, height));
                return std::string("frame mission --index 3 --polar polar.png");
              },
          .message = {"000003.png: byte 16: image is " + size + " (rows x cols): expected at most"},
          .absent = {"polar.png"}};
}

CatalogueCase simulateSize(const std::string& name, const std::string& flags,
                           const std::vector<std::string>& message) {
  return {
      .name = name,
      .prepare =
          [flags](const Workspace&) { return "simulate --scene riser " + flags + " --out sim"; },
      .message = message,
      .absent = {"sim"}};
}

std::string tableOf(int beams) {
  std::string table = "{table_deg: [";
  for (int j = 0; j < beams; ++j) {
    table += (j > 0 ? ", " : "") + std::to_string(-30.0 + 60.0 * j / beams);
  }
  return table + "]}";
}

}  // namespace

std::vector<CatalogueCase> limitCases() {
  return {
      sonarSize(
          "SonarWithABillionBeams", "beams: 64}", "beams: 1000000000}",
          {"mission.yaml: line 8: sonar.bearings", "1000000000 beams: expected at most 4096"}),
      sonarSize("SonarWithATableOf5000Beams", "{fov_deg: 60, beams: 64}", tableOf(5000),
                {"mission.yaml: line 8: sonar.bearings", "5000 beams: expected at most 4096"}),
      sonarSize("SonarWithAHundredMillionBins", "bins: 200}", "bins: 100000000}",
                {"mission.yaml: line", "100000000 range bins: expected at most 16384"}),
      {.name = "SonarFrameOfTooManyPixels",
       .prepare =
           [](const Workspace& ws) {
             replaceIn(ws.mission() / "mission.yaml", "bins: 200}", "bins: 16384}");
             replaceIn(ws.mission() / "mission.yaml", "beams: 64}", "beams: 4096}");
             return std::string("info mission");
           },
       .message = {"mission.yaml: line 6: sonar",
                   "16384 bins x 4096 beams: expected at most 16777216 pixels"}},
      hugeFrame("FramePng30000Square", 30000, 30000),
      hugeFrame("FramePngTooWide", 5000, 200),
      hugeFrame("FramePngTooTall", 64, 20000),
      hugeFrame("FramePngTooManyPixels", 4096, 16384),
      {.name = "FramePngHugeIsSkippedByInfo",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws.mission() / "frames/000003.png", pngHeader(30000, 30000));
             return std::string("info mission");
           },
       .outcome = Outcome::Succeeds,
       .message = {"Failed       1 frames"}},
      {.name = "ReconstructElevationStepTiny",
       .prepare =
           [](const Workspace&) {
             return std::string("reconstruct mission --elevation-step 1e-7 --out out");
           },
       .message = {"--elevation-step", "from 0.01 to 90"},
       .absent = {"out"}},
      {.name = "ReconstructElevationStepTinyInParams",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "params.yaml", "elevation_step_deg: 1e-7\n");
             return std::string("reconstruct mission --params params.yaml --out out");
           },
       .message = {"params.yaml: line 1: elevation_step_deg", "from 0.01 to 90"},
       .absent = {"out"}},
      {.name = "SimulateElevationStepTiny",
       .prepare =
           [](const Workspace&) {
             return std::string("simulate --scene riser --elevation-step 1e-7 --out sim");
           },
       .message = {"--elevation-step: Value 1e-7 not in range 0.010000 to 90"},
       .absent = {"sim"}},
      // Completeness samples the reference; on a 1 km triangle every 1 cm that was 5e9 points.
      {.name = "EvaluateOnAReferenceOfOneKilometre",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "reference.ply",
                        asciiPly({{0, 0, 10}, {1000, 0, 10}, {0, 1000, 10}}, {{0, 1, 2}}));
             writeBytes(ws / "points.ply", asciiPly({{2, 0, 10}, {2.05, 0.01, 10}}));
             return std::string(
                 "evaluate --json --reference reference.ply --reconstruction points.ply");
           },
       .outcome = Outcome::Succeeds,
       .message = {"\"reference_spacing_m\": 0.555"}},
      {.name = "ReconstructVoxelSizeTiny",
       .prepare =
           [](const Workspace&) {
             return std::string("reconstruct mission --voxel-size 0.0001 --out out");
           },
       .message = {"parameters: voxel_size_m: the map's box",
                   "voxels of 0.0001 m: expected at most",
                   "use a larger voxel size or a smaller region"},
       .absent = {"out/surface_points.ply", "out/report.json"}},
      // Memory: the estimate of the map, frames and occlusion buffers against the memory
      // available, here capped by the user.
      {.name = "ReconstructOverTheMemoryAvailable",
       .prepare = [](const Workspace&) { return std::string("reconstruct mission --out out"); },
       .message = {"parameters: voxel_size_m: the reconstruction needs at least",
                   "but the memory budget is 0.8 MiB (80 % of 1.0 MiB available, "
                   "SONARCARVE_MEMORY_LIMIT_MB)",
                   "use a larger voxel size or a smaller region, or set memory_budget_mb"},
       .absent = {"out/surface_points.ply", "out/report.json", "out/manifest.json"},
       .wrapper = "env SONARCARVE_MEMORY_LIMIT_MB=1"},
      // The memory budget (memory_budget_mb): the estimate before the map exists, then what
      // the run holds after each frame; an earlier run's files stay as they were.
      {.name = "ReconstructOverItsMemoryBudgetBeforeCarving",
       .prepare =
           [](const Workspace&) {
             return std::string("reconstruct mission --memory-budget 1 --out out");
           },
       .message = {"parameters: voxel_size_m: the reconstruction needs at least",
                   "but the memory budget is 1.0 MiB (memory_budget_mb)"},
       .absent = {"out"}},
      {.name = "ReconstructOverItsMemoryBudgetBetweenFrames",
       .prepare =
           [](const Workspace& ws) {
             // A seabed seen from a lawnmower: its map outgrows the estimate (21 MiB) at once.
             const RunResult made =
                 runShell("cd " + quoted(ws.root()) + " && '" + SONARCARVE_CLI +
                          "' simulate --scene seabed-objects --trajectory lawnmower --noise none "
                          "--beam clipped --max-frames 8 --out seabed 2>&1");
             EXPECT_EQ(made.exit_code, 0) << made.output;
             writePrevious(ws / "out/report.json");
             return std::string(
                 "reconstruct seabed --voxel-size 0.03 --memory-budget 30 --out out");
           },
       .message = {"parameters: memory_budget_mb: the run holds", "after frame 1 of 8 (map ",
                   "over the memory budget of 30 MiB (memory_budget_mb): set memory_budget_mb, "
                   "a region of interest (region), a larger voxel size (voxel_size_m), or shard "
                   "the mission (docs/scaling.md)"},
       .absent = {"out/surface_points.ply", "out/map.bt", "out/manifest.json"},
       .intact = {"out/report.json"}},
      {.name = "SceneMeshOverTheMemoryAvailable",
       .prepare =
           [](const Workspace& ws) {
             std::string obj;
             for (int i = 0; i < 20000; ++i) {
               obj += "v " + std::to_string(i) + ".5 0.25 10.75\n";
             }
             obj += "f 1 2 3\n";
             writeBytes(ws / "big.obj", obj);
             return std::string("simulate --scene big.obj --max-frames 1 --out sim");
           },
       .message = {"big.obj: a mesh of", "MiB to read, more than the 1 MiB available",
                   "expected a smaller mesh or more memory"},
       .absent = {"sim"},
       .wrapper = "env SONARCARVE_MEMORY_LIMIT_MB=1"},
      {.name = "ReconstructUnderAGenerousMemoryLimit",
       .prepare = [](const Workspace&) { return std::string("reconstruct mission --out out"); },
       .outcome = Outcome::Succeeds,
       .message = {"\"frames_used\""},
       .wrapper = "env SONARCARVE_MEMORY_LIMIT_MB=4096"},
      simulateSize("SimulateStepZero", "--step 0", {"--step: Value 0 not in range"}),
      simulateSize("SimulateStepOfAKilometre", "--step 1000", {"--step: Value 1000 not in range"}),
      simulateSize("SimulateAMillionFrames", "--max-frames 1000000",
                   {"--max-frames: Value 1000000 not in range"}),
      simulateSize("SimulateNoRaysPerBeam", "--rays-per-beam 0",
                   {"--rays-per-beam: Value 0 not in range"}),
      simulateSize("SimulateAThousandRaysPerBeam", "--rays-per-beam 1000",
                   {"--rays-per-beam: Value 1000 not in range"}),
      simulateSize("SimulateTooManyRaysPerFrame", "--elevation-step 0.01 --rays-per-beam 32",
                   {"--rays-per-beam: ", "rays per frame: expected at most 1.67772e+07",
                    "use a larger --elevation-step or fewer --rays-per-beam"}),
      // A negative count of frames timed the reference engine on none, said as "0 frames".
      {.name = "BenchReferenceFramesNegative",
       .prepare = [](const Workspace&) { return std::string("bench carve --reference-frames -5"); },
       .message = {"--reference-frames: Value -5 not in range 0 to 1000000"}},
  };
}

}  // namespace sonarcarve::test
