// Class "writes that cannot lie": output folders that cannot be written, outputs that collide
// with folders, and a full disk (a file size limit) for every kind of output. The command
// fails, says why and where, and the previous file is intact.
#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {
namespace {

constexpr int kFullDiskKib = 8;  // every output below is larger

// A reconstruction folder holding a mesh of 2 x 40 x 40 triangles and its vertices as points.
std::string writeReconstruction(const Workspace& ws) {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<long, 3>> faces;
  constexpr int kSide = 41;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      points.push_back({0.05 * i, 0.05 * j, 10.0 + 0.001 * i * j});
      if (i > 0 && j > 0) {
        const long a = (i - 1) * kSide + j - 1, b = a + 1, c = a + kSide, d = c + 1;
        faces.push_back({a, b, d});
        faces.push_back({a, d, c});
      }
    }
  }
  writeBytes(ws / "rec/mesh.ply", asciiPly(points, faces));
  writeBytes(ws / "rec/surface_points.ply", asciiPly(points));
  return "rec";
}

CatalogueCase exportFullDisk(const std::string& name, const std::string& file,
                             const std::string& flags = "") {
  return {.name = name,
          .prepare =
              [file, flags](const Workspace& ws) {
                writePrevious(ws / file);
                return "export " + writeReconstruction(ws) + flags + " --out " + file;
              },
          .message = {file + ": byte",
                      "write failed: File too large (disk full or file size "
                      "limit); previous file kept"},
          .intact = {file},
          .file_size_limit_kib = kFullDiskKib};
}

// An export with `flags` onto an earlier `file`, which must stay: refused by `message`.
CatalogueCase exportRefused(const std::string& name, const std::string& file,
                            const std::string& flags, const std::string& message) {
  return {.name = name,
          .prepare =
              [file, flags](const Workspace& ws) {
                writePrevious(ws / file);
                return "export " + writeReconstruction(ws) + " " + flags + " --out " + file;
              },
          .message = {message},
          .intact = {file}};
}

}  // namespace

