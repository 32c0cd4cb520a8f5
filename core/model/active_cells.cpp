#include "model/active_cells.h"

#include <bit>
#include <cmath>

namespace sonarcarve {

ActiveCells::ActiveCells(const BlockGrid& grid)
    : masks_(static_cast<std::size_t>(grid.blockCount()), 0xFF) {}

ActiveCells::ActiveCells(const BlockGrid& grid, double min_logit)
    : masks_(static_cast<std::size_t>(grid.blockCount()), 0) {
  if (grid.emptyLogit() >= min_logit) {
    masks_.assign(masks_.size(), 0xFF);  // even absent voxels count: every cell is needed
    return;
  }
  const std::vector<float>& logits = grid.logits();
  for (int block = 0; block < grid.blockCount(); ++block) {
    const Eigen::Vector3i first = grid.blockCoords(block) * kBlockSide;
    const std::size_t base = static_cast<std::size_t>(block) * kBlockVoxels;
    for (int local = 0; local < kBlockVoxels; ++local) {
      if (!(logits[base + static_cast<std::size_t>(local)] >= min_logit)) {
        continue;
      }
      const Eigen::Vector3i voxel =
          first + Eigen::Vector3i(local % kBlockSide, (local / kBlockSide) % kBlockSide,
                                  local / (kBlockSide * kBlockSide));
      // The cells of voxel +- 1 on each axis cover those of its 27 neighbours (a cell is
      // wider than 2 voxels).
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3i near =
            voxel + Eigen::Vector3i((corner & 1) != 0 ? 1 : -1, (corner & 2) != 0 ? 1 : -1,
                                    (corner & 4) != 0 ? 1 : -1);
        const Eigen::Vector3i near_block = BlockGrid::blockOf(near);
        const int index =
            near_block == grid.blockCoords(block) ? block : grid.findBlock(near_block);
        if (index >= 0) {
          masks_[static_cast<std::size_t>(index)] |=
              static_cast<std::uint8_t>(1u << static_cast<unsigned>(cellBit(near)));
        }
      }
    }
  }
}

ActiveCells ActiveCells::reaching(const BlockGrid& grid, double min_alpha) {
  return min_alpha > 0.0 && min_alpha < 1.0
             ? ActiveCells(grid, std::log(min_alpha / (1.0 - min_alpha)))
             : ActiveCells(grid);
}

double ActiveCells::activeShare() const {
  if (masks_.empty()) {
    return 0.0;
  }
  std::size_t active = 0;
  for (const std::uint8_t m : masks_) {
    active += static_cast<std::size_t>(std::popcount(m));
  }
  return static_cast<double>(active) / (8.0 * static_cast<double>(masks_.size()));
}

}  // namespace sonarcarve
