// VoxelStencil: what the forward model reads of the grid around one ray sample. The logit and
// the reflectance at a point are trilinear in the eight voxel centres around it; the occupancy
// gradient there is the trilinear blend of the eight voxels' central differences of the logit,
// which reads the 4 x 4 x 4 voxels around the point. A blend of central differences, not the
// derivative of the trilinear field, so that the normal (and so the incidence) moves
// continuously with the point: the model stays continuous in the pose.
// Corner c = cx + 2 cy + 4 cz, (cx, cy, cz) in {0, 1}^3; patch voxel (x, y, z) in 0..3 at
// x + 4 y + 16 z, the corners at 1..2. Absent voxels have index -1 and the empty logit.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "model/active_cells.h"
#include "model/block_grid.h"

namespace sonarcarve {

struct VoxelStencil {
  Eigen::Vector3i base;                     ///< corner 0's voxel
  std::array<double, 8> weight{};           ///< trilinear weight of each corner
  std::array<Eigen::Vector3d, 8> d_weight;  ///< its gradient in the point, per metre
  std::array<std::int64_t, 64> index{};     ///< the patch's flat parameter indices (-1: absent)
  std::array<double, 64> logit{};
  std::array<double, 8> reflectance{};

  static int patch(int x, int y, int z) { return x + 4 * y + 16 * z; }
  static int cornerPatch(int c) { return patch(1 + (c & 1), 1 + ((c >> 1) & 1), 1 + (c >> 2)); }

  double logitAt() const;
  double reflectanceAt() const;
  /// Central difference of the logit at corner c (per metre).
  Eigen::Vector3d cornerGradient(int c, double voxel_size) const;
  /// The blended occupancy gradient at the point.
  Eigen::Vector3d gradientAt(double voxel_size) const;
};

/// Reads the grid around world points; remembers the blocks it last found.
class StencilReader {
 public:
  /// `active` (optional, must outlive the reader): the cells a march samples; without, every
  /// cell of every present block.
  explicit StencilReader(const BlockGrid& grid, const ActiveCells* active = nullptr)
      : grid_(grid), active_(active) {}

  const Eigen::AlignedBox3d& bounds() const { return grid_.bounds(); }

  /// Whether the voxel that contains `p` lies in an active cell of a present block; if not,
  /// `exit_m` is how far along `direction` from `p` the ray leaves that (absent) block, or that
  /// block's inactive cell (the whole block if none of its cells is active).
  bool inSampledCell(const Eigen::Vector3d& p, const Eigen::Vector3d& direction, double& exit_m);
  /// Weights and the eight corners' logits (cheap: enough for the occupancy).
  void readCorners(const Eigen::Vector3d& p, VoxelStencil& stencil);
  /// The rest of the patch's logits and the corners' reflectance.
  void readPatch(VoxelStencil& stencil);

 private:
  void findBlocks(const Eigen::Vector3i& lo, const Eigen::Vector3i& hi);
  std::int64_t indexOf(const Eigen::Vector3i& voxel) const;

  const BlockGrid& grid_;
  const ActiveCells* active_;
  Eigen::Vector3i block_lo_{0, 0, 0};
  Eigen::Vector3i block_hi_{0, 0, 0};
  std::array<int, 8> blocks_{};  // of block_lo_ / block_hi_ on each axis
  bool found_ = false;
  Eigen::Vector3i sampled_block_{0, 0, 0};  // inSampledCell's last block and its index
  int sampled_index_ = -1;
  bool sampled_found_ = false;
};

}  // namespace sonarcarve
