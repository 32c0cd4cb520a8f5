#include "carve/voxel_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "common/error.h"
#include "common/floor_div.h"
#include "common/number_text.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// The mask of a block's carved voxels, if it holds carved and unknown voxels only.
bool carvedMask(const float* values, std::array<std::uint64_t, 8>& mask) {
  for (std::size_t w = 0; w < mask.size(); ++w) {
    const float* v = values + 64 * w;
    std::uint64_t carved = 0;
    bool only_carved_or_unknown = true;
    for (int i = 0; i < 64; ++i) {  // no branch: the compiler vectorises it
      carved |= static_cast<std::uint64_t>(v[i] == 0.0f) << i;
      only_carved_or_unknown &= v[i] == 0.0f || v[i] == VoxelMap::kUnknown;
    }
    if (!only_carved_or_unknown) {
      return false;
    }
    mask[w] = carved;
  }
  return true;
}

// A slot of a pool: one given back before, or a new one (`new_chunk` adds room for
// kChunkBlocks more when the last chunk is full).
template <typename NewChunk>
std::int32_t takeSlot(std::vector<std::int32_t>& free, std::size_t& used, std::size_t chunk,
                      NewChunk&& new_chunk) {
  if (!free.empty()) {
    const std::int32_t slot = free.back();
    free.pop_back();
    return slot;
  }
  if (used % chunk == 0) {
    new_chunk();
  }
  return static_cast<std::int32_t>(used++);
}
}  // namespace

VoxelMap::VoxelMap(double voxel_size_m, const Eigen::AlignedBox3d& bounds, bool with_counts)
    : voxel_size_m_(voxel_size_m), with_counts_(with_counts) {
  if (!(voxel_size_m > 0.0) || bounds.isEmpty()) {
    throw Error("voxel map", "", "expected a positive voxel size and a non-empty region");
  }
  const double reach_voxels =
      std::max(bounds.min().cwiseAbs().maxCoeff(), bounds.max().cwiseAbs().maxCoeff()) /
      voxel_size_m;
  if (!(reach_voxels < kMaxVoxelIndex)) {
    throw Error(
        "voxel map", "box (" + nedText(bounds.min()) + ") to (" + nedText(bounds.max()) + ") m",
        "the map reaches " + shortestNumber(reach_voxels) +
            " voxels from its origin: expected at most 2^25 = " + shortestNumber(kMaxVoxelIndex) +
            " (+-" + shortestNumber(kMaxVoxelIndex * voxel_size_m) + " m at " +
            shortestNumber(voxel_size_m) +
            " m voxels); navigation is moved to a mission origin near the track, so a "
            "map this far holds a track or a range this long");
  }
  const Eigen::Vector3i lo = voxelOf(bounds.min());
  const Eigen::Vector3i hi = voxelOf(bounds.max());
  for (int a = 0; a < 3; ++a) {
    first_block_[a] = floorDiv(lo[a], kBlockSide);
    dims_[a] = floorDiv(hi[a], kBlockSide) - first_block_[a] + 1;
  }
  for (int a = 0; a < 3; ++a) {
    page_dims_[a] = (dims_[a] + kPageSide - 1) / kPageSide;
  }
  const double blocks =
      static_cast<double>(page_dims_.x()) * page_dims_.y() * page_dims_.z() * kPageBlocks;
  if (blocks > 2.0e9) {
    throw Error("voxel map", "",
                "region too large for the voxel size (" + std::to_string(blocks) +
                    " blocks); set a smaller region");
  }
  pages_.resize(static_cast<std::size_t>(page_dims_.x()) * page_dims_.y() * page_dims_.z());
  const auto n = static_cast<std::size_t>(blocks);
  chunks_.reserve(n / kChunkBlocks + 1);
  count_chunks_.reserve(n / kChunkBlocks + 1);
  mask_chunks_.reserve(n / kChunkBlocks + 1);
}

