// Class "a failed run leaves no result" (issue 44): a run that fails once it has started (an
// input found wrong by a stage, the memory budget, a full disk) must not leave an empty or
// half-written --out that looks like a result. A folder the run made is removed again, and
// said so; an earlier result in the folder survives the failed run intact, its manifest still
// "complete". The message cases (message_cases.cpp) check the same for every error they raise.
#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {
namespace {

// An earlier run's result in out/: its files and a manifest that lists them.
void writeEarlierResult(const Workspace& ws) {
  for (const char* name : {"surface_points.ply", "mesh.ply", "report.json"}) {
    writePrevious(ws / "out" / name);
  }
  writeBytes(ws / "out/manifest.json",
             R"({"status": "complete", "files": [{"name": "surface_points.ply"},)"
             R"( {"name": "mesh.ply"}, {"name": "report.json"}]})");
}

const std::vector<std::string> kEarlierResult = {"out/surface_points.ply", "out/mesh.ply",
                                                 "out/report.json"};
const std::pair<std::string, std::string> kEarlierManifest = {"out/manifest.json", "\"complete\""};

CatalogueCase keepsEarlierResult(const std::string& name, const std::string& flags,
                                 const std::vector<std::string>& message, int file_limit_kib = 0) {
  return {.name = name,
          .prepare =
              [flags](const Workspace& ws) {
                writeEarlierResult(ws);
                return "reconstruct mission " + flags + " --out out";
              },
          .message = message,
          .absent = {"out/map.bt", "out/params.yaml"},
          .intact = kEarlierResult,
          .file_size_limit_kib = file_limit_kib,
          .holds = {kEarlierManifest}};
}

CatalogueCase removesNewFolder(const std::string& name, const std::string& command,
                               const std::vector<std::string>& message, int file_limit_kib = 0) {
  std::vector<std::string> said = message;
  said.push_back("removed new/deeper/out, which this run had created");
  said.push_back("removed new, which this run had created");
  return {.name = name,
          .prepare = [command](const Workspace&) { return command + " --out new/deeper/out"; },
          .message = said,
          .absent = {"new"},
          .file_size_limit_kib = file_limit_kib};
}

// An earlier simulated mission in sim/ (the riser), some of its files marked as an earlier
// run's, then `simulate --force` of another scene into it: it fails part-way (a full disk)
// and must leave the earlier mission as it was, nothing of the new one mixed in.
const std::vector<std::string> kEarlierMission = {"sim/nav.csv", "sim/frames.csv",
                                                  "sim/ground_truth.ply", "sim/frames/000001.png"};

CatalogueCase keepsEarlierMission(const std::string& name, const std::string& flags,
                                  const std::vector<std::string>& message, int file_limit_kib) {
  std::vector<std::string> said = message;
  said.push_back("nothing was changed in sim (the run's files are written apart first");
  return {.name = name,
          .prepare =
              [flags](const Workspace& ws) {
                runCliIn(ws, "simulate --scene riser --max-frames 2 --out sim");
                for (const std::string& file : kEarlierMission) {
                  writePrevious(ws / file);
                }
                return "simulate --scene jacket-node --max-frames 3 --force " + flags +
                       " --out sim";
              },
          .message = said,
          .absent = {"sim/frames/000002.png", "sim/mission.mcap"},
          .intact = kEarlierMission,
          .file_size_limit_kib = file_limit_kib,
          .holds = {{"sim/mission.yaml", "name: riser / vertical"}}};
}

std::string importCommand(const Workspace& ws) {
  std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "ping.raw");
  return "import --format oculus ping.raw";
}

}  // namespace

