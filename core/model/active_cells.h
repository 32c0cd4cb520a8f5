// ActiveCells: which parts of a block grid a ray must sample. Each block is split into 2 x 2 x 2
// cells of 4 x 4 x 4 voxels; a cell is active when a sample in one of its voxels can read a
// voxel whose logit reaches a threshold (the trilinear corners of a sample lie within one voxel
// of the voxel that holds it, so each such voxel marks the cells of its 3 x 3 x 3 neighbours).
// A sample elsewhere interpolates logits all below the threshold, so its occupancy is below
// sigmoid(threshold): a ray march that drops such samples may jump over inactive cells and
// get the same samples. Built from the grid as it is; rebuild after its logits change.
#pragma once

#include <cstdint>
#include <vector>

#include "model/block_grid.h"

namespace sonarcarve {

inline constexpr int kCellSide = 4;  ///< voxels on a cell's side; two cells on a block's side

class ActiveCells {
 public:
  /// Every cell of every present block active: a march that jumps only over absent blocks.
  explicit ActiveCells(const BlockGrid& grid);
  /// The cells near voxels of logit >= min_logit.
  ActiveCells(const BlockGrid& grid, double min_logit);
  /// The cells where a sample's occupancy can reach `min_alpha` (every cell unless it is in
  /// (0, 1)).
  static ActiveCells reaching(const BlockGrid& grid, double min_alpha);

  /// The 8-bit mask of block `index`'s cells (bit x + 2 y + 4 z of the cell (x, y, z)).
  std::uint8_t mask(int block) const { return masks_[static_cast<std::size_t>(block)]; }
  static int cellBit(const Eigen::Vector3i& voxel) {
    return ((voxel.x() >> 2) & 1) | (((voxel.y() >> 2) & 1) << 1) | (((voxel.z() >> 2) & 1) << 2);
  }
  bool active(int block, const Eigen::Vector3i& voxel) const {
    return ((mask(block) >> cellBit(voxel)) & 1) != 0;
  }
  /// Share of the present blocks' cells that are active (0 when there are none).
  double activeShare() const;

 private:
  std::vector<std::uint8_t> masks_;
};

}  // namespace sonarcarve
