#include "model/ray_march.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace sonarcarve {
namespace {

// The distances along the ray between which it is inside `box` (slab test).
bool rayThroughBox(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& origin,
                   const Eigen::Vector3d& direction, double& enter_m, double& leave_m) {
  if (box.isEmpty()) {
    return false;
  }
  enter_m = 0.0;
  leave_m = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double d = direction[axis];
    if (std::abs(d) < 1e-15) {
      if (origin[axis] < box.min()[axis] || origin[axis] > box.max()[axis]) {
        return false;
      }
      continue;
    }
    double t0 = (box.min()[axis] - origin[axis]) / d;
    double t1 = (box.max()[axis] - origin[axis]) / d;
    if (t0 > t1) {
      std::swap(t0, t1);
    }
    enter_m = std::max(enter_m, t0);
    leave_m = std::min(leave_m, t1);
  }
  return enter_m <= leave_m;
}

}  // namespace

void marchRay(StencilReader& reader, double voxel_size, const Eigen::Vector3d& origin,
              const Eigen::Vector3d& direction, const Eigen::Vector3d& direction_sonar,
              const MarchLimits& limits, std::vector<RaySample>& samples) {
  samples.clear();
  const RangeBins& bins = limits.bins;
  const double ds = bins.resolution_m / limits.samples_per_bin;
  int last = bins.count * limits.samples_per_bin;
  // Samples before the window (i < 0) still occlude; none outside the grid's box matter.
  int i = -static_cast<int>(std::floor(bins.min_m / ds));
  double enter_m = 0.0;
  double leave_m = 0.0;
  if (!rayThroughBox(reader.bounds(), origin, direction, enter_m, leave_m)) {
    return;
  }
  i = std::max(i, static_cast<int>(std::floor((enter_m - bins.min_m) / ds - 0.5)));
  last = std::min(last, static_cast<int>(std::ceil((leave_m - bins.min_m) / ds - 0.5)) + 1);
  double transmittance = 1.0;
  RaySample sample;
  while (i < last && transmittance >= limits.min_transmittance) {
    const double range = bins.min_m + (i + 0.5) * ds;
    const Eigen::Vector3d p = origin + range * direction;
    double exit_m = 0.0;
    if (!reader.inSampledCell(p, direction, exit_m)) {
      const double next = std::ceil((range + exit_m - bins.min_m) / ds - 0.5);
      i = std::max(i + 1, static_cast<int>(std::min(next, double(last))));
      continue;
    }
    ++i;
    reader.readCorners(p, sample.stencil);
    const double alpha = sigmoid(sample.stencil.logitAt());
    if (alpha < limits.min_alpha) {
      continue;
    }
    reader.readPatch(sample.stencil);
    sample.range_m = range;
    sample.p_sonar = range * direction_sonar;
    sample.alpha = alpha;
    sample.transmittance = transmittance;
    sample.reflectance = sample.stencil.reflectanceAt();
    sample.gradient = sample.stencil.gradientAt(voxel_size);
    const double norm = sample.gradient.norm();
    sample.cos_incidence =
        norm > 1e-12 ? std::max(0.0, direction.dot(sample.gradient) / norm) : 0.0;
    samples.push_back(sample);
    transmittance *= 1.0 - alpha;
  }
}

}  // namespace sonarcarve
