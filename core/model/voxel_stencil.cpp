#include "model/voxel_stencil.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sonarcarve {

double VoxelStencil::logitAt() const {
  double o = 0.0;
  for (int c = 0; c < 8; ++c) {
    o += weight[static_cast<std::size_t>(c)] * logit[static_cast<std::size_t>(cornerPatch(c))];
  }
  return o;
}

double VoxelStencil::reflectanceAt() const {
  double rho = 0.0;
  for (std::size_t c = 0; c < 8; ++c) {
    rho += weight[c] * reflectance[c];
  }
  return rho;
}

Eigen::Vector3d VoxelStencil::cornerGradient(int c, double voxel_size) const {
  const int at = cornerPatch(c);
  const auto l = [&](int offset) { return logit[static_cast<std::size_t>(at + offset)]; };
  const double scale = 0.5 / voxel_size;
  return {scale * (l(1) - l(-1)), scale * (l(4) - l(-4)), scale * (l(16) - l(-16))};
}

Eigen::Vector3d VoxelStencil::gradientAt(double voxel_size) const {
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (int c = 0; c < 8; ++c) {
    g += weight[static_cast<std::size_t>(c)] * cornerGradient(c, voxel_size);
  }
  return g;
}

namespace {

// How far along `direction` from `p` the ray leaves the axis-aligned cube of side `side` metres
// whose lowest corner is `corner` (in units of the side).
double cubeExit(const Eigen::Vector3i& corner, double side, const Eigen::Vector3d& p,
                const Eigen::Vector3d& direction) {
  double exit_m = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double d = direction[axis];
    if (std::abs(d) > 1e-12) {
      const double wall = (corner[axis] + (d > 0.0 ? 1 : 0)) * side;
      exit_m = std::min(exit_m, (wall - p[axis]) / d);
    }
  }
  return std::max(exit_m, 0.0);
}

}  // namespace

bool StencilReader::inSampledCell(const Eigen::Vector3d& p, const Eigen::Vector3d& direction,
                                  double& exit_m) {
  Eigen::Vector3i voxel;
  if (!grid_.voxelOf(p, voxel)) {
    exit_m = grid_.voxelSize();
    return false;
  }
  // One block of its own remembered: the stencil's reads keep findBlocks' range for theirs.
  const Eigen::Vector3i block_coords = BlockGrid::blockOf(voxel);
  if (!sampled_found_ || block_coords != sampled_block_) {
    sampled_block_ = block_coords;
    sampled_index_ = grid_.findBlock(block_coords);
    sampled_found_ = true;
  }
  const int block = sampled_index_;
  if (block >= 0 && (active_ == nullptr || active_->active(block, voxel))) {
    return true;
  }
  const double size = grid_.voxelSize();
  if (block < 0 || active_->mask(block) == 0) {
    exit_m = cubeExit(BlockGrid::blockOf(voxel), size * kBlockSide, p, direction);
  } else {
    const Eigen::Vector3i cell(voxel.x() >> 2, voxel.y() >> 2, voxel.z() >> 2);
    exit_m = cubeExit(cell, size * kCellSide, p, direction);
  }
  return false;
}

void StencilReader::findBlocks(const Eigen::Vector3i& lo, const Eigen::Vector3i& hi) {
  const Eigen::Vector3i block_lo = BlockGrid::blockOf(lo);
  const Eigen::Vector3i block_hi = BlockGrid::blockOf(hi);
  if (found_ && block_lo == block_lo_ && block_hi == block_hi_) {
    return;
  }
  block_lo_ = block_lo;
  block_hi_ = block_hi;
  // Axes on which the range spans one block take block_lo's entry: no second look-up.
  const int spans = (block_hi.x() != block_lo.x() ? 1 : 0) |
                    (block_hi.y() != block_lo.y() ? 2 : 0) | (block_hi.z() != block_lo.z() ? 4 : 0);
  for (int s = 0; s < 8; ++s) {
    if ((s & ~spans) != 0) {
      blocks_[static_cast<std::size_t>(s)] = blocks_[static_cast<std::size_t>(s & spans)];
      continue;
    }
    const Eigen::Vector3i block((s & 1) != 0 ? block_hi.x() : block_lo.x(),
                                (s & 2) != 0 ? block_hi.y() : block_lo.y(),
                                (s & 4) != 0 ? block_hi.z() : block_lo.z());
    blocks_[static_cast<std::size_t>(s)] = grid_.findBlock(block);
  }
  found_ = true;
}

