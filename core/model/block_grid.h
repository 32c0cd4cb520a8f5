// BlockGrid: the surface the forward model images, a sparse grid of voxels in blocks of
// 8 x 8 x 8. Each voxel holds an occupancy logit o (alpha = sigmoid(o): the chance that a ray
// sample there stops) and a reflectance rho. Voxel v = (i, j, k) covers
// [v * size, (v + 1) * size) in the world frame (metres); its centre is (v + 1/2) * size.
// Blocks are hashed by a 64-bit key of their three 21-bit coordinates, which covers +-2^20
// blocks (+-168 km at 2 cm voxels) on each axis: a coordinate out of that range throws rather
// than wraps. Voxels of absent blocks are empty: logit emptyLogit(), reflectance 0.
// The parameters live in two flat arrays, block after block (block index * 512 + local
// index), which is also the layout of their gradients (model/model_gradient.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sonarcarve {

inline constexpr int kBlockSide = 8;
inline constexpr int kBlockVoxels = kBlockSide * kBlockSide * kBlockSide;

class BlockGrid {
 public:
  /// Throws Error unless voxel_size_m > 0. `empty_logit`: the logit of absent voxels and of new
  /// blocks' voxels.
  explicit BlockGrid(double voxel_size_m, float empty_logit = -12.0f);

  double voxelSize() const { return voxel_size_m_; }
  float emptyLogit() const { return empty_logit_; }

  /// The key of a block; throws Error if a coordinate is outside [-2^20, 2^20).
  static std::int64_t blockKey(const Eigen::Vector3i& block);
  /// The voxel that contains a world point (floor of p / size, computed as p times 1 / size),
  /// if it is within the grid's reach.
  bool voxelOf(const Eigen::Vector3d& p_world, Eigen::Vector3i& voxel) const;
  Eigen::Vector3d voxelCentre(const Eigen::Vector3i& voxel) const {
    return (voxel.cast<double>().array() + 0.5).matrix() * voxel_size_m_;
  }

  /// The index of a block, or -1 if absent.
  int findBlock(const Eigen::Vector3i& block) const;
  /// The index of a block, added (empty) if absent.
  int addBlock(const Eigen::Vector3i& block);
  /// Flat index of a voxel's parameters, or -1 if its block is absent.
  std::int64_t voxelIndex(const Eigen::Vector3i& voxel) const;
  /// Flat index of a voxel's parameters, its block added if absent.
  std::int64_t addVoxel(const Eigen::Vector3i& voxel);

  /// The box (world frame, metres) that holds every block; empty if there are none.
  const Eigen::AlignedBox3d& bounds() const { return bounds_; }

  int blockCount() const { return static_cast<int>(block_coords_.size()); }
  const Eigen::Vector3i& blockCoords(int index) const {
    return block_coords_[static_cast<std::size_t>(index)];
  }
  /// The voxel at flat index `index`.
  Eigen::Vector3i voxelAt(std::int64_t index) const;
  std::size_t voxelCount() const { return logits_.size(); }

  std::vector<float>& logits() { return logits_; }
  const std::vector<float>& logits() const { return logits_; }
  std::vector<float>& reflectance() { return reflectance_; }
  const std::vector<float>& reflectance() const { return reflectance_; }

  /// The block of a voxel and the voxel's index inside it.
  static Eigen::Vector3i blockOf(const Eigen::Vector3i& voxel) {
    return {voxel.x() >> 3, voxel.y() >> 3, voxel.z() >> 3};
  }
  static int localIndex(const Eigen::Vector3i& voxel) {
    return ((voxel.z() & 7) * kBlockSide + (voxel.y() & 7)) * kBlockSide + (voxel.x() & 7);
  }

 private:
  double voxel_size_m_;
  double inverse_size_;  // voxelOf multiplies: the rays' every step asks it
  float empty_logit_;
  // Blocks are also found through a dense table over a box around them while that box holds at
  // most kDenseCells blocks (a structure's band; the rays' many look-ups of absent blocks then
  // cost an array read, not a hash); past it, through the hash alone.
  static constexpr std::int64_t kDenseCells = std::int64_t{1} << 24;
  void indexDensely(const Eigen::Vector3i& block, int index);
  std::size_t denseCell(const Eigen::Vector3i& rel) const;  // rel: from dense_lo_
  std::unordered_map<std::int64_t, int> blocks_;
  Eigen::Vector3i dense_lo_ = Eigen::Vector3i::Zero();
  Eigen::Vector3i dense_dims_ = Eigen::Vector3i::Zero();
  std::vector<int> dense_;
  bool dense_given_up_ = false;
  std::vector<Eigen::Vector3i> block_coords_;
  Eigen::AlignedBox3d bounds_;
  std::vector<float> logits_;
  std::vector<float> reflectance_;
};

}  // namespace sonarcarve
