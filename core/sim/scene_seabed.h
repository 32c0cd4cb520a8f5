// SceneSeabed: the seabed under a demo scene. Flat by default: a plane at `floor_m` under the
// site, sloping `slope_deg` down to the north, meshed as before (seabedSquare). With a relief
// (SeabedReliefSpec::relief_m > 0) it is a heightfield (sim/seabed_relief.h) meshed every
// quarter metre, levelled within `flat_radius_m` of the site (where a structure stands, a mud
// mat lies) and reaching its full relief 2 m further out; the scenes set what stands on it at
// downAt(), so the ground truth follows the relief.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "geometry/scene.h"
#include "sim/seabed_relief.h"

namespace sonarcarve {

struct SeabedReliefSpec {
  double relief_m = 0.0;      ///< amplitude of the relief; 0: the flat seabed
  double wavelength_m = 6.0;  ///< the waves' wavelengths are drawn between this and twice it
  std::uint64_t seed = 1;
};

/// Throws Error naming the setting out of range (relief 0 to 5 m, wavelength 1 to 1000 m).
void validate(const SeabedReliefSpec& spec);

class SceneSeabed {
 public:
  SceneSeabed(double floor_m, double slope_deg, const SeabedReliefSpec& relief,
              const Eigen::Vector2d& site = Eigen::Vector2d::Zero(), double flat_radius_m = 0.0);

  bool flat() const { return !relief_; }
  /// Depth of the seabed at a place.
  double downAt(double north_m, double east_m) const;
  /// The seabed over a square of side `size_m` centred on the site; a flat one in
  /// `flat_resolution` cells a side.
  Scene mesh(double size_m, int flat_resolution, float reflectivity) const;

 private:
  double relief(const Eigen::Vector2d& north_east) const;  // offset from the plane
  double floor_m_;
  double slope_deg_;
  Eigen::Vector2d site_;
  double flat_radius_m_;
  std::optional<SeabedRelief> relief_;
  double relief_at_site_ = 0.0;
};

}  // namespace sonarcarve
