#include "carve/voxel_map.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/error.h"
#include "common/floor_div.h"

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
  const Eigen::Vector3i lo = voxelOf(bounds.min());
  const Eigen::Vector3i hi = voxelOf(bounds.max());
  for (int a = 0; a < 3; ++a) {
    first_block_[a] = floorDiv(lo[a], kBlockSide);
    dims_[a] = floorDiv(hi[a], kBlockSide) - first_block_[a] + 1;
  }
  const double blocks = static_cast<double>(dims_.x()) * dims_.y() * dims_.z();
  if (blocks > 2.0e9) {
    throw Error("voxel map", "",
                "region too large for the voxel size (" + std::to_string(blocks) +
                    " blocks); set a smaller region");
  }
  const auto n = static_cast<std::size_t>(blocks);
  state_.assign(n, BlockState::Unknown);
  slot_.assign(n, -1);
  stamp_.assign(n, 0);
  visited_.assign(n, 0);
  chunks_.reserve(n / kChunkBlocks + 1);
  count_chunks_.reserve(n / kChunkBlocks + 1);
  mask_chunks_.reserve(n / kChunkBlocks + 1);
}

Eigen::AlignedBox3d VoxelMap::bounds() const {
  const Eigen::Vector3d lo = first_block_.cast<double>() * blockSize();
  return {lo, lo + dims_.cast<double>() * blockSize()};
}

Eigen::Vector3i VoxelMap::blockCoords(std::size_t index) const {
  const auto nx = static_cast<std::size_t>(dims_.x());
  const auto ny = static_cast<std::size_t>(dims_.y());
  return Eigen::Vector3i(static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
                         static_cast<int>(index / (nx * ny)));
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
  return state_[block] == BlockState::Mixed ? slotValues(slot_[block]) : nullptr;
}

float* VoxelMap::values(std::size_t block) {
  return state_[block] == BlockState::Mixed ? slotValues(slot_[block]) : nullptr;
}

void VoxelMap::copyValues(std::size_t block, float* out) const {
  switch (state_[block]) {
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
      const auto* bytes = reinterpret_cast<const unsigned char*>(slotMask(slot_[block]));
      for (int b = 0; b < kBlockVoxels / 8; ++b) {
        std::copy_n(patterns[bytes[b]].data(), 8, out + 8 * b);
      }
      return;
    }
    case BlockState::Mixed:
      std::copy_n(slotValues(slot_[block]), kBlockVoxels, out);
      return;
  }
}

const std::uint8_t* VoxelMap::views(std::size_t block) const {
  return with_counts_ && state_[block] == BlockState::Mixed ? slotCounts(slot_[block]) : nullptr;
}

const std::uint8_t* VoxelMap::carveVotes(std::size_t block) const {
  const std::uint8_t* v = views(block);
  return v == nullptr ? nullptr : v + kBlockVoxels;
}

std::uint8_t* VoxelMap::counts(std::size_t block) {
  return with_counts_ && state_[block] == BlockState::Mixed ? slotCounts(slot_[block]) : nullptr;
}

Eigen::Vector3i VoxelMap::voxelOf(const Eigen::Vector3d& p_world) const {
  return (p_world / voxel_size_m_).array().floor().cast<int>();
}

float VoxelMap::value(const Eigen::Vector3i& voxel) const {
  Eigen::Vector3i rel;
  Eigen::Vector3i in;
  for (int a = 0; a < 3; ++a) {
    const int b = floorDiv(voxel[a], kBlockSide);
    rel[a] = b - first_block_[a];
    in[a] = voxel[a] - b * kBlockSide;
    if (rel[a] < 0 || rel[a] >= dims_[a]) {
      return kUnknown;
    }
  }
  const std::size_t block = blockIndex(rel);
  switch (state_[block]) {
    case BlockState::Unknown:
      return kUnknown;
    case BlockState::Free:
      return 0.0f;
    case BlockState::Partial: {
      const int i = (in.z() * kBlockSide + in.y()) * kBlockSide + in.x();
      return (slotMask(slot_[block])[i / 64] >> (i % 64)) & 1u ? 0.0f : kUnknown;
    }
    case BlockState::Mixed:
      break;
  }
  return values(block)[(in.z() * kBlockSide + in.y()) * kBlockSide + in.x()];
}