Eigen::AlignedBox3d VoxelMap::bounds() const {
  const Eigen::Vector3d lo = first_block_.cast<double>() * blockSize();
  return {lo, lo + dims_.cast<double>() * blockSize()};
}

Eigen::Vector3i VoxelMap::pageCoords(std::size_t page) const {
  const auto nx = static_cast<std::size_t>(page_dims_.x());
  const auto ny = static_cast<std::size_t>(page_dims_.y());
  return Eigen::Vector3i(static_cast<int>(page % nx), static_cast<int>((page / nx) % ny),
                         static_cast<int>(page / (nx * ny)));
}

Eigen::Vector3i VoxelMap::blockCoords(std::size_t index) const {
  const auto in = static_cast<int>(index % kPageBlocks);
  return pageCoords(index / kPageBlocks) * kPageSide +
         Eigen::Vector3i(in % kPageSide, (in / kPageSide) % kPageSide,
                         in / (kPageSide * kPageSide));
}

std::size_t VoxelMap::blockAtRowOrder(std::size_t n) const {
  const auto nx = static_cast<std::size_t>(dims_.x());
  const auto ny = static_cast<std::size_t>(dims_.y());
  return blockIndex(Eigen::Vector3i(static_cast<int>(n % nx), static_cast<int>((n / nx) % ny),
                                    static_cast<int>(n / (nx * ny))));
}

std::size_t VoxelMap::rowOrderOf(std::size_t block) const {
  const Eigen::Vector3i rel = blockCoords(block);
  return (static_cast<std::size_t>(rel.z()) * dims_.y() + rel.y()) * dims_.x() + rel.x();
}

VoxelMap::Page& VoxelMap::heldPage(std::size_t block) {
  std::unique_ptr<Page>& page = pages_[pageOf(block)];
  if (page == nullptr) {
    page = std::make_unique<Page>();
    page->slot.fill(-1);
    ++pages_held_;
  }
  return *page;
}

void VoxelMap::holdPages(const Eigen::Vector3i& lo, const Eigen::Vector3i& hi) {
  for (int z = lo.z() >> 3; z <= hi.z() >> 3; ++z) {
    for (int y = lo.y() >> 3; y <= hi.y() >> 3; ++y) {
      for (int x = lo.x() >> 3; x <= hi.x() >> 3; ++x) {
        heldPage(pageIndex({x, y, z}) * kPageBlocks);
      }
    }
  }
}

void VoxelMap::releasePage(std::size_t page) {
  if (pages_[page] == nullptr) {
    return;
  }
  for (std::size_t b = page * kPageBlocks; b < (page + 1) * kPageBlocks; ++b) {
    releaseSlot(b);
  }
  pages_[page].reset();
  --pages_held_;
}

namespace {

// packPage's bytes: the page's states, stamps and visits, then each Mixed block's values (and
// counts) and each Partial block's mask, in block order.
template <typename T>
void appendBytes(std::vector<std::uint8_t>& out, const T* data, std::size_t count) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(data);
  out.insert(out.end(), bytes, bytes + count * sizeof(T));
}

}  // namespace

std::vector<std::uint8_t> VoxelMap::packPage(std::size_t page) const {
  std::vector<std::uint8_t> out;
  const Page* p = pages_[page].get();
  if (p == nullptr) {
    throw Error("voxel map", "page " + std::to_string(page), "expected a held page to pack");
  }
  appendBytes(out, p->state.data(), kPageBlocks);
  appendBytes(out, p->stamp.data(), kPageBlocks);
  appendBytes(out, p->visited.data(), kPageBlocks);
  for (int i = 0; i < kPageBlocks; ++i) {
    const auto in = static_cast<std::size_t>(i);
    if (p->state[in] == BlockState::Mixed) {
      appendBytes(out, slotValues(p->slot[in]), kBlockVoxels);
      if (with_counts_) {
        appendBytes(out, slotCounts(p->slot[in]), kCountBytes);
      }
    } else if (p->state[in] == BlockState::Partial) {
      appendBytes(out, slotMask(p->slot[in]), kMaskWords);
    }
  }
  return out;
}

