#include "carve/occupancy_export.h"

#include <octomap/OcTree.h>
#include <algorithm>

#include "common/error.h"
#include "io/atomic_file.h"

namespace sonarcarve {

void writeOccupancyBt(const VoxelMap& map, const std::filesystem::path& path) {
  octomap::OcTree tree(map.voxelSize());
  for (std::size_t b = 0; b < map.blockCount(); ++b) {
    const float* v = map.values(b);
    if (v == nullptr || std::none_of(v, v + VoxelMap::kBlockVoxels,
                                     [](float x) { return x > 0.0f && x < VoxelMap::kUnknown; })) {
      continue;
    }
    const Eigen::Vector3i base = (map.blockCoords(b) + map.firstBlock()) * VoxelMap::kBlockSide;
    for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
      if (v[i] == VoxelMap::kUnknown) {
        continue;
      }
      const Eigen::Vector3i voxel =
          base + Eigen::Vector3i(i % VoxelMap::kBlockSide,
                                 (i / VoxelMap::kBlockSide) % VoxelMap::kBlockSide,
                                 i / (VoxelMap::kBlockSide * VoxelMap::kBlockSide));
      const octomap::OcTreeKey key(static_cast<octomap::key_type>(voxel.x() + 32768),
                                   static_cast<octomap::key_type>(voxel.y() + 32768),
                                   static_cast<octomap::key_type>(voxel.z() + 32768));
      tree.updateNode(key, v[i] > 0.0f, true);
    }
  }
  tree.updateInnerOccupancy();
  tree.prune();
  replaceFileAtomically(path, [&](const std::filesystem::path& tmp) {
    if (!tree.writeBinary(tmp.string())) {
      throw Error(path.string(), "", "OctoMap could not write the .bt file");
    }
  });
}

}  // namespace sonarcarve