std::int64_t StencilReader::indexOf(const Eigen::Vector3i& voxel) const {
  const Eigen::Vector3i block = BlockGrid::blockOf(voxel);
  const int s = (block.x() != block_lo_.x() ? 1 : 0) + (block.y() != block_lo_.y() ? 2 : 0) +
                (block.z() != block_lo_.z() ? 4 : 0);
  const int found = blocks_[static_cast<std::size_t>(s)];
  return found < 0 ? -1 : std::int64_t{found} * kBlockVoxels + BlockGrid::localIndex(voxel);
}

void StencilReader::readCorners(const Eigen::Vector3d& p, VoxelStencil& stencil) {
  const double size = grid_.voxelSize();
  const Eigen::Vector3d u = p / size - Eigen::Vector3d::Constant(0.5);
  const Eigen::Vector3d floor_u = u.array().floor();
  stencil.base = floor_u.cast<int>();
  const Eigen::Vector3d f = u - floor_u;
  findBlocks(stencil.base, stencil.base + Eigen::Vector3i::Ones());
  const std::vector<float>& logits = grid_.logits();
  // Per axis, the weights of the lower and upper corner and their derivatives.
  const double wx[2] = {1.0 - f.x(), f.x()};
  const double wy[2] = {1.0 - f.y(), f.y()};
  const double wz[2] = {1.0 - f.z(), f.z()};
  const double dw[2] = {-1.0 / size, 1.0 / size};
  for (int c = 0; c < 8; ++c) {
    const int x = c & 1;
    const int y = (c >> 1) & 1;
    const int z = c >> 2;
    const auto cu = static_cast<std::size_t>(c);
    stencil.weight[cu] = wx[x] * wy[y] * wz[z];
    stencil.d_weight[cu] = {dw[x] * wy[y] * wz[z], wx[x] * dw[y] * wz[z], wx[x] * wy[y] * dw[z]};
    const std::int64_t index = indexOf(stencil.base + Eigen::Vector3i(x, y, z));
    const auto at = static_cast<std::size_t>(VoxelStencil::cornerPatch(c));
    stencil.index[at] = index;
    stencil.logit[at] = index < 0 ? grid_.emptyLogit() : logits[static_cast<std::size_t>(index)];
  }
}

void StencilReader::readPatch(VoxelStencil& stencil) {
  const Eigen::Vector3i lo = stencil.base - Eigen::Vector3i::Ones();
  findBlocks(lo, lo + Eigen::Vector3i::Constant(3));
  const std::vector<float>& logits = grid_.logits();
  for (int z = 0; z < 4; ++z) {
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 4; ++x) {
        const bool corner = x >= 1 && x <= 2 && y >= 1 && y <= 2 && z >= 1 && z <= 2;
        if (corner) {
          continue;  // read by readCorners
        }
        const std::int64_t index = indexOf(lo + Eigen::Vector3i(x, y, z));
        const auto at = static_cast<std::size_t>(VoxelStencil::patch(x, y, z));
        stencil.index[at] = index;
        stencil.logit[at] =
            index < 0 ? grid_.emptyLogit() : logits[static_cast<std::size_t>(index)];
      }
    }
  }
  for (int c = 0; c < 8; ++c) {
    const std::int64_t index =
        stencil.index[static_cast<std::size_t>(VoxelStencil::cornerPatch(c))];
    stencil.reflectance[static_cast<std::size_t>(c)] =
        index < 0 ? 0.0 : grid_.reflectance()[static_cast<std::size_t>(index)];
  }
}

}  // namespace sonarcarve
