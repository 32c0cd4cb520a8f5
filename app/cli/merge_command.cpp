// `sonarcarve-cli merge A.scmap B.scmap [...] --out C.scmap`: the voxel-wise minimum of carved
// maps (reconstruct --save-map) on one grid, as if one run had carved all their frames
// (carve/map_file.h): two dives over one structure, or the shards of a long mission.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "carve/map_file.h"
#include "cli/commands.h"
#include "io/files/output_folder.h"

namespace sonarcarve::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string out;
};

// Errors (a broken map names its byte; maps of other grids) reach main, which prints them.
int runMerge(const MergeOptions& o) {
  const auto hold = holdOutputFile(o.out);  // a FIFO or a device as --out fails now
  std::unique_ptr<VoxelMap> merged = loadMap(o.inputs.front());
  for (std::size_t i = 1; i < o.inputs.size(); ++i) {
    const std::unique_ptr<VoxelMap> next = loadMap(o.inputs[i]);
    merged = mergeMaps(*merged, *next);
  }
  saveMap(*merged, o.out);
  std::cout << "merged " << o.inputs.size() << " maps into " << o.out << ": "
            << merged->occupiedCount() << " occupied voxels, "
            << merged->blockCount(VoxelMap::BlockState::Free) << " free and "
            << merged->blockCount(VoxelMap::BlockState::Mixed) << " mixed blocks of "
            << merged->voxelSize() << " m voxels\n";
  return 0;
}

}  // namespace

void addMergeCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "merge", "Merge carved maps (reconstruct --save-map) into one: each voxel keeps its minimum");
  auto o = std::make_shared<MergeOptions>();
  cmd->add_option("maps", o->inputs, "Map files (.scmap), two or more")
      ->required()
      ->expected(2, -1);
  cmd->add_option("--out", o->out, "Map file to write (written atomically)")->required();
  cmd->callback([o, &exit_code] { exit_code = runMerge(*o); });
}

}  // namespace sonarcarve::cli
