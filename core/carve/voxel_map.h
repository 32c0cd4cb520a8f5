// VoxelMap: the carved map of the fast engine. Each voxel keeps the MINIMUM intensity seen
// over all views that observed it; +inf means never observed (unknown). A voxel is carved
// (empty) at 0 and occupied above 0.
//
// Storage is block-sparse: blocks of 8 x 8 x 8 voxels over a bounded box of the world. A block
// is Unknown (nothing stored), Free (every voxel carved: nothing stored, and it stays so, since
// a minimum never rises), Partial (carved and unknown voxels only, as a mask of its carved
// voxels: 64 bytes; the blocks at the edges of the views, four in five of a riser's) or Mixed
// (512 floats, when a voxel is occupied, or in a map with counts). While views still reach a
// block the carver keeps it as floats, and masks it once they have moved on
// (compactColdBlocks): carving never expands the blocks it works on. Free and unknown space
// therefore cost a few bytes per block, and carving skips free blocks entirely.
//
// Voxel (i, j, k) covers [i, i+1) * voxel_size along north, east, down, as OctoMap's keys do
// (key = index + 32768), so both engines and exported .bt files share one grid.
// Each voxel of a Mixed block also keeps two bytes: its views (how many observed it, to 63,
// and whether any saw it above and any below its axis: a voxel seen from both sides has had
// the sonar's axis pass over it, the views that resolve its elevation; pose refinement aligns
// frames to such settled voxels) and the views that voted to carve it (to 255: robust
// carving carves a voxel once `CarveParams::carve_votes` views agree).
// Limits: the box must hold at most 2^31 blocks; indices fit OctoMap's +-32768 voxels.
// Not thread safe for writing; FastCarver coordinates its threads.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace sonarcarve {

class VoxelMap {
 public:
  static constexpr int kBlockSide = 8;
  static constexpr int kBlockVoxels = kBlockSide * kBlockSide * kBlockSide;
  static constexpr float kUnknown = std::numeric_limits<float>::infinity();
  enum class BlockState : std::uint8_t { Unknown, Free, Mixed, Partial };

  /// Covers `bounds` (world NED, metres), rounded outwards to whole blocks; keeps the voxels'
  /// counts when `with_counts`. Throws Error if the voxel size is not positive or the box is
  /// empty or too large.
  VoxelMap(double voxel_size_m, const Eigen::AlignedBox3d& bounds, bool with_counts = false);
  bool hasCounts() const { return with_counts_; }

  double voxelSize() const { return voxel_size_m_; }
  double blockSize() const { return voxel_size_m_ * kBlockSide; }
  const Eigen::Vector3i& blockDims() const { return dims_; }
  /// Global index of the first block of the box (block = floor(voxel / 8)).
  const Eigen::Vector3i& firstBlock() const { return first_block_; }
  Eigen::AlignedBox3d bounds() const;
  std::size_t blockCount() const { return state_.size(); }

  /// Linear index of a block given in box-relative block coordinates.
  std::size_t blockIndex(const Eigen::Vector3i& rel) const {
    return (static_cast<std::size_t>(rel.z()) * dims_.y() + rel.y()) * dims_.x() + rel.x();
  }
  Eigen::Vector3i blockCoords(std::size_t index) const;
  /// The box-relative blocks [lo, hi] (inclusive) that `box` (world) touches; false if none.
  bool blockSpan(const Eigen::AlignedBox3d& box, Eigen::Vector3i& lo, Eigen::Vector3i& hi) const;
  BlockState state(std::size_t block) const { return state_[block]; }
  /// The 512 values of a Mixed block (x fastest, then y, then z); nullptr otherwise.
  const float* values(std::size_t block) const;
  float* values(std::size_t block);
  /// The 512 values of any block into `out`: unknown (+inf), carved (0) or stored.
  void copyValues(std::size_t block, float* out) const;
  /// The counts of a Mixed block's voxels: views(block)[i] and carveVotes(block)[i] are those
  /// of values(block)[i]; nullptr otherwise and in a map without counts.
  const std::uint8_t* views(std::size_t block) const;
  const std::uint8_t* carveVotes(std::size_t block) const;
  /// Both counts of a Mixed block as one array of 2 x 512 (views, then carve votes).
  std::uint8_t* counts(std::size_t block);
  static constexpr int kCountBytes = 2 * kBlockVoxels;
  static constexpr std::uint8_t kViewCountMask = 0x3F;
  static constexpr std::uint8_t kSeenAbove = 0x40;
  static constexpr std::uint8_t kSeenBelow = 0x80;
  /// Frame stamp of the last change of a block (0: never changed).
  std::uint32_t stamp(std::size_t block) const { return stamp_[block]; }
  /// Notes that a view at `stamp` reached the block. Thread safe for different blocks.
  void markVisited(std::size_t block, std::uint32_t stamp) {
    visited_[block] = static_cast<std::uint16_t>(stamp);
  }
  /// Keeps as masks the Mixed blocks of carved and unknown voxels only that no view has
  /// reached in the `cold_after` stamps before `now`. Not thread safe.
  void compactColdBlocks(std::uint32_t now, std::uint32_t cold_after);

