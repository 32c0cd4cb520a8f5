#include "sim/seabed_relief.h"

#include <cmath>
#include <numbers>
#include <random>

namespace sonarcarve {

SeabedRelief::SeabedRelief(std::uint64_t rng_seed, double amplitude_m, double min_wavelength_m,
                           double max_wavelength_m)
    : amplitude_m_(amplitude_m) {
  std::mt19937_64 rng(rng_seed);
  std::uniform_real_distribution<double> wavelength(min_wavelength_m, max_wavelength_m),
      angle(0.0, 2.0 * std::numbers::pi);
  for (std::size_t k = 0; k < 3; ++k) {
    const double heading = angle(rng);
    wave_[k] = 2.0 * std::numbers::pi / wavelength(rng) *
               Eigen::Vector2d(std::cos(heading), std::sin(heading));
    phase_[k] = angle(rng);
  }
}

double SeabedRelief::offsetDown(const Eigen::Vector2d& p) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    sum += std::sin(wave_[k].dot(p) + phase_[k]);
  }
  return amplitude_m_ * sum / 3.0;
}

Eigen::Vector2d SeabedRelief::slope(const Eigen::Vector2d& p) const {
  Eigen::Vector2d slope = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < 3; ++k) {
    slope += std::cos(wave_[k].dot(p) + phase_[k]) * wave_[k];
  }
  slope *= amplitude_m_ / 3.0;
  return slope;
}

Scene heightfieldMesh(const Eigen::Vector2d& origin, int cells, double step_m,
                      const std::function<double(const Eigen::Vector2d&)>& down,
                      const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& slope,
                      const std::function<float(const Eigen::Vector2d&)>& reflectivity) {
  Scene seabed;
  seabed.name = "seabed";
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      const Eigen::Vector2d p = origin + step_m * Eigen::Vector2d(i, j);
      // The normal of the surface down = f(north, east), pointing up (-down).
      const Eigen::Vector2d s = slope(p);
      seabed.vertices.emplace_back(p.cast<float>().x(), p.cast<float>().y(),
                                   static_cast<float>(down(p)));
      seabed.normals.push_back(
          Eigen::Vector3f(static_cast<float>(s.x()), static_cast<float>(s.y()), -1.0f)
              .normalized());
    }
  }
  const auto vertex = [&](int i, int j) { return static_cast<std::uint32_t>(i * (cells + 1) + j); };
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const float r = reflectivity(origin + step_m * Eigen::Vector2d(i + 0.5, j + 0.5));
      seabed.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      seabed.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
      seabed.reflectivity.insert(seabed.reflectivity.end(), 2, r);
    }
  }
  return seabed;
}

}  // namespace sonarcarve