std::vector<CatalogueCase> outputCases() {
  return {
      {.name = "ReconstructOutIsAFile",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "out");
             return std::string("reconstruct mission --out out");
           },
       .message = {"out: is a regular file: expected a folder or a new path"},
       .intact = {"out"}},
      {.name = "ReconstructOutUnderAFile",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "file");
             return std::string("reconstruct mission --out file/out");
           },
       .message = {"file/out: cannot create the output folder", "Not a directory"},
       .intact = {"file"}},
      {.name = "ReconstructOutNotWritable",
       .prepare = [](const Workspace&) { return std::string("reconstruct mission --out /proc"); },
       .message = {"/proc: cannot write in the output folder",
                   "expected a folder where files can be created"}},
      {.name = "SimulateOutIsAFile",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "sim");
             return std::string("simulate --scene riser --max-frames 1 --out sim");
           },
       .message = {"sim: is a regular file: expected a folder or a new path"},
       .intact = {"sim"}},
      {.name = "ExportOutIsAFolder",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_directories(ws / "mesh.obj");
             writePrevious(ws / "mesh.obj/inside");
             return "export " + writeReconstruction(ws) + " --out mesh.obj";
           },
       .message = {"mesh.obj: is a directory: expected a regular file or a new path"},
       .intact = {"mesh.obj/inside"}},
      {.name = "ExportFromAFolderWhoseRunFailed",
       .prepare =
           [](const Workspace& ws) {
             const std::string rec = writeReconstruction(ws);
             writeBytes(ws / rec / "manifest.json",
                        "{\"command\": \"reconstruct\", \"status\": \"failed\"}\n");
             return "export " + rec + " --out mesh.stl";
           },
       .message = {"rec/manifest.json: status: the run that wrote this folder is 'failed'",
                   "expected a complete run"},
       .absent = {"mesh.stl"}},
      {.name = "ExportFromAFolderWhoseRunNeverEnded",
       .prepare =
           [](const Workspace& ws) {
             const std::string rec = writeReconstruction(ws);
             writeBytes(ws / rec / "manifest.json", "{\"status\": \"running\"}\n");
             return "export " + rec + " --points --out points.ply";
           },
       .message = {"is 'running'", "expected a complete run"},
       .absent = {"points.ply"}},
      {.name = "NoiseModelOutFolderMissing",
       .prepare =
           [](const Workspace&) {
             return std::string("noise-model mission --out missing/noise.yaml");
           },
       .message = {"missing/noise.yaml: cannot create a file in missing: No such file"},
       .absent = {"missing"}},
      {.name = "FramePictureIsAFolder",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_directories(ws / "polar.png");
             return std::string("frame mission --index 0 --polar polar.png");
           },
       .message = {"polar.png: is a directory: expected a regular file or a new path"}},
      {.name = "ReconstructIntoAFolderInUse",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "out/report.json");
             return std::string("reconstruct mission --out out");
           },
       .message = {"out: is being written by another sonarcarve run (pid "},
       .intact = {"out/report.json"},
       .wrapper = "flock -o out"},
      // Targets that are not a regular file or a new path (issue 44): a FIFO, a device or a
      // dangling link is refused before any work and left as it was; a link is written through.
      {.name = "ExportOntoAFifo",
       .prepare =
           [](const Workspace& ws) {
             makeFifo(ws / "mesh.ply");
             return "export " + writeReconstruction(ws) + " --out mesh.ply";
           },
       .message = {"mesh.ply: is a FIFO (named pipe): expected a regular file or a new path"},
       .fifos = {"mesh.ply"}},
      {.name = "ExportOntoDevNull",
       .prepare =
           [](const Workspace& ws) {
             return "export " + writeReconstruction(ws) + " --points --out /dev/null";
           },
       .message = {"/dev/null: is a device: expected a regular file or a new path"}},
      {.name = "ExportThroughALink",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "runs/points.ply");
             std::filesystem::create_symlink("runs/points.ply", ws / "points.ply");
             return "export " + writeReconstruction(ws) + " --points --out points.ply";
           },
       .outcome = Outcome::Succeeds,
       .message = {"wrote points.ply"},
       .holds = {{"runs/points.ply", "ply"}}},
      {.name = "ExportOntoADanglingLink",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_symlink("missing.ply", ws / "points.ply");
             return "export " + writeReconstruction(ws) + " --points --out points.ply";
           },
       .message = {"points.ply: is a symbolic link to missing.ply, which is missing"},
       .absent = {"missing.ply"}},
      {.name = "NoiseModelOntoAFifo",
       .prepare =
           [](const Workspace& ws) {
             makeFifo(ws / "noise.yaml");
             return std::string("noise-model mission --out noise.yaml");
           },
       .message = {"noise.yaml: is a FIFO (named pipe): expected a regular file or a new path"},
       .fifos = {"noise.yaml"}},
      {.name = "SimulateIntoAFifo",
       .prepare =
           [](const Workspace& ws) {
             makeFifo(ws / "sim");
             return std::string("simulate --scene riser --max-frames 1 --out sim");
           },
       .message = {"sim: is a FIFO (named pipe): expected a folder or a new path"},
       .fifos = {"sim"}},
      {.name = "ImportIntoAFifo",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "ping.raw");
             makeFifo(ws / "imported");
             return std::string("import --format oculus ping.raw --out imported");
           },
       .message = {"imported: is a FIFO (named pipe): expected a folder or a new path"},
       .fifos = {"imported"}},
      // A folder another run holds (flock on the folder, as sonarcarve's own lock): the second
      // run fails at once and changes nothing in it.
      {.name = "SimulateIntoAFolderInUse",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "sim/mission.yaml");
             return std::string("simulate --scene riser --max-frames 1 --force --out sim");
           },
       .message = {"sim: is being written by another sonarcarve run (pid "},
       .absent = {"sim/nav.csv", "sim/frames"},
       .intact = {"sim/mission.yaml"},
       .wrapper = "flock -o sim"},
      {.name = "ImportIntoAFolderInUse",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "ping.raw");
             std::filesystem::create_directories(ws / "imported");
             return std::string("import --format oculus ping.raw --out imported");
           },
       .message = {"imported: is being written by another sonarcarve run (pid "},
       .absent = {"imported/frames", "imported/mission.yaml"},
       .wrapper = "flock -o imported"},
      {.name = "ExportIntoAFolderInUse",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_directories(ws / "out");
             return "export " + writeReconstruction(ws) + " --points --out out/points.ply";
           },
       .message = {"out: is being written by another sonarcarve run (pid "},
       .absent = {"out/points.ply"},
       .wrapper = "flock -o out"},
      {.name = "ReconstructRemovesTheMeshOfAnEarlierRun",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "out/mesh.ply");
             writePrevious(ws / "out/mesh.stl");
             return std::string("reconstruct mission --mesh false --out out");
           },
       .outcome = Outcome::Succeeds,
       .message = {"removed out/mesh.ply of an earlier run"},
       .absent = {"out/mesh.ply", "out/mesh.stl"}},
      {.name = "ExportPointsOntoAFolder",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_directories(ws / "points.ply");
             return "export " + writeReconstruction(ws) + " --points --out points.ply";
           },
       .message = {"points.ply: is a directory: expected a regular file or a new path"}},
      {.name = "NoiseModelOntoAFolder",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_directories(ws / "noise.yaml");
             return std::string("noise-model mission --out noise.yaml");
           },
       .message = {"noise.yaml: is a directory: expected a regular file or a new path"}},
      {.name = "ImportIntoAFile",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "ping.raw");
             std::filesystem::copy_file(ws.mission() / "nav.csv", ws / "nav.csv");
             writePrevious(ws / "imported");
             return std::string("import --format oculus ping.raw --nav nav.csv --out imported");
           },
       .message = {"imported: is a regular file: expected a folder or a new path"},
       .intact = {"imported"}},
      {.name = "SimulateIntoAFolderThatCannotBeWritten",
       .prepare =
           [](const Workspace&) {
             return std::string("simulate --scene riser --max-frames 1 --out /proc");
           },
       .message = {"/proc: cannot write in the output folder"}},
      exportFullDisk("ExportObjOnAFullDisk", "mesh.obj"),
      exportFullDisk("ExportStlOnAFullDisk", "mesh.stl"),
      exportFullDisk("ExportPlyOnAFullDisk", "mesh.ply"),
      exportFullDisk("ExportAsciiPlyOnAFullDisk", "mesh_ascii.ply", " --format ply-ascii"),
      exportFullDisk("ExportPointsOnAFullDisk", "points.ply", " --points"),
      exportFullDisk("ExportLasOnAFullDisk", "points.las"),
      // LAS (issue 43) to a target that cannot be written: a folder where files cannot be
      // created, a folder in the file's place; nothing is left behind.
      {.name = "ExportLasIntoAFolderThatCannotBeWritten",
       .prepare =
           [](const Workspace& ws) {
             return "export " + writeReconstruction(ws) + " --format las --out /sys/points.las";
           },
       .message = {"/sys/points.las: cannot create a file in /sys"}},
      {.name = "ExportGeoTiffIntoAFolderThatCannotBeWritten",
       .prepare =
           [](const Workspace& ws) {
             return "export " + writeReconstruction(ws) + " --out /sys/seabed.tif";
           },
       .message = {"/sys/seabed.tif: cannot create a file in /sys"}},
      // A cell's edge within a millimetre and a kilometre (a grid past 2e8 cells is refused
      // too: SeabedGrid's unit test); 1e300 m wrote a raster whose corners were 1e300 m away.
      exportRefused("ExportGeoTiffWithCellsTooSmall", "seabed.tif", "--cell 0.00001",
                    "--cell: Value 0.00001 not in range 0.001000 to 1000.000000"),
      exportRefused("ExportGeoTiffWithCellsOf1e300", "seabed.tif", "--cell 1e300",
                    "--cell: Value 1e300 not in range 0.001000 to 1000.000000"),
      exportRefused("ExportGeoTiffWithCellsNaN", "seabed.tif", "--cell nan",
                    "export: cell: the edge of the seabed grid's cells: expected 0.001 to 1000 m, "
                    "got nan"),
      // A crop box that holds no point writes no file of no point (as no mesh of no triangle);
      // one that is not a box, or an origin beyond any survey, is refused by its flag. Each was
      // written with exit 0 (an origin of 1e300 m as float32 infinities).
      exportRefused("ExportLasOfAnEmptyCropBox", "points.las",
                    "--format las --crop 100 100 100 101 101 101",
                    "points.las: no point to export (empty reconstruction or crop box)"),
      exportRefused("ExportGeoTiffOfAnEmptyCropBox", "seabed.tif", "--crop 100 100 100 101 101 101",
                    "seabed.tif: no point to export (empty reconstruction or crop box)"),
      exportRefused("ExportWithAnInvertedCropBox", "points.las", "--crop 5 5 5 -5 -5 -5",
                    "export: crop: expected a box N0 E0 D0 N1 E1 D1 of finite numbers, each of "
                    "N0, E0, D0 at most N1, E1, D1 (metres, NED), got 5 5 5 to -5 -5 -5"),
      exportRefused("ExportWithAnOriginOf1e300", "mesh.ply", "--origin 1e300 0 0",
                    "export: origin: expected finite origins within 1e8 m of zero (metres, NED), "
                    "got 1e+300 0 0"),
      {.name = "ExportLasOntoAFolder",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_directories(ws / "points.las");
             writePrevious(ws / "points.las/inside");
             return "export " + writeReconstruction(ws) + " --out points.las";
           },
       .message = {"points.las: is a directory: expected a regular file or a new path"},
       .intact = {"points.las/inside"}},
      {.name = "NoiseModelOnAFullDisk",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "noise.yaml");
             return std::string("noise-model mission --out noise.yaml");
           },
       .message = {"noise.yaml: byte", "write failed: File too large"},
       .intact = {"noise.yaml"},
       .file_size_limit_kib = kFullDiskKib},
      {.name = "FramePictureOnAFullDisk",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "fan.png");
             return std::string("frame mission --index 0 --fan fan.png");
           },
       .message = {"fan.png: byte", "write failed: File too large"},
       .intact = {"fan.png"},
       .file_size_limit_kib = 2},
      // The run's files are written apart first: none can be, so the folder is as it was, the
      // earlier run's report included (failed_run_cases.cpp has more).
      {.name = "ReconstructOnAFullDisk",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "out/report.json");
             return std::string("reconstruct mission --out out");
           },
       // The temporary file of map.bt's blocks cannot grow either: they are kept in memory
       // and the run goes on to the outputs, which fail.
       .message = {"out/", "write failed: File too large",
                   "warning: temporary file of map.bt blocks", "was kept in memory instead",
                   "nothing was changed in out"},
       .absent = {"out/manifest.json", "out/surface_points.ply"},
       .intact = {"out/report.json"},
       .file_size_limit_kib = 1},
      {.name = "ReconstructWritesAManifest",
       .prepare = [](const Workspace&) { return std::string("reconstruct mission --out out"); },
       .outcome = Outcome::Succeeds,
       .message = {"\"frames_used\""},
       .holds = {{"out/manifest.json", "\"status\": \"complete\""},
                 {"out/manifest.json", "\"name\": \"report.json\""},
                 {"out/manifest.json", "\"reconstruct\""}}},
      {.name = "ReconstructRemovesTheFilesOfAnEarlierManifestOnly",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "out/old_points.ply");
             writePrevious(ws / "out/notes.txt");
             writeBytes(ws / "out/manifest.json",
                        R"({"status": "complete", "files": [{"name": "old_points.ply"}]})");
             return std::string("reconstruct mission --out out");
           },
       .outcome = Outcome::Succeeds,
       .message = {"removed out/old_points.ply of an earlier run"},
       .absent = {"out/old_points.ply"},
       .intact = {"out/notes.txt"}},
      {.name = "SimulateOnAFullDisk",
       .prepare =
           [](const Workspace&) {
             return std::string("simulate --scene riser --max-frames 1 --out sim");
           },
       .message = {"sim/", "write failed: File too large",
                   "removed sim, which this run had created"},
       .absent = {"sim"},
       .file_size_limit_kib = kFullDiskKib},
  };
}

}  // namespace sonarcarve::test
