#include "support/model_scenes.h"

#include <algorithm>
#include <cmath>

namespace sonarcarve::test {

void voxelise(BlockGrid& grid, const SignedDistance& sd, const Eigen::AlignedBox3d& box,
              double band, double slope, float reflectance) {
  const double size = grid.voxelSize();
  Eigen::Vector3i lo;
  Eigen::Vector3i hi;
  if (!grid.voxelOf(box.min(), lo) || !grid.voxelOf(box.max(), hi)) {
    return;
  }
  for (int z = lo.z(); z <= hi.z(); ++z) {
    for (int y = lo.y(); y <= hi.y(); ++y) {
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Eigen::Vector3i voxel(x, y, z);
        const double distance = sd(grid.voxelCentre(voxel)) / size;
        if (std::abs(distance) > band) {
          continue;
        }
        const bool fresh = grid.voxelIndex(voxel) < 0;
        const auto index = static_cast<std::size_t>(grid.addVoxel(voxel));
        const auto logit = static_cast<float>(
            std::clamp(-distance * slope, static_cast<double>(grid.emptyLogit()), 6.0));
        if (fresh || logit > grid.logits()[index]) {
          grid.logits()[index] = logit;
          grid.reflectance()[index] = reflectance;
        }
      }
    }
  }
}

SignedDistance slab(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                    double thickness) {
  const Eigen::Vector3d n = normal.normalized();
  return [=](const Eigen::Vector3d& p) {
    const double out = n.dot(p - centre);
    return std::max(out, -out - thickness);
  };
}

SignedDistance cylinder(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double radius) {
  const Eigen::Vector3d a = axis.normalized();
  return [=](const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - point;
    return (d - a.dot(d) * a).norm() - radius;
  };
}

}  // namespace sonarcarve::test
