#include "carve/occupancy_export.h"

#include <octomap/OcTree.h>
#include <sstream>
#include <unordered_set>

#include "common/error.h"
#include "io/atomic_file.h"

namespace sonarcarve {
namespace {

octomap::OcTreeKey keyOf(const Eigen::Vector3i& voxel) {
  return {static_cast<octomap::key_type>(voxel.x() + 32768),
          static_cast<octomap::key_type>(voxel.y() + 32768),
          static_cast<octomap::key_type>(voxel.z() + 32768)};
}

}  // namespace

void writeOccupancyBt(const VoxelMap& map, const std::filesystem::path& path) {
  octomap::OcTree tree(map.voxelSize());
  // Occupied voxels on the shell of occupied space; the blocks holding them.
  std::unordered_set<std::size_t> shell_blocks;
  const double block = map.blockSize();
  map.forEachOccupiedOnShell([&](const Eigen::Vector3i& voxel, float) {
    tree.updateNode(keyOf(voxel), true, true);
    const Eigen::Vector3i rel =
        (map.voxelCentre(voxel) / block).array().floor().cast<int>().matrix() - map.firstBlock();
    shell_blocks.insert(map.blockIndex(rel));
  });
  // The carved voxels around them: the free space next to the structure.
  for (const std::size_t b : shell_blocks) {
    const float* v = map.values(b);
    for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
      if (v[i] == 0.0f) {
        tree.updateNode(keyOf(map.voxelIndex(b, i)), false, true);
      }
    }
  }
  tree.updateInnerOccupancy();
  tree.prune();
  std::ostringstream bt;
  if (!tree.writeBinary(bt)) {
    throw Error(path.string(), "", "OctoMap could not encode the .bt file");
  }
  writeFileAtomically(path, bt.str());
}

}  // namespace sonarcarve
