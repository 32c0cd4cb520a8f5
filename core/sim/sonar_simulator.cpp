#include "sim/sonar_simulator.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "model/elevation_fan.h"
#include "model/range_deposit.h"
#include "model/reflectance.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

// One elevation sample of one ray fan: where it hit and what it returns.
struct Sample {
  bool hit = false;
  float range = 0.0f;
  float energy = 0.0f;
  Eigen::Vector3f point;
};

// Left edge and width of traced beam `j`, which may lie beyond the fan (j < 0 or j >= count):
// those continue the outer beams' spacing.
std::pair<double, double> tracedBeam(const BearingTable& table, int j) {
  const auto& edges = table.edges();
  const int n = table.count();
  if (j < 0) {
    const double width = edges[1] - edges[0];
    return {edges[0] + j * width, width};
  }
  if (j >= n) {
    const double width =
        edges[static_cast<std::size_t>(n)] - edges[static_cast<std::size_t>(n) - 1];
    return {edges[static_cast<std::size_t>(n)] + (j - n) * width, width};
  }
  const auto u = static_cast<std::size_t>(j);
  return {edges[u], edges[u + 1] - edges[u]};
}

// Bearing of every traced ray, beam by beam from `pad` beams left of the fan to `pad` beams
// right of it, `rays` per beam.
std::vector<double> rayBearings(const BearingTable& table, int pad, int rays) {
  std::vector<double> bearings;
  for (int j = -pad; j < table.count() + pad; ++j) {
    const auto [left, width] = tracedBeam(table, j);
    for (int s = 0; s < rays; ++s) {
      bearings.push_back(left + (s + 0.5) * width / rays);
    }
  }
  return bearings;
}

}  // namespace

std::string beamName(SimulatedBeam beam) {
  return beam == SimulatedBeam::Realistic ? "realistic" : "clipped";
}

SimulatedBeam beamFromName(const std::string& name) {
  if (name == "realistic") {
    return SimulatedBeam::Realistic;
  }
  if (name == "clipped") {
    return SimulatedBeam::Clipped;
  }
  throw Error("simulator", "beam", "expected 'realistic' or 'clipped', not '" + name + "'");
}

SonarSimulator::SonarSimulator(const RayCaster& caster, const SonarModel& sonar,
                               ImagingSettings settings, ThreadPool& pool)
    : caster_(caster), sonar_(sonar), settings_(settings), pool_(pool) {
  if (!(settings_.elevation_step_rad > 0.0) || settings_.rays_per_beam < 1) {
    throw Error("simulator", "settings", "expected a positive elevation step and >= 1 ray/beam");
  }
  if (settings_.side_lobes < 0 || !(settings_.horizontal_beam_width_rad >= 0.0) ||
      !std::isfinite(settings_.horizontal_beam_width_rad) ||
      !(settings_.visible_beam_level_db < 0.0)) {
    throw Error("simulator", "settings",
                "expected side lobes >= 0, a horizontal beam width >= 0 and a visible beam "
                "level below 0 dB");
  }
  const double aperture = sonar.verticalAperture();
  const bool realistic = settings_.beam == SimulatedBeam::Realistic;
  if (!realistic && settings_.elevation_beam.family != ElevationFamily::Sinc2) {
    throw Error("simulator", "settings",
                "expected the realistic beam for an elevation beam other than sinc2");
  }
  const ElevationPattern elevation_beam(settings_.elevation_beam, aperture, settings_.side_lobes);
  traced_elevation_rad_ = realistic ? elevation_beam.tracedHalfAngle() : 0.5 * aperture;
  fan_ = elevationFan(traced_elevation_rad_, settings_.elevation_step_rad);
  elevations_ = fan_.count;
  const int rays = settings_.rays_per_beam;
  // Each sample stands for dtheta / A of the aperture; sub-rays share the beam.
  sample_scale_ =
      realistic
          ? static_cast<float>(elevationSampleScale(settings_.gain, fan_.step_rad, aperture, rays))
          : static_cast<float>(settings_.gain) / static_cast<float>(elevations_ * rays);
  // Seen: within the pattern's level (the clipped beam's sinc2: as the realistic's default).
  const auto visible = elevation_beam.interval(settings_.visible_beam_level_db);
  for (int k = 0; k < elevations_; ++k) {
    const double theta = fan_.angle(k);
    // Realistic: a ray stands for a cell of solid angle cos(theta) dtheta dphi, so that a
    // small target returns p(theta) at any elevation (rays crowd in bearing as |theta| grows).
    beam_weight_.push_back(
        static_cast<float>(realistic ? solidAngleWeight(elevation_beam.power(theta), theta)
                                     : sonar.beamPattern().weight(theta)));
    visible_elevation_.push_back(
        static_cast<char>(theta >= visible.first && theta <= visible.second));
  }
  if (realistic) {
    addBearingLeakage(sonar);
  }
  traceBearings(sonar);
}