void VoxelMap::unpackPage(std::size_t page, const std::vector<std::uint8_t>& bytes) {
  const std::string where = "page " + std::to_string(page);
  if (pages_[page] != nullptr) {
    throw Error("voxel map", where, "expected a page not held to unpack into");
  }
  std::size_t at = 0;
  const auto take = [&](auto* data, std::size_t count) {
    const std::size_t n = count * sizeof(*data);
    if (at + n > bytes.size()) {
      throw Error("voxel map", where,
                  "packed page ends early: " + std::to_string(bytes.size()) + " bytes");
    }
    std::copy_n(bytes.data() + at, n, reinterpret_cast<std::uint8_t*>(data));
    at += n;
  };
  auto held = std::make_unique<Page>();
  held->slot.fill(-1);
  take(held->state.data(), kPageBlocks);
  take(held->stamp.data(), kPageBlocks);
  take(held->visited.data(), kPageBlocks);
  pages_[page] = std::move(held);
  ++pages_held_;
  try {
    Page& p = *pages_[page];
    for (int i = 0; i < kPageBlocks; ++i) {
      const auto in = static_cast<std::size_t>(i);
      const std::size_t block = page * kPageBlocks + in;
      if (p.state[in] == BlockState::Mixed) {
        p.slot[in] = takeValueSlot(block);
        take(slotValues(p.slot[in]), kBlockVoxels);
        if (with_counts_) {
          take(slotCounts(p.slot[in]), kCountBytes);
        }
      } else if (p.state[in] == BlockState::Partial) {
        p.slot[in] = takeMaskSlot();
        take(slotMask(p.slot[in]), kMaskWords);
      } else if (p.state[in] != BlockState::Unknown && p.state[in] != BlockState::Free) {
        p.state[in] = BlockState::Unknown;
        throw Error("voxel map", where, "packed page holds an unknown block state");
      }
    }
    if (at != bytes.size()) {
      throw Error("voxel map", where,
                  "packed page has " + std::to_string(bytes.size() - at) + " bytes too many");
    }
  } catch (const Error&) {
    // Blocks not reached yet hold no slot: they go with the page, the others give theirs back.
    Page& p = *pages_[page];
    for (std::size_t in = 0; in < static_cast<std::size_t>(kPageBlocks); ++in) {
      if (p.slot[in] < 0) {
        p.state[in] = BlockState::Unknown;
      }
    }
    releasePage(page);
    throw;
  }
}

bool VoxelMap::blockSpan(const Eigen::AlignedBox3d& box, Eigen::Vector3i& lo,
                         Eigen::Vector3i& hi) const {
  const Eigen::AlignedBox3d inside = box.intersection(bounds());
  if (inside.isEmpty()) {
    return false;
  }
  const double block = blockSize();
  lo = ((inside.min() / block).array().floor().cast<int>().matrix() - first_block_)
           .cwiseMax(Eigen::Vector3i::Zero());
  hi = ((inside.max() / block).array().floor().cast<int>().matrix() - first_block_)
           .cwiseMin(dims_ - Eigen::Vector3i::Ones());
  return (lo.array() <= hi.array()).all();
}

const float* VoxelMap::values(std::size_t block) const {
  return state(block) == BlockState::Mixed ? slotValues(slotOf(block)) : nullptr;
}

float* VoxelMap::values(std::size_t block) {
  return state(block) == BlockState::Mixed ? slotValues(slotOf(block)) : nullptr;
}

