#include "pipeline/sector_restore.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace sonarcarve {
namespace {

constexpr int kNormalReach = 2;              // voxels either side
constexpr std::size_t kNormalMinPoints = 6;  // a plane through fewer is a guess
constexpr int kOwnSurfaceVoxels = 3;         // a voxel's own surface around it hides nothing

struct VoxelHash {
  std::size_t operator()(const Eigen::Vector3i& v) const {
    return (static_cast<std::size_t>(static_cast<std::uint32_t>(v.x())) * 73856093u) ^
           (static_cast<std::size_t>(static_cast<std::uint32_t>(v.y())) * 19349663u) ^
           (static_cast<std::size_t>(static_cast<std::uint32_t>(v.z())) * 83492791u);
  }
};

std::vector<Eigen::Vector3i> voxelsOf(const VoxelMap& map, const SurfacePoints& surface) {
  std::vector<Eigen::Vector3i> voxels;
  voxels.reserve(surface.size());
  for (const SurfacePoint& p : surface) {
    voxels.push_back(map.voxelOf(p.position_m.cast<double>()));
  }
  return voxels;
}

}  // namespace

std::vector<Eigen::Vector3f> surfaceNormals(const std::vector<Eigen::Vector3i>& voxels) {
  const std::unordered_set<Eigen::Vector3i, VoxelHash> present(voxels.begin(), voxels.end());
  std::vector<Eigen::Vector3f> normals(voxels.size(), Eigen::Vector3f::Zero());
  for (std::size_t i = 0; i < voxels.size(); ++i) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
    std::size_t n = 0;
    for (int dz = -kNormalReach; dz <= kNormalReach; ++dz) {
      for (int dy = -kNormalReach; dy <= kNormalReach; ++dy) {
        for (int dx = -kNormalReach; dx <= kNormalReach; ++dx) {
          const Eigen::Vector3i d(dx, dy, dz);
          if (present.count(voxels[i] + d) > 0) {
            const Eigen::Vector3d p = d.cast<double>();
            sum += p;
            outer += p * p.transpose();
            ++n;
          }
        }
      }
    }
    if (n < kNormalMinPoints) {
      continue;
    }
    const Eigen::Vector3d mean = sum / static_cast<double>(n);
    const Eigen::Matrix3d covariance = outer / static_cast<double>(n) - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    normals[i] = eigen.eigenvectors().col(0).cast<float>();  // the smallest eigenvalue's
  }
  return normals;
}

namespace {

// Whether a surface voxel of any sector lies between `from` (a voxel, its own few voxels left
// out) and `to` (world): the sector looking from there may have been in its shadow.
bool hiddenFrom(const VoxelMap& grid, const Eigen::Vector3i& from, const Eigen::Vector3d& to,
                const std::unordered_set<Eigen::Vector3i, VoxelHash>& surface) {
  const Eigen::Vector3d start = grid.voxelCentre(from);
  const double length = (to - start).norm();
  const Eigen::Vector3d step = (to - start) / length * grid.voxelSize();
  const auto steps = static_cast<int>(length / grid.voxelSize());
  for (int i = kOwnSurfaceVoxels; i < steps; ++i) {
    const Eigen::Vector3i voxel = grid.voxelOf(start + step * i);
    if (surface.count(voxel) > 0) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<bool> elevationSwept(const SurfacePoints& points, const std::vector<PosedFrame>& frames,
                                 const SonarModel& sonar, double min_span_rad) {
  const double reach = sonar.mainLobeReach();
  std::vector<double> lowest(points.size(), std::numeric_limits<double>::infinity());
  std::vector<double> highest(points.size(), -std::numeric_limits<double>::infinity());
  for (const PosedFrame& frame : frames) {
    const Eigen::Isometry3d T_sonar_world = frame.T_world_sonar.inverse();
    for (std::size_t p = 0; p < points.size(); ++p) {
      const Polar polar = polarFromPoint(T_sonar_world * points[p].position_m.cast<double>());
      if (std::abs(polar.elevation_rad) <= reach && sonar.range().binOf(polar.range_m) &&
          sonar.bearings().beamOf(polar.bearing_rad)) {
        lowest[p] = std::min(lowest[p], polar.elevation_rad);
        highest[p] = std::max(highest[p], polar.elevation_rad);
      }
    }
  }
  std::vector<bool> swept(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    swept[p] = highest[p] - lowest[p] >= min_span_rad;
  }
  return swept;
}

SectorRestoreCount restoreSectorSurfaces(VoxelMap& mission_map,
                                         const std::vector<SectorCarve>& sectors,
                                         double trusted_incidence_rad) {
  SectorRestoreCount count;
  const double cos_trusted = std::cos(trusted_incidence_rad);
  std::vector<std::vector<Eigen::Vector3i>> voxels(sectors.size());
  std::unordered_set<Eigen::Vector3i, VoxelHash> every_surface;
  for (std::size_t k = 0; k < sectors.size(); ++k) {
    voxels[k] = voxelsOf(*sectors[k].map, sectors[k].surface);
    every_surface.insert(voxels[k].begin(), voxels[k].end());
  }
  std::unordered_map<Eigen::Vector3i, float, VoxelHash> kept;
  for (std::size_t k = 0; k < sectors.size(); ++k) {
    const SectorCarve& sector = sectors[k];
    const std::vector<Eigen::Vector3f> normals = surfaceNormals(voxels[k]);
    for (std::size_t i = 0; i < voxels[k].size(); ++i) {
      const Eigen::Vector3i& voxel = voxels[k][i];
      ++count.candidates;
      if (normals[i].isZero()) {
        ++count.no_normal;
        continue;
      }
      const Eigen::Vector3d normal = normals[i].cast<double>();
      const Eigen::Vector3d at = mission_map.voxelCentre(voxel);
      const bool vetoed =
          std::any_of(sectors.begin(), sectors.end(), [&](const SectorCarve& other) {
            if (&other == &sector || other.map->value(voxel) != 0.0f) {
              return false;  // only a sector that carved it
            }
            const Eigen::Vector3d towards = (other.centre - at).normalized();
            return std::abs(normal.dot(towards)) >= cos_trusted &&
                   !hiddenFrom(mission_map, voxel, other.centre, every_surface);
          });
      if (vetoed) {
        ++count.vetoed;
        continue;
      }
      const float value = sector.map->value(voxel);
      const auto [it, inserted] = kept.emplace(voxel, value);
      if (!inserted) {
        it->second = std::min(it->second, value);
      }
    }
  }
  // What the mission's map carved of the sectors' surfaces, less the vetoed voxels, set back.
  // (Carving what the mission's map keeps and no sector's surface holds was measured too, and
  // lost more than it gained: docs/design/heading-sectors.md.)
  std::vector<std::pair<Eigen::Vector3i, float>> changes;
  for (const auto& [voxel, value] : kept) {
    if (mission_map.value(voxel) == 0.0f) {
      changes.emplace_back(voxel, value);
    }
  }
  count.restored = changes.size();
  mission_map.setVoxels(changes);
  return count;
}

}  // namespace sonarcarve
