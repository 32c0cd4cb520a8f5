#include "pipeline/map_updates.h"

namespace sonarcarve {

MapUpdate changedBlocks(const VoxelMap& map, std::uint32_t since, std::size_t frames_done,
                        const VoxelMap* previous) {
  MapUpdate update;
  update.frames_done = frames_done;
  for (std::size_t b = 0; b < map.blockCount(); ++b) {
    if (map.stamp(b) <= since && (previous == nullptr || previous->stamp(b) == 0)) {
      continue;
    }
    MapBlockUpdate block;
    block.block = b;
    if (const float* v = map.values(b)) {
      for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
        if (v[i] > 0.0f && v[i] < VoxelMap::kUnknown) {
          block.points.push_back(map.voxelCentre(map.voxelIndex(b, i)).cast<float>());
          block.values.push_back(v[i]);
        }
      }
    }
    update.blocks.push_back(std::move(block));
  }
  return update;
}

void MapUpdateSink::frameDone(const VoxelMap* map, std::size_t done, bool last,
                              std::uint32_t stamp) {
  if (map != nullptr && (done % every_ == 0 || last)) {
    observer_.mapUpdated(changedBlocks(*map, last_stamp_, done));
    last_stamp_ = stamp;
  }
}

void MapUpdateSink::replaced(const VoxelMap& map, const VoxelMap* previous,
                             std::size_t frames_done) {
  observer_.mapUpdated(changedBlocks(map, 0, frames_done, previous));
}

}  // namespace sonarcarve
