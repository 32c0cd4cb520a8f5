#include "model/ray_march.h"

#include <cmath>

namespace sonarcarve {

void marchRay(StencilReader& reader, double voxel_size, const Eigen::Vector3d& origin,
              const Eigen::Vector3d& direction, const Eigen::Vector3d& direction_sonar,
              const MarchLimits& limits, std::vector<RaySample>& samples) {
  samples.clear();
  const RangeBins& bins = limits.bins;
  const double ds = bins.resolution_m / limits.samples_per_bin;
  const int last = bins.count * limits.samples_per_bin;
  // Samples before the window (i < 0) still occlude.
  int i = -static_cast<int>(std::floor(bins.min_m / ds));
  double transmittance = 1.0;
  RaySample sample;
  while (i < last && transmittance >= limits.min_transmittance) {
    const double range = bins.min_m + (i + 0.5) * ds;
    const Eigen::Vector3d p = origin + range * direction;
    double exit_m = 0.0;
    if (!reader.inPresentBlock(p, direction, exit_m)) {
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
