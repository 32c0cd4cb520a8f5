#include "model/block_grid.h"

#include <cmath>

#include "common/error.h"

namespace sonarcarve {
namespace {

constexpr std::int64_t kKeyBits = 21;
constexpr std::int64_t kKeyHalf = std::int64_t{1} << (kKeyBits - 1);
// Voxel coordinates stay far inside int: blocks within +-2^20 hold voxels within +-2^23.
constexpr double kVoxelReach = static_cast<double>(kKeyHalf * kBlockSide);

}  // namespace

BlockGrid::BlockGrid(double voxel_size_m, float empty_logit)
    : voxel_size_m_(voxel_size_m), inverse_size_(1.0 / voxel_size_m), empty_logit_(empty_logit) {
  if (!(voxel_size_m > 0.0) || !std::isfinite(voxel_size_m)) {
    throw Error("model grid", "voxel size", "expected a positive finite voxel size");
  }
}

std::int64_t BlockGrid::blockKey(const Eigen::Vector3i& block) {
  std::int64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const std::int64_t c = block[axis];
    if (c < -kKeyHalf || c >= kKeyHalf) {
      throw Error("model grid", "block", "block coordinate out of the grid's reach");
    }
    key = (key << kKeyBits) | (c + kKeyHalf);
  }
  return key;
}

bool BlockGrid::voxelOf(const Eigen::Vector3d& p_world, Eigen::Vector3i& voxel) const {
  for (int axis = 0; axis < 3; ++axis) {
    const double u = std::floor(p_world[axis] * inverse_size_);
    if (!(std::abs(u) < kVoxelReach)) {
      return false;
    }
    voxel[axis] = static_cast<int>(u);
  }
  return true;
}

int BlockGrid::findBlock(const Eigen::Vector3i& block) const {
  if (!dense_.empty()) {
    const Eigen::Vector3i rel = block - dense_lo_;
    if ((rel.array() < 0).any() || (rel.array() >= dense_dims_.array()).any()) {
      return -1;
    }
    return dense_[denseCell(rel)];
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (block[axis] < -kKeyHalf || block[axis] >= kKeyHalf) {
      return -1;
    }
  }
  const auto it = blocks_.find(blockKey(block));
  return it == blocks_.end() ? -1 : it->second;
}

int BlockGrid::addBlock(const Eigen::Vector3i& block) {
  const auto [it, added] = blocks_.try_emplace(blockKey(block), blockCount());
  if (added) {
    block_coords_.push_back(block);
    const double side = voxel_size_m_ * kBlockSide;
    bounds_.extend(block.cast<double>() * side);
    bounds_.extend((block.cast<double>().array() + 1.0).matrix() * side);
    logits_.resize(logits_.size() + kBlockVoxels, empty_logit_);
    reflectance_.resize(reflectance_.size() + kBlockVoxels, 0.0f);
    indexDensely(block, it->second);
  }
  return it->second;
}

std::size_t BlockGrid::denseCell(const Eigen::Vector3i& rel) const {
  return (static_cast<std::size_t>(rel.z()) * static_cast<std::size_t>(dense_dims_.y()) +
          static_cast<std::size_t>(rel.y())) *
             static_cast<std::size_t>(dense_dims_.x()) +
         static_cast<std::size_t>(rel.x());
}

void BlockGrid::indexDensely(const Eigen::Vector3i& block, int index) {
  if (dense_given_up_) {
    return;
  }
  const Eigen::Vector3i rel = block - dense_lo_;
  const bool inside =
      !dense_.empty() && (rel.array() >= 0).all() && (rel.array() < dense_dims_.array()).all();
  if (!inside) {
    // A box around every block with a margin of half its size on each side, so that a grid
    // growing block by block rebuilds the table a logarithmic number of times.
    Eigen::AlignedBox3i box(block);
    for (const Eigen::Vector3i& b : block_coords_) {
      box.extend(b);
    }
    const Eigen::Vector3i margin = (box.sizes() / 2).array() + 2;
    const Eigen::Vector3i lo = box.min() - margin;
    const Eigen::Vector3i dims = box.sizes() + 2 * margin + Eigen::Vector3i::Ones();
    const std::int64_t cells = std::int64_t{dims.x()} * dims.y() * dims.z();
    if (cells > kDenseCells) {
      dense_given_up_ = true;
      dense_.clear();
      dense_.shrink_to_fit();
      return;
    }
    dense_lo_ = lo;
    dense_dims_ = dims;
    dense_.assign(static_cast<std::size_t>(cells), -1);
    for (std::size_t i = 0; i < block_coords_.size(); ++i) {
      dense_[denseCell(block_coords_[i] - dense_lo_)] = static_cast<int>(i);
    }
    return;
  }
  dense_[denseCell(rel)] = index;
}

std::int64_t BlockGrid::voxelIndex(const Eigen::Vector3i& voxel) const {
  const int block = findBlock(blockOf(voxel));
  return block < 0 ? -1 : std::int64_t{block} * kBlockVoxels + localIndex(voxel);
}

std::int64_t BlockGrid::addVoxel(const Eigen::Vector3i& voxel) {
  return std::int64_t{addBlock(blockOf(voxel))} * kBlockVoxels + localIndex(voxel);
}

Eigen::Vector3i BlockGrid::voxelAt(std::int64_t index) const {
  const auto local = static_cast<int>(index % kBlockVoxels);
  const Eigen::Vector3i offset(local % kBlockSide, (local / kBlockSide) % kBlockSide,
                               local / (kBlockSide * kBlockSide));
  return blockCoords(static_cast<int>(index / kBlockVoxels)) * kBlockSide + offset;
}

}  // namespace sonarcarve