void SonarSimulator::traceBearings(const SonarModel& sonar) {
  const std::vector<double> bearings =
      rayBearings(sonar.bearings(), pad_beams_, settings_.rays_per_beam);
  directions_.reserve(bearings.size() * static_cast<std::size_t>(elevations_));
  for (const double bearing : bearings) {
    for (int k = 0; k < elevations_; ++k) {
      directions_.push_back(rayDirection(bearing, fan_.angle(k)).cast<float>());
    }
  }
}

void SonarSimulator::addBearingLeakage(const SonarModel& sonar) {
  const BearingTable& table = sonar.bearings();
  const int rays = settings_.rays_per_beam;
  const auto widthOf = [&](int j) {
    return settings_.horizontal_beam_width_rad > 0.0 ? settings_.horizontal_beam_width_rad
                                                     : tracedBeam(table, j).second;
  };
  // Enough beams beyond each edge for the outer beams' traced extent.
  for (int j : {0, table.count() - 1}) {
    const double extent = SincSquaredBeam(widthOf(j)).null(settings_.side_lobes + 1);
    pad_beams_ =
        std::max(pad_beams_, static_cast<int>(std::ceil(extent / tracedBeam(table, j).second)));
  }
  const std::vector<double> ray_bearing = rayBearings(table, pad_beams_, rays);
  // Beam j takes every sub-ray within its traced extent, weighted by its power pattern; the
  // weights sum to rays_per_beam, so that a target wider than the beam gives the clipped
  // beam's counts.
  tap_offset_.push_back(0);
  for (int j = 0; j < table.count(); ++j) {
    const SincSquaredBeam beam(widthOf(j));
    const double centre = table.centre(j);
    const double extent = beam.null(settings_.side_lobes + 1);
    const auto first = std::upper_bound(ray_bearing.begin(), ray_bearing.end(), centre - extent);
    const auto last = std::lower_bound(ray_bearing.begin(), ray_bearing.end(), centre + extent);
    tap_first_.push_back(static_cast<int>(first - ray_bearing.begin()));
    double total = 0.0;
    for (auto it = first; it != last; ++it) {
      total += beam.power(*it - centre);
    }
    for (auto it = first; it != last; ++it) {
      tap_weight_.push_back(static_cast<float>(rays * beam.power(*it - centre) / total));
    }
    tap_offset_.push_back(static_cast<int>(tap_weight_.size()));
  }
}

cv::Mat SonarSimulator::leak(const cv::Mat& ray_columns) const {
  // Beam by beam, its taps' columns weighted and summed in tap order, range bins side by side.
  cv::Mat beam_columns(sonar_.cols(), sonar_.rows(), CV_32F, cv::Scalar(0.0f));
  const int bins = beam_columns.cols;
  pool_.parallelFor(static_cast<std::size_t>(beam_columns.rows), 16,
                    [&](std::size_t begin, std::size_t end) {
                      for (std::size_t j = begin; j < end; ++j) {
                        float* out = beam_columns.ptr<float>(static_cast<int>(j));
                        int column = tap_first_[j];
                        for (int t = tap_offset_[j]; t < tap_offset_[j + 1]; ++t, ++column) {
                          const float weight = tap_weight_[static_cast<std::size_t>(t)];
                          const float* in = ray_columns.ptr<float>(column);
                          for (int b = 0; b < bins; ++b) {
                            out[b] += weight * in[b];
                          }
                        }
                      }
                    });
  return beam_columns;
}

