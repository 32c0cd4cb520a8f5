// SeabedRelief: a gentle seabed relief, continuous everywhere: three long sine waves of seeded
// headings, wavelengths and phases, averaged and scaled to an amplitude. The seabed field's
// relief (sim/seabed_field.h) and the one under a structure scene (sim/scene_seabed.h).
// heightfieldMesh meshes any seabed depth function over a square grid.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>

#include "geometry/scene.h"

namespace sonarcarve {

class SeabedRelief {
 public:
  /// Waves of wavelengths drawn in [min_wavelength_m, max_wavelength_m] from `rng_seed`.
  SeabedRelief(std::uint64_t rng_seed, double amplitude_m, double min_wavelength_m,
               double max_wavelength_m);

  double amplitude() const { return amplitude_m_; }
  /// The relief's depth offset at a place (positive down), within +-amplitude.
  double offsetDown(const Eigen::Vector2d& north_east) const;
  /// Its gradient d(offset) / d(north, east).
  Eigen::Vector2d slope(const Eigen::Vector2d& north_east) const;
  /// Wave vector (radians per metre) and phase of wave k (0..2).
  const Eigen::Vector2d& wave(int k) const { return wave_[static_cast<std::size_t>(k)]; }
  double phase(int k) const { return phase_[static_cast<std::size_t>(k)]; }

 private:
  double amplitude_m_;
  std::array<Eigen::Vector2d, 3> wave_;
  std::array<double, 3> phase_{};
};

/// A seabed mesh "seabed" over the square from `origin` (north, east) of `cells` x `cells`
/// cells of side `step_m`: vertices at depth `down`, normals up from the gradient `slope` of
/// the depth, each cell's two triangles of the reflectivity `reflectivity` gives its centre.
Scene heightfieldMesh(const Eigen::Vector2d& origin, int cells, double step_m,
                      const std::function<double(const Eigen::Vector2d&)>& down,
                      const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& slope,
                      const std::function<float(const Eigen::Vector2d&)>& reflectivity);

}  // namespace sonarcarve
