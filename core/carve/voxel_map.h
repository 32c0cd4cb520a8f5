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
// The block table is paged: a page holds the table entries of a cube of 8^3 blocks (1.28 m at
// 2 cm voxels) and exists only once something is stored there (or a carver reaches it), so an
// empty region of the box costs a null pointer; releasePage lets a finished region go
// (eviction, docs/scaling.md). A block's index is its page's, times 512, plus its place in the
// page: indices run page by page, not along the box's rows.
// Limits: the box must hold at most 2^31 blocks and lie within kMaxVoxelIndex voxels of the
// origin on every axis (the mission origin keeps survey maps near zero); map.bt holds the voxels
// within OctoMap's +-32768 (carve/occupancy_export.h).
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
  /// The farthest a map reaches from its origin on any axis, in voxels: 2^25 (671 km at 2 cm).
  /// Voxel indices are 32-bit and the surface mesher packs tiles of 64 voxels in 21 bits
  /// (+-2^26 voxels); half of that leaves room for every border and product of them.
  static constexpr double kMaxVoxelIndex = 33554432.0;
  enum class BlockState : std::uint8_t { Unknown, Free, Mixed, Partial };

  /// Covers `bounds` (world NED, metres), rounded outwards to whole blocks; keeps the voxels'
  /// counts when `with_counts`. Throws Error if the voxel size is not positive or the box is
  /// empty, too large or reaches beyond kMaxVoxelIndex voxels from the origin (never a wrapped
  /// or overflowed index).
  VoxelMap(double voxel_size_m, const Eigen::AlignedBox3d& bounds, bool with_counts = false);
  bool hasCounts() const { return with_counts_; }

  double voxelSize() const { return voxel_size_m_; }
  double blockSize() const { return voxel_size_m_ * kBlockSide; }
  const Eigen::Vector3i& blockDims() const { return dims_; }
  /// Global index of the first block of the box (block = floor(voxel / 8)).
  const Eigen::Vector3i& firstBlock() const { return first_block_; }
  Eigen::AlignedBox3d bounds() const;
  /// Size of the blocks' index space (pages x 512): indices past the box's edges in its last
  /// pages stay Unknown.
  std::size_t blockCount() const { return pages_.size() * kPageBlocks; }

  static constexpr int kPageSide = 8;  ///< blocks a side of a page of the block table
  static constexpr int kPageBlocks = kPageSide * kPageSide * kPageSide;
  /// Index of a block given in box-relative block coordinates.
  std::size_t blockIndex(const Eigen::Vector3i& rel) const {
    const Eigen::Vector3i page(rel.x() >> 3, rel.y() >> 3, rel.z() >> 3);
    const auto in = static_cast<std::size_t>(
        ((rel.z() & 7) * kPageSide + (rel.y() & 7)) * kPageSide + (rel.x() & 7));
    return pageIndex(page) * kPageBlocks + in;
  }
  Eigen::Vector3i blockCoords(std::size_t index) const;
  /// The box's blocks in the order of rows (x fastest, then y, then z), as map files store
  /// them: the n-th block of that order, and a block's place in it.
  std::size_t blockAtRowOrder(std::size_t n) const;
  std::size_t rowOrderOf(std::size_t block) const;
  std::size_t boxBlockCount() const {
    return static_cast<std::size_t>(dims_.x()) * dims_.y() * dims_.z();
  }

  /// Pages of the block table: their grid over the box, index and coordinates.
  const Eigen::Vector3i& pageDims() const { return page_dims_; }
  std::size_t pageCount() const { return pages_.size(); }
  std::size_t pageIndex(const Eigen::Vector3i& page) const {
    return (static_cast<std::size_t>(page.z()) * page_dims_.y() + page.y()) * page_dims_.x() +
           page.x();
  }
  Eigen::Vector3i pageCoords(std::size_t page) const;
  static std::size_t pageOf(std::size_t block) { return block / kPageBlocks; }
  bool pageHeld(std::size_t page) const { return pages_[page] != nullptr; }
  std::size_t pagesHeld() const { return pages_held_; }
  /// Makes room in the table for the box-relative blocks [lo, hi] (inclusive): a carver calls
  /// it before its threads reach them. Not thread safe.
  void holdPages(const Eigen::Vector3i& lo, const Eigen::Vector3i& hi);
  /// Lets a page's blocks go: their contents and the page's table entries; they read Unknown
  /// afterwards. Not thread safe.
  void releasePage(std::size_t page);
  /// A held page as bytes: its table entries and its blocks' contents (and counts), so that
  /// it can be let go and held again later exactly as it was (carve/page_spill.h).
  std::vector<std::uint8_t> packPage(std::size_t page) const;
  /// Holds a page that is not held from packPage's bytes. Throws Error if they are not a
  /// page of this map. Not thread safe.
  void unpackPage(std::size_t page, const std::vector<std::uint8_t>& bytes);
  /// The box-relative blocks [lo, hi] (inclusive) that `box` (world) touches; false if none.
  bool blockSpan(const Eigen::AlignedBox3d& box, Eigen::Vector3i& lo, Eigen::Vector3i& hi) const;
  BlockState state(std::size_t block) const {
    const Page* p = pages_[pageOf(block)].get();
    return p == nullptr ? BlockState::Unknown : p->state[block % kPageBlocks];
  }
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
  std::uint32_t stamp(std::size_t block) const {
    const Page* p = pages_[pageOf(block)].get();
    return p == nullptr ? 0 : p->stamp[block % kPageBlocks];
  }
  /// Notes that a view at `stamp` reached the block, whose page is held (holdPages). Thread
  /// safe for different blocks.
  void markVisited(std::size_t block, std::uint32_t stamp) {
    pages_[pageOf(block)]->visited[block % kPageBlocks] = static_cast<std::uint16_t>(stamp);
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

  /// Sets global voxels (inside the box) to values, block by block (storeBlock; counts kept).
  /// Not thread safe.
  void setVoxels(const std::vector<std::pair<Eigen::Vector3i, float>>& voxels);

  /// Calls f(global voxel index, value) for every occupied voxel (0 < value < inf).
  void forEachOccupied(const std::function<void(const Eigen::Vector3i&, float)>& f) const;
  /// Like forEachOccupied, but only voxels with at least one of their six face neighbours
  /// not occupied: the shell that can be a first return. Voxels buried inside occupied
  /// space (under a seabed that no view could carve) are always behind a neighbour.
  void forEachOccupiedOnShell(const std::function<void(const Eigen::Vector3i&, float)>& f) const;
  /// The same within one page (reading its neighbours' voxels at its faces), block by block.
  void forEachOccupiedOnShellIn(std::size_t page,
                                const std::function<void(const Eigen::Vector3i&, float)>& f) const;
  std::size_t occupiedCount() const;
  std::size_t blockCount(BlockState state) const;
  /// Bytes held by the map (block table and block contents).
  std::size_t memoryBytes() const;

 private:
  double voxel_size_m_;
  bool with_counts_;
  Eigen::Vector3i first_block_;
  Eigen::Vector3i dims_;
  Eigen::Vector3i page_dims_;
  // The table entries of a page's blocks.
  struct Page {
    std::array<BlockState, kPageBlocks> state{};
    std::array<std::int32_t, kPageBlocks> slot{};  // Mixed: value slot; Partial: mask slot
    std::array<std::uint32_t, kPageBlocks> stamp{};
    std::array<std::uint16_t, kPageBlocks> visited{};  // stamp of the last view, mod 2^16
  };
  std::vector<std::unique_ptr<Page>> pages_;
  std::size_t pages_held_ = 0;
  /// The page of a block, made when missing (under storage_mutex_ when threads store).
  Page& heldPage(std::size_t block);
  std::int32_t& slotOf(std::size_t block) const {
    return pages_[pageOf(block)]->slot[block % kPageBlocks];
  }
  BlockState& stateOf(std::size_t block) const {
    return pages_[pageOf(block)]->state[block % kPageBlocks];
  }
  /// The block holding global voxel `voxel` and the voxel's place in it (x fastest); false
  /// outside the box.
  bool locate(const Eigen::Vector3i& voxel, std::size_t& block, int& in) const;
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
  /// A value slot (and counts) for `block`, which becomes its owner (under storage_mutex_).
  std::int32_t takeValueSlot(std::size_t block);
  /// A mask slot (under storage_mutex_).
  std::int32_t takeMaskSlot();
  /// Gives back the block's slot, if it holds one (under storage_mutex_).
  void releaseSlot(std::size_t block);
  /// Keeps `mask` (bit i: voxel i carved) as the block's contents (under storage_mutex_).
  void storeMask(std::size_t block, const std::array<std::uint64_t, 8>& mask);
  std::mutex storage_mutex_;
};

}  // namespace sonarcarve
