#include "sim/visible_surface.h"

#include <array>
#include <cmath>

namespace sonarcarve {

std::uint64_t VisibleSurface::cellOf(const Eigen::Vector3f& p_world) const {
  // 21 bits per axis: +-10 km at 1 cm.
  const auto key_of = [&](float v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / cell_m_)) +
                                      (1 << 20)) &
           0x1FFFFF;
  };
  return (key_of(p_world.x()) << 42) | (key_of(p_world.y()) << 21) | key_of(p_world.z());
}

void VisibleSurface::add(std::span<const Eigen::Vector3f> p_world) {
  // The points of one batch (neighbouring rays) crowd into few cells: a small table of the
  // cells met last drops most repeats before the shared set is locked. Cells use 63 bits, so
  // all ones marks an empty slot.
  constexpr std::size_t kRecentBits = 10;
  constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::array<std::uint64_t, std::size_t{1} << kRecentBits> recent;
  recent.fill(kEmpty);
  std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> fresh;
  for (const Eigen::Vector3f& p : p_world) {
    const std::uint64_t cell = cellOf(p);
    std::uint64_t& slot = recent[(cell * 0x9E3779B97F4A7C15ULL) >> (64 - kRecentBits)];
    if (slot != cell) {
      slot = cell;
      fresh.emplace_back(cell, p);
    }
  }
  std::lock_guard lock(mutex_);
  for (const auto& [cell, p] : fresh) {
    if (cells_.try_emplace(cell, static_cast<std::uint32_t>(points_.size())).second) {
      points_.push_back(p);
    }
  }
}

}  // namespace sonarcarve