void VoxelMap::copyValues(std::size_t block, float* out) const {
  switch (state(block)) {
    case BlockState::Unknown:
      std::fill_n(out, kBlockVoxels, kUnknown);
      return;
    case BlockState::Free:
      std::fill_n(out, kBlockVoxels, 0.0f);
      return;
    case BlockState::Partial: {
      // Eight voxels at a time from a table of the 256 patterns of a mask byte.
      static const auto patterns = [] {
        std::array<std::array<float, 8>, 256> table{};
        for (int byte = 0; byte < 256; ++byte) {
          for (int bit = 0; bit < 8; ++bit) {
            table[static_cast<std::size_t>(byte)][static_cast<std::size_t>(bit)] =
                (byte >> bit) & 1 ? 0.0f : kUnknown;
          }
        }
        return table;
      }();
      const auto* bytes = reinterpret_cast<const unsigned char*>(slotMask(slotOf(block)));
      for (int b = 0; b < kBlockVoxels / 8; ++b) {
        std::copy_n(patterns[bytes[b]].data(), 8, out + 8 * b);
      }
      return;
    }
    case BlockState::Mixed:
      std::copy_n(slotValues(slotOf(block)), kBlockVoxels, out);
      return;
  }
}

const std::uint8_t* VoxelMap::views(std::size_t block) const {
  return with_counts_ && state(block) == BlockState::Mixed ? slotCounts(slotOf(block)) : nullptr;
}

const std::uint8_t* VoxelMap::carveVotes(std::size_t block) const {
  const std::uint8_t* v = views(block);
  return v == nullptr ? nullptr : v + kBlockVoxels;
}

std::uint8_t* VoxelMap::counts(std::size_t block) {
  return with_counts_ && state(block) == BlockState::Mixed ? slotCounts(slotOf(block)) : nullptr;
}

Eigen::Vector3i VoxelMap::voxelOf(const Eigen::Vector3d& p_world) const {
  return (p_world / voxel_size_m_).array().floor().cast<int>();
}

bool VoxelMap::locate(const Eigen::Vector3i& voxel, std::size_t& block, int& in) const {
  Eigen::Vector3i rel;
  in = 0;
  for (int a = 2; a >= 0; --a) {
    const int b = floorDiv(voxel[a], kBlockSide);
    rel[a] = b - first_block_[a];
    in = in * kBlockSide + (voxel[a] - b * kBlockSide);
    if (rel[a] < 0 || rel[a] >= dims_[a]) {
      return false;
    }
  }
  block = blockIndex(rel);
  return true;
}

void VoxelMap::setVoxels(const std::vector<std::pair<Eigen::Vector3i, float>>& voxels) {
  std::map<std::size_t, std::vector<std::pair<int, float>>> by_block;
  for (const auto& [voxel, v] : voxels) {
    std::size_t block = 0;
    int in = 0;
    if (!locate(voxel, block, in)) {
      throw Error("voxel map", "", "a voxel to set lies outside the map's box");
    }
    by_block[block].emplace_back(in, v);
  }
  std::array<float, kBlockVoxels> values{};
  for (const auto& [block, changes] : by_block) {
    copyValues(block, values.data());
    for (const auto& [in, v] : changes) {
      values[static_cast<std::size_t>(in)] = v;
    }
    storeBlock(block, values.data(), stamp(block));
  }
}

float VoxelMap::value(const Eigen::Vector3i& voxel) const {
  std::size_t block = 0;
  int i = 0;
  if (!locate(voxel, block, i)) {
    return kUnknown;
  }
  switch (state(block)) {
    case BlockState::Unknown:
      return kUnknown;
    case BlockState::Free:
      return 0.0f;
    case BlockState::Partial:
      return (slotMask(slotOf(block))[i / 64] >> (i % 64)) & 1u ? 0.0f : kUnknown;
    case BlockState::Mixed:
      break;
  }
  return values(block)[i];
}

void VoxelMap::storeMask(std::size_t block, const std::array<std::uint64_t, kMaskWords>& mask) {
  if (state(block) != BlockState::Partial) {
    releaseSlot(block);
    slotOf(block) = takeMaskSlot();
    stateOf(block) = BlockState::Partial;
  }
  std::copy(mask.begin(), mask.end(), slotMask(slotOf(block)));
}

