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
    : voxel_size_m_(voxel_size_m), empty_logit_(empty_logit) {
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
    const double u = std::floor(p_world[axis] / voxel_size_m_);
    if (!(std::abs(u) < kVoxelReach)) {
      return false;
    }
    voxel[axis] = static_cast<int>(u);
  }
  return true;
}

int BlockGrid::findBlock(const Eigen::Vector3i& block) const {
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
  }
  return it->second;
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