std::vector<CatalogueCase> failedRunCases() {
  return {
      removesNewFolder("ReconstructWithNoFrameSelected", "reconstruct mission --first-frame 20",
                       {"frames.first (--first-frame)"}),
      removesNewFolder("ReconstructOverItsMemoryBudget", "reconstruct mission --memory-budget 1",
                       {"but the memory budget is 1.0 MiB (memory_budget_mb)"}),
      removesNewFolder("ReconstructOnAFullDisk", "reconstruct mission",
                       {"write failed: File too large"}, 1),
      removesNewFolder("SimulateOnAFullDisk", "simulate --scene riser --max-frames 1",
                       {"write failed: File too large"}, 8),
      // Its first frame cannot be written; then its bag (--format), once the mission is whole.
      keepsEarlierMission("SimulateForceOnAFullDiskKeepsTheEarlierMission", "",
                          {"sim/frames/000000.png", "write failed: File too large"}, 8),
      keepsEarlierMission("SimulateForceFailingOnItsBagKeepsTheEarlierMission", "--format mcap",
                          {"sim/mission.mcap", "write failed: File too large"}, 1400),
      // What is in the way of the move (a FIFO where its simulation.yaml goes) is refused
      // before anything moves: the earlier mission stays whole, the FIFO a FIFO.
      {.name = "SimulateForceOntoAFifoKeepsTheEarlierMission",
       .prepare =
           [](const Workspace& ws) {
             runCliIn(ws, "simulate --scene riser --max-frames 2 --out sim");
             for (const std::string& file : kEarlierMission) {
               writePrevious(ws / file);
             }
             std::filesystem::remove(ws / "sim/simulation.yaml");
             makeFifo(ws / "sim/simulation.yaml");
             return std::string("simulate --scene jacket-node --max-frames 3 --force --out sim");
           },
       .message = {"sim/simulation.yaml: is a FIFO (named pipe): expected a regular file or a "
                   "new path",
                   "nothing was changed in sim"},
       .absent = {"sim/frames/000002.png"},
       .intact = kEarlierMission,
       .holds = {{"sim/mission.yaml", "name: riser / vertical"}},
       .fifos = {"sim/simulation.yaml"}},
      // One that succeeds leaves its own mission only: the earlier frames past its own and the
      // earlier bag are removed, and said so.
      {.name = "SimulateForceReplacesTheEarlierMissionWhole",
       .prepare =
           [](const Workspace& ws) {
             runCliIn(ws, "simulate --scene riser --max-frames 3 --format mcap --out sim");
             return std::string("simulate --scene jacket-node --max-frames 1 --force --out sim");
           },
       .outcome = Outcome::Succeeds,
       .message = {"removed sim/mission.mcap of an earlier run"},
       .absent = {"sim/frames/000001.png", "sim/frames/000002.png", "sim/mission.mcap"},
       .holds = {{"sim/mission.yaml", "name: jacket-node / vertical"},
                 {"sim/frames.csv", "frames/000000.png"},
                 {"sim/simulation.yaml", "jacket-node"}}},
      keepsEarlierResult("ReconstructWithNoFrameSelectedKeepsAnEarlierResult", "--first-frame 20",
                         {"frames.first (--first-frame)"}),
      keepsEarlierResult("ReconstructOffTheClockKeepsAnEarlierResult", "--time-offset 1000",
                         {"expected frame times on the navigation's clock (--time-offset)"}),
      keepsEarlierResult("ReconstructOverItsMemoryBudgetKeepsAnEarlierResult", "--memory-budget 1",
                         {"(memory_budget_mb)"}),
      // The outputs fail to be written: nothing of the run was moved into out/.
      keepsEarlierResult("ReconstructOnAFullDiskKeepsAnEarlierResult", "",
                         {"out/", "write failed: File too large",
                          "nothing was changed in out (the run's files are written apart first"},
                         1),
      keepsEarlierResult("ReconstructSavingItsMapOnAFullDiskKeepsAnEarlierResult", "--save-map",
                         {"write failed: File too large", "nothing was changed in out"}, 64),
      {.name = "ReconstructRemovesTheStagingOfAKilledRun",
       .prepare =
           [](const Workspace& ws) {
             writePrevious(ws / "out/.run.tmp-999999999/surface_points.ply");
             return std::string("reconstruct mission --out out");
           },
       .outcome = Outcome::Succeeds,
       .message = {"\"frames_used\""},
       .absent = {"out/.run.tmp-999999999"},
       .holds = {{"out/manifest.json", "\"complete\""}}},
      {.name = "ImportOnAFullDisk",
       .prepare = [](const Workspace& ws) { return importCommand(ws) + " --out imported"; },
       .message = {"write failed: File too large",
                   "removed imported, which held the import's partial mission"},
       .absent = {"imported"},
       .file_size_limit_kib = 1},
      {.name = "ImportIntoAnEmptyFolderOnAFullDisk",
       .prepare =
           [](const Workspace& ws) {
             std::filesystem::create_directories(ws / "imported");
             return importCommand(ws) + " --out imported";
           },
       .message = {"write failed: File too large",
                   "emptied imported, which held the import's partial mission"},
       .absent = {"imported/frames", "imported/mission.yaml", "imported/frames.csv",
                  "imported/nav.csv"},
       .file_size_limit_kib = 1},
  };
}

}  // namespace sonarcarve::test