void VoxelMap::compactColdBlocks(std::uint32_t now, std::uint32_t cold_after) {
  if (with_counts_) {
    return;
  }
  std::array<std::uint64_t, kMaskWords> mask{};
  for (std::size_t slot = 0; slot < slot_block_.size(); ++slot) {
    const std::int32_t block = slot_block_[slot];
    if (block < 0) {
      continue;
    }
    const auto b = static_cast<std::size_t>(block);
    const std::uint16_t visited = pages_[pageOf(b)]->visited[b % kPageBlocks];
    const auto age = static_cast<std::uint16_t>(static_cast<std::uint16_t>(now) - visited);
    if (age > cold_after && carvedMask(slotValues(slotOf(b)), mask)) {
      storeMask(b, mask);
    }
  }
}

std::int32_t VoxelMap::takeValueSlot(std::size_t block) {
  const std::int32_t slot = takeSlot(free_slots_, slots_used_, kChunkBlocks, [&] {
    chunks_.push_back(std::make_unique<float[]>(kChunkBlocks * kBlockVoxels));
    if (with_counts_) {
      count_chunks_.push_back(std::make_unique<std::uint8_t[]>(kChunkBlocks * kCountBytes));
    }
  });
  if (slot_block_.size() < slots_used_) {
    slot_block_.resize(slots_used_, -1);
  }
  slot_block_[static_cast<std::size_t>(slot)] = static_cast<std::int32_t>(block);
  return slot;
}

std::int32_t VoxelMap::takeMaskSlot() {
  return takeSlot(free_mask_slots_, mask_slots_used_, kChunkBlocks, [&] {
    mask_chunks_.push_back(std::make_unique<std::uint64_t[]>(kChunkBlocks * kMaskWords));
  });
}

void VoxelMap::releaseSlot(std::size_t block) {
  if (pages_[pageOf(block)] == nullptr) {
    return;
  }
  std::int32_t& slot = slotOf(block);
  if (state(block) == BlockState::Mixed) {
    slot_block_[static_cast<std::size_t>(slot)] = -1;
    free_slots_.push_back(slot);
  } else if (state(block) == BlockState::Partial) {
    free_mask_slots_.push_back(slot);
  }
  slot = -1;
}

void VoxelMap::storeBlock(std::size_t block, const float* new_values, std::uint32_t stamp,
                          const std::uint8_t* new_counts, bool compact) {
  if (pages_[pageOf(block)] == nullptr) {
    std::lock_guard lock(storage_mutex_);
    heldPage(block);
  }
  pages_[pageOf(block)]->stamp[block % kPageBlocks] = stamp;
  // Without counts, a block of carved and unknown voxels keeps a mask of its carved ones.
  std::array<std::uint64_t, kMaskWords> mask{};
  const bool partial =
      compact && new_values != nullptr && !with_counts_ && carvedMask(new_values, mask);
  const bool all_carved =
      new_values == nullptr ||
      (partial
           ? std::all_of(mask.begin(), mask.end(), [](std::uint64_t w) { return ~w == 0; })
           : std::all_of(new_values, new_values + kBlockVoxels, [](float v) { return v == 0.0f; }));
  if (all_carved) {
    if (state(block) == BlockState::Mixed || state(block) == BlockState::Partial) {
      std::lock_guard lock(storage_mutex_);
      releaseSlot(block);
    }
    stateOf(block) = BlockState::Free;
    return;
  }
  if (partial) {
    std::lock_guard lock(storage_mutex_);
    storeMask(block, mask);
    return;
  }
  if (state(block) != BlockState::Mixed) {
    std::lock_guard lock(storage_mutex_);
    releaseSlot(block);
    slotOf(block) = takeValueSlot(block);
    stateOf(block) = BlockState::Mixed;
    if (with_counts_ && new_counts == nullptr) {
      std::fill_n(slotCounts(slotOf(block)), kCountBytes, std::uint8_t{0});
    }
  }
  float* target = slotValues(slotOf(block));
  if (target != new_values) {
    std::copy(new_values, new_values + kBlockVoxels, target);
  }
  if (!with_counts_ || new_counts == nullptr) {
    return;
  }
  std::uint8_t* target_counts = slotCounts(slotOf(block));
  if (target_counts != new_counts) {
    std::copy(new_counts, new_counts + kCountBytes, target_counts);
  }
}

