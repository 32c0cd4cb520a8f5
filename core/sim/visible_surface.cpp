#include "sim/visible_surface.h"

#include <cmath>

namespace sonarcarve {

void VisibleSurface::add(const Eigen::Vector3f& p_world) {
  // 21 bits per axis: +-10 km at 1 cm.
  const auto key_of = [&](float v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / cell_m_)) +
                                      (1 << 20)) &
           0x1FFFFF;
  };
  const std::uint64_t key =
      (key_of(p_world.x()) << 42) | (key_of(p_world.y()) << 21) | key_of(p_world.z());
  if (cells_.emplace(key, static_cast<std::uint32_t>(points_.size())).second) {
    points_.push_back(p_world);
  }
}

}  // namespace sonarcarve