void VoxelMap::storeMask(std::size_t block, const std::array<std::uint64_t, kMaskWords>& mask) {
  if (state_[block] != BlockState::Partial) {
    releaseSlot(block);
    slot_[block] = takeSlot(free_mask_slots_, mask_slots_used_, kChunkBlocks, [&] {
      mask_chunks_.push_back(std::make_unique<std::uint64_t[]>(kChunkBlocks * kMaskWords));
    });
    state_[block] = BlockState::Partial;
  }
  std::copy(mask.begin(), mask.end(), slotMask(slot_[block]));
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
    const auto age = static_cast<std::uint16_t>(static_cast<std::uint16_t>(now) - visited_[b]);
    if (age > cold_after && carvedMask(slotValues(slot_[b]), mask)) {
      storeMask(b, mask);
    }
  }
}

void VoxelMap::releaseSlot(std::size_t block) {
  if (state_[block] == BlockState::Mixed) {
    slot_block_[static_cast<std::size_t>(slot_[block])] = -1;
    free_slots_.push_back(slot_[block]);
  } else if (state_[block] == BlockState::Partial) {
    free_mask_slots_.push_back(slot_[block]);
  }
  slot_[block] = -1;
}

void VoxelMap::storeBlock(std::size_t block, const float* new_values, std::uint32_t stamp,
                          const std::uint8_t* new_counts, bool compact) {
  stamp_[block] = stamp;
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
    if (state_[block] == BlockState::Mixed || state_[block] == BlockState::Partial) {
      std::lock_guard lock(storage_mutex_);
      releaseSlot(block);
    }
    state_[block] = BlockState::Free;
    return;
  }
  if (partial) {
    std::lock_guard lock(storage_mutex_);
    storeMask(block, mask);
    return;
  }
  if (state_[block] != BlockState::Mixed) {
    std::lock_guard lock(storage_mutex_);
    releaseSlot(block);
    slot_[block] = takeSlot(free_slots_, slots_used_, kChunkBlocks, [&] {
      chunks_.push_back(std::make_unique<float[]>(kChunkBlocks * kBlockVoxels));
      if (with_counts_) {
        count_chunks_.push_back(std::make_unique<std::uint8_t[]>(kChunkBlocks * kCountBytes));
      }
    });
    if (slot_block_.size() < slots_used_) {
      slot_block_.resize(slots_used_, -1);
    }
    slot_block_[static_cast<std::size_t>(slot_[block])] = static_cast<std::int32_t>(block);
    state_[block] = BlockState::Mixed;
    if (with_counts_ && new_counts == nullptr) {
      std::fill_n(slotCounts(slot_[block]), kCountBytes, std::uint8_t{0});
    }
  }
  float* target = slotValues(slot_[block]);
  if (target != new_values) {
    std::copy(new_values, new_values + kBlockVoxels, target);
  }
  if (!with_counts_ || new_counts == nullptr) {
    return;
  }
  std::uint8_t* target_counts = slotCounts(slot_[block]);
  if (target_counts != new_counts) {
    std::copy(new_counts, new_counts + kCountBytes, target_counts);
  }
}

void VoxelMap::forEachOccupied(const std::function<void(const Eigen::Vector3i&, float)>& f) const {
  for (std::size_t b = 0; b < state_.size(); ++b) {
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
  const auto occupied = [](float v) { return v > 0.0f && v < kUnknown; };
  constexpr int kS = kBlockSide;
  for (std::size_t b = 0; b < state_.size(); ++b) {
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
  return static_cast<std::size_t>(std::count(state_.begin(), state_.end(), s));
}

std::size_t VoxelMap::memoryBytes() const {
  return state_.capacity() * sizeof(BlockState) + slot_.capacity() * sizeof(std::int32_t) +
         stamp_.capacity() * sizeof(std::uint32_t) +
         chunks_.size() * kChunkBlocks * kBlockVoxels * sizeof(float) +
         count_chunks_.size() * kChunkBlocks * kCountBytes +
         mask_chunks_.size() * kChunkBlocks * kMaskWords * sizeof(std::uint64_t);
}

}  // namespace sonarcarve
