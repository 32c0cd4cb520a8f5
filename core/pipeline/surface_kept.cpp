#include "pipeline/surface_kept.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_set>

namespace sonarcarve {
namespace {

// A cell of the hash grid, packed: 21 bits an axis (cells of 2 voxels: +-42 km at 2 cm, far
// beyond a first surface's few metres around the mission origin).
std::uint64_t cellKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::int64_t kMask = (std::int64_t{1} << 21) - 1;
  return (static_cast<std::uint64_t>(x & kMask) << 42) |
         (static_cast<std::uint64_t>(y & kMask) << 21) | static_cast<std::uint64_t>(z & kMask);
}

}  // namespace

FirstSurfaceKept firstSurfaceKept(const std::vector<Eigen::Vector3f>& first,
                                  const std::vector<Eigen::Vector3f>& surface, double voxel_m) {
  const double cell = 2.0 * voxel_m;
  const auto index = [&](float v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
  std::unordered_set<std::uint64_t> cells;
  cells.reserve(surface.size());
  for (const Eigen::Vector3f& p : surface) {
    cells.insert(cellKey(index(p.x()), index(p.y()), index(p.z())));
  }
  FirstSurfaceKept kept;
  kept.first_points = first.size();
  for (const Eigen::Vector3f& p : first) {
    const std::int64_t x = index(p.x());
    const std::int64_t y = index(p.y());
    const std::int64_t z = index(p.z());
    bool near = false;  // a surface point in this cell or a neighbour: within 2 to 4 voxels
    for (std::int64_t dx = -1; dx <= 1 && !near; ++dx) {
      for (std::int64_t dy = -1; dy <= 1 && !near; ++dy) {
        for (std::int64_t dz = -1; dz <= 1 && !near; ++dz) {
          near = cells.count(cellKey(x + dx, y + dy, z + dz)) > 0;
        }
      }
    }
    kept.kept += near ? 1 : 0;
  }
  return kept;
}

RunChoice firstSurfaceKeptChoice(const FirstSurfaceKept& kept) {
  RunChoice choice;
  choice.name = "first surface kept";
  char value[32];
  std::snprintf(value, sizeof value, "%.0f %%", 100.0 * kept.share());
  choice.value = value;
  choice.detail = std::to_string(kept.kept) + " of " + std::to_string(kept.first_points) +
                  " points of the beam check's first surface (carved inside the aperture from "
                  "the middle of the mission) have a surface point of the run near them";
  if (kept.share() < kKeptFirstSurfaceShare) {
    choice.reason =
        "the run carved away most of the surface a first carve inside the aperture "
        "kept: the frames show structure the map has lost";
    choice.action =
        "check the sonar's declared elevation beam (beam_pattern), the navigation "
        "and the keep level (dynamic_range_db); beam_aware_carving: false carves by "
        "the paper's rule";
    choice.warning = true;
  } else {
    choice.reason =
        "the run kept the surface a first carve inside the aperture kept, less its "
        "ghosts";
  }
  return choice;
}

}  // namespace sonarcarve
