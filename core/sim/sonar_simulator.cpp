#include "sim/sonar_simulator.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "common/error.h"

namespace sonarcarve {
namespace {

// One elevation sample of one ray fan: where it hit and what it returns.
struct Sample {
  bool hit = false;
  float range = 0.0f;
  float energy = 0.0f;
  Eigen::Vector3f point;
};

// Adds `energy` spread uniformly over the ranges [r0, r1] into the column's range bins.
void spreadOverRange(float r0, float r1, float energy, const RangeBins& bins, float* column,
                     int stride) {
  if (r1 < r0) {
    std::swap(r0, r1);
  }
  const auto first = static_cast<double>(r0);
  const auto last = static_cast<double>(r1);
  const double span = last - first;
  const double res = bins.resolution_m;
  if (span < 1e-6 * res) {
    if (const auto bin = bins.binOf(0.5 * (first + last))) {
      column[*bin * stride] += energy;
    }
    return;
  }
  const int b0 = std::max(0, static_cast<int>(std::floor((first - bins.min_m) / res)));
  const int b1 = std::min(bins.count - 1, static_cast<int>(std::floor((last - bins.min_m) / res)));
  for (int b = b0; b <= b1; ++b) {
    const double lo = std::max(first, bins.min_m + b * res);
    const double hi = std::min(last, bins.min_m + (b + 1) * res);
    if (hi > lo) {
      column[b * stride] += static_cast<float>(energy * (hi - lo) / span);
    }
  }
}

}  // namespace

SonarSimulator::SonarSimulator(const RayCaster& caster, const SonarModel& sonar,
                               ImagingSettings settings, ThreadPool& pool)
    : caster_(caster), sonar_(sonar), settings_(settings), pool_(pool) {
  if (!(settings_.elevation_step_rad > 0.0) || settings_.rays_per_beam < 1) {
    throw Error("simulator", "settings", "expected a positive elevation step and >= 1 ray/beam");
  }
  const double aperture = sonar.verticalAperture();
  elevations_ = std::max(2, static_cast<int>(std::ceil(aperture / settings_.elevation_step_rad)));
  const double step = aperture / elevations_;
  for (int k = 0; k < elevations_; ++k) {
    beam_weight_.push_back(
        static_cast<float>(sonar.beamPattern().weight(-0.5 * aperture + (k + 0.5) * step)));
  }
  const auto& edges = sonar.bearings().edges();
  const int rays = settings_.rays_per_beam;
  directions_.reserve(static_cast<std::size_t>(sonar.cols() * rays * elevations_));
  for (int j = 0; j < sonar.cols(); ++j) {
    const double left = edges[static_cast<std::size_t>(j)];
    const double width = edges[static_cast<std::size_t>(j) + 1] - left;
    for (int s = 0; s < rays; ++s) {
      const double bearing = left + (s + 0.5) * width / rays;
      for (int k = 0; k < elevations_; ++k) {
        const double elevation = -0.5 * aperture + (k + 0.5) * step;
        directions_.push_back(pointFromPolar({1.0, bearing, elevation}).cast<float>());
      }
    }
  }
}

cv::Mat SonarSimulator::render(const Eigen::Isometry3d& T_world_sonar, const HitSink& hits) const {
  const int rows = sonar_.rows();
  const int cols = sonar_.cols();
  cv::Mat image(rows, cols, CV_32F, cv::Scalar(0.0f));
  const Eigen::Matrix3f R = T_world_sonar.linear().cast<float>();
  const Eigen::Vector3f origin = T_world_sonar.translation().cast<float>();
  const float max_range = static_cast<float>(sonar_.range().maxRange());
  const int rays = settings_.rays_per_beam;
  const int K = elevations_;
  // Each sample stands for dtheta / A of the aperture; sub-rays share the beam.
  const float per_sample = static_cast<float>(settings_.gain) / static_cast<float>(K * rays);
  std::mutex hits_mutex;

  pool_.parallelFor(static_cast<std::size_t>(cols), 8, [&](std::size_t begin, std::size_t end) {
    std::vector<Sample> fan(static_cast<std::size_t>(K));
    std::vector<Eigen::Vector3f> seen;
    for (std::size_t j = begin; j < end; ++j) {
      float* column = image.ptr<float>(0) + j;
      for (int s = 0; s < rays; ++s) {
        const Eigen::Vector3f* dirs =
            &directions_[(j * static_cast<std::size_t>(rays) + static_cast<std::size_t>(s)) *
                         static_cast<std::size_t>(K)];
        for (int k = 0; k < K; ++k) {
          Sample& sample = fan[static_cast<std::size_t>(k)];
          const Eigen::Vector3f dir = R * dirs[k];
          RayHit hit;
          sample.hit = caster_.intersect(origin, dir, max_range, hit);
          if (!sample.hit) {
            continue;
          }
          sample.range = hit.distance;
          sample.point = origin + hit.distance * dir;
          const float cos_incidence = std::abs(hit.normal.dot(dir));
          double range_factor = 1.0;
          if (settings_.spreading_exponent != 0.0 || settings_.tvg_exponent != 0.0) {
            range_factor = std::pow(static_cast<double>(hit.distance),
                                    settings_.tvg_exponent - settings_.spreading_exponent);
          }
          sample.energy = per_sample * caster_.scene().reflectivity[hit.triangle] * cos_incidence *
                          beam_weight_[static_cast<std::size_t>(k)] *
                          static_cast<float>(range_factor);
          if (hits && cos_incidence >= settings_.visible_min_cos_incidence &&
              sonar_.range().binOf(hit.distance)) {
            seen.push_back(sample.point);
          }
        }
        // Half of each sample's elevation interval lies towards each neighbour. Where two
        // neighbours hit one continuous surface (hit points no farther apart than a surface at
        // 83 degrees of incidence puts them), their facing halves are spread over the ranges
        // between the hits; every other half stays at its own sample's range.
        const float step = static_cast<float>(settings_.elevation_step_rad);
        const auto linked = [&](int k) {
          const Sample& a = fan[static_cast<std::size_t>(k)];
          const Sample& b = fan[static_cast<std::size_t>(k) + 1];
          return a.hit && b.hit && (a.point - b.point).norm() < 8.0f * a.range * step + 0.01f;
        };
        bool linked_below = false;
        for (int k = 0; k < K; ++k) {
          const Sample& a = fan[static_cast<std::size_t>(k)];
          const bool linked_above = k + 1 < K && linked(k);
          if (a.hit && !linked_below) {
            spreadOverRange(a.range, a.range, 0.5f * a.energy, sonar_.range(), column, cols);
          }
          if (linked_above) {
            const Sample& b = fan[static_cast<std::size_t>(k) + 1];
            spreadOverRange(a.range, b.range, 0.5f * (a.energy + b.energy), sonar_.range(), column,
                            cols);
          } else if (a.hit) {
            spreadOverRange(a.range, a.range, 0.5f * a.energy, sonar_.range(), column, cols);
          }
          linked_below = linked_above;
        }
      }
    }
    if (hits && !seen.empty()) {
      std::lock_guard lock(hits_mutex);
      for (const auto& p : seen) {
        hits(p);
      }
    }
  });
  return image;
}

}  // namespace sonarcarve