void VoxelMap::forEachOccupied(const std::function<void(const Eigen::Vector3i&, float)>& f) const {
  for (std::size_t b = 0; b < blockCount(); ++b) {
    if (pages_[pageOf(b)] == nullptr) {
      b += kPageBlocks - 1;
      continue;
    }
    const float* v = values(b);
    if (v == nullptr) {
      continue;
    }
    for (int i = 0; i < kBlockVoxels; ++i) {
      if (v[i] > 0.0f && v[i] < kUnknown) {
        f(voxelIndex(b, i), v[i]);
      }
    }
  }
}

void VoxelMap::forEachOccupiedOnShell(
    const std::function<void(const Eigen::Vector3i&, float)>& f) const {
  for (std::size_t page = 0; page < pages_.size(); ++page) {
    forEachOccupiedOnShellIn(page, f);
  }
}

void VoxelMap::forEachOccupiedOnShellIn(
    std::size_t page, const std::function<void(const Eigen::Vector3i&, float)>& f) const {
  if (pages_[page] == nullptr) {
    return;
  }
  const auto occupied = [](float v) { return v > 0.0f && v < kUnknown; };
  constexpr int kS = kBlockSide;
  for (std::size_t b = page * kPageBlocks; b < (page + 1) * kPageBlocks; ++b) {
    const float* v = values(b);
    if (v == nullptr) {
      continue;
    }
    const Eigen::Vector3i base = (blockCoords(b) + first_block_) * kS;
    for (int i = 0; i < kBlockVoxels; ++i) {
      if (!occupied(v[i])) {
        continue;
      }
      const Eigen::Vector3i in(i % kS, (i / kS) % kS, i / (kS * kS));
      bool shell = false;
      for (int axis = 0; axis < 3 && !shell; ++axis) {
        for (int step : {-1, 1}) {
          Eigen::Vector3i n = in;
          n[axis] += step;
          const bool inside = n[axis] >= 0 && n[axis] < kS;
          const float neighbour = inside ? v[(n.z() * kS + n.y()) * kS + n.x()] : value(base + n);
          if (!occupied(neighbour)) {
            shell = true;
            break;
          }
        }
      }
      if (shell) {
        f(base + in, v[i]);
      }
    }
  }
}

std::size_t VoxelMap::occupiedCount() const {
  std::size_t n = 0;
  forEachOccupied([&](const Eigen::Vector3i&, float) { ++n; });
  return n;
}

std::size_t VoxelMap::blockCount(BlockState s) const {
  std::size_t n = 0;
  for (const std::unique_ptr<Page>& page : pages_) {
    if (page != nullptr) {
      n += static_cast<std::size_t>(std::count(page->state.begin(), page->state.end(), s));
    } else if (s == BlockState::Unknown) {
      n += kPageBlocks;
    }
  }
  return n;
}

std::size_t VoxelMap::memoryBytes() const {
  return pages_.capacity() * sizeof(std::unique_ptr<Page>) + pages_held_ * sizeof(Page) +
         chunks_.size() * kChunkBlocks * kBlockVoxels * sizeof(float) +
         count_chunks_.size() * kChunkBlocks * kCountBytes +
         mask_chunks_.size() * kChunkBlocks * kMaskWords * sizeof(std::uint64_t);
}

}  // namespace sonarcarve