  /// Global index of voxel `i` (0..511, x fastest) of block `block`.
  Eigen::Vector3i voxelIndex(std::size_t block, int i) const {
    return (blockCoords(block) + first_block_) * kBlockSide +
           Eigen::Vector3i(i % kBlockSide, (i / kBlockSide) % kBlockSide,
                           i / (kBlockSide * kBlockSide));
  }
  /// World position of the centre of global voxel `voxel`.
  Eigen::Vector3d voxelCentre(const Eigen::Vector3i& voxel) const {
    return (voxel.cast<double>() + Eigen::Vector3d::Constant(0.5)) * voxel_size_m_;
  }
  /// Global voxel index containing `p_world`.
  Eigen::Vector3i voxelOf(const Eigen::Vector3d& p_world) const;
  /// Value of a global voxel (kUnknown outside the box).
  float value(const Eigen::Vector3i& voxel) const;

  /// Replaces a block's state after carving: `values` (512) are the block's new contents, or
  /// nullptr for Free (kept as Free when every voxel is carved, else Partial or Mixed,
  /// whichever holds them); `counts`
  /// (kCountBytes, or nullptr: zeros for a block that was not Mixed, unchanged otherwise) its
  /// counts. Thread safe against other calls for *different* blocks.
  /// `compact` false keeps values of carved and unknown voxels as floats (a block views still
  /// reach; compactColdBlocks masks it later).
  void storeBlock(std::size_t block, const float* values, std::uint32_t stamp,
                  const std::uint8_t* counts = nullptr, bool compact = true);

  /// Calls f(global voxel index, value) for every occupied voxel (0 < value < inf).
  void forEachOccupied(const std::function<void(const Eigen::Vector3i&, float)>& f) const;
  /// Like forEachOccupied, but only voxels with at least one of their six face neighbours
  /// not occupied: the shell that can be a first return. Voxels buried inside occupied
  /// space (under a seabed that no view could carve) are always behind a neighbour.
  void forEachOccupiedOnShell(const std::function<void(const Eigen::Vector3i&, float)>& f) const;
  std::size_t occupiedCount() const;
  std::size_t blockCount(BlockState state) const;
  /// Bytes held by the map (block table and block contents).
  std::size_t memoryBytes() const;

 private:
  double voxel_size_m_;
  bool with_counts_;
  Eigen::Vector3i first_block_;
  Eigen::Vector3i dims_;
  std::vector<BlockState> state_;
  std::vector<std::int32_t> slot_;  // Mixed blocks: index into storage_ / kBlockVoxels
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint16_t> visited_;    // stamp of the last view that reached a block, mod 2^16
  std::vector<std::int32_t> slot_block_;  // the block a value slot holds, or -1
  // Block contents live in chunks of kChunkBlocks blocks whose addresses never change, so
  // threads may carve Mixed blocks in place while others allocate new ones.
  static constexpr std::size_t kChunkBlocks = 1024;
  float* slotValues(std::int32_t slot) const {
    const auto s = static_cast<std::size_t>(slot);
    return chunks_[s / kChunkBlocks].get() + (s % kChunkBlocks) * kBlockVoxels;
  }
  std::uint8_t* slotCounts(std::int32_t slot) const {
    const auto s = static_cast<std::size_t>(slot);
    return count_chunks_[s / kChunkBlocks].get() + (s % kChunkBlocks) * kCountBytes;
  }
  std::vector<std::unique_ptr<float[]>> chunks_;  // capacity reserved up front
  std::vector<std::unique_ptr<std::uint8_t[]>> count_chunks_;
  std::size_t slots_used_ = 0;
  std::vector<std::int32_t> free_slots_;
  // Partial blocks' masks (bit i: voxel i carved), in chunks as the values are; slot_ of a
  // Partial block indexes them.
  static constexpr int kMaskWords = kBlockVoxels / 64;
  std::uint64_t* slotMask(std::int32_t slot) const {
    const auto s = static_cast<std::size_t>(slot);
    return mask_chunks_[s / kChunkBlocks].get() + (s % kChunkBlocks) * kMaskWords;
  }
  std::vector<std::unique_ptr<std::uint64_t[]>> mask_chunks_;  // capacity reserved up front
  std::size_t mask_slots_used_ = 0;
  std::vector<std::int32_t> free_mask_slots_;
  /// Gives back the block's slot, if it holds one (under storage_mutex_).
  void releaseSlot(std::size_t block);
  /// Keeps `mask` (bit i: voxel i carved) as the block's contents (under storage_mutex_).
  void storeMask(std::size_t block, const std::array<std::uint64_t, 8>& mask);
  std::mutex storage_mutex_;
};

}  // namespace sonarcarve