cv::Mat SonarSimulator::render(const Eigen::Isometry3d& T_world_sonar, const HitSink& hits) const {
  const int cols = sonar_.cols();
  const bool realistic = settings_.beam == SimulatedBeam::Realistic;
  const int rays = settings_.rays_per_beam;
  const int traced_beams = cols + 2 * pad_beams_;
  // The image held transposed, a row per column, so that a fan adds into contiguous range bins.
  // Clipped: every ray adds into its own beam's column. Realistic: into its own sub-ray
  // column, which leak() then shares among the beams.
  cv::Mat columns(realistic ? traced_beams * rays : cols, sonar_.rows(), CV_32F, cv::Scalar(0.0f));
  const Eigen::Matrix3f R = T_world_sonar.linear().cast<float>();
  const Eigen::Vector3f origin = T_world_sonar.translation().cast<float>();
  const float max_range = static_cast<float>(sonar_.range().maxRange());
  const int K = elevations_;

  pool_.parallelFor(
      static_cast<std::size_t>(traced_beams), 8, [&](std::size_t begin, std::size_t end) {
        std::vector<Sample> fan(static_cast<std::size_t>(K));
        std::vector<Eigen::Vector3f> fan_directions(static_cast<std::size_t>(K));
        std::vector<RayHit> fan_hits(static_cast<std::size_t>(K));
        std::vector<Eigen::Vector3f> seen;
        for (std::size_t j = begin; j < end; ++j) {
          const auto beam = static_cast<int>(j) - pad_beams_;
          const bool in_fan = beam >= 0 && beam < cols;
          for (int s = 0; s < rays; ++s) {
            float* column = columns.ptr<float>(realistic ? static_cast<int>(j) * rays + s : beam);
            const Eigen::Vector3f* dirs =
                &directions_[(j * static_cast<std::size_t>(rays) + static_cast<std::size_t>(s)) *
                             static_cast<std::size_t>(K)];
            // One sub-ray's elevations, neighbours in direction: traced as packets.
            for (int k = 0; k < K; ++k) {
              fan_directions[static_cast<std::size_t>(k)] = R * dirs[k];
            }
            caster_.intersectFan(origin, fan_directions, max_range, fan_hits);
            for (int k = 0; k < K; ++k) {
              Sample& sample = fan[static_cast<std::size_t>(k)];
              const Eigen::Vector3f& dir = fan_directions[static_cast<std::size_t>(k)];
              const RayHit& hit = fan_hits[static_cast<std::size_t>(k)];
              sample.hit = hit.found;
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
              sample.energy =
                  lambertianReturn(sample_scale_, caster_.scene().reflectivity[hit.triangle],
                                   cos_incidence, beam_weight_[static_cast<std::size_t>(k)]) *
                  static_cast<float>(range_factor);
              if (hits && in_fan && visible_elevation_[static_cast<std::size_t>(k)] != 0 &&
                  cos_incidence >= settings_.visible_min_cos_incidence &&
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
                depositAtRange(a.range, 0.5f * a.energy, sonar_.range(), column);
              }
              if (linked_above) {
                const Sample& b = fan[static_cast<std::size_t>(k) + 1];
                spreadOverRange(a.range, b.range, 0.5f * (a.energy + b.energy), sonar_.range(),
                                column);
              } else if (a.hit) {
                depositAtRange(a.range, 0.5f * a.energy, sonar_.range(), column);
              }
              linked_below = linked_above;
            }
          }
        }
        if (hits && !seen.empty()) {
          hits(seen);
        }
      });
  cv::Mat image;
  cv::transpose(realistic ? leak(columns) : columns, image);
  return image;
}

}  // namespace sonarcarve
