// SeabedField: a seabed of unbounded extent with objects on it, generated procedurally from a
// seed, for long survey missions (docs/simulator.md, "The seabed field"). The world is cut into
// square tiles; a tile's seabed and objects are a function of the seed and the tile's place
// only, so any part of the field is built on demand, the same every time, and a mission of an
// hour meets new seabed and new objects all along without holding the whole field.
//   seabed   a height field `depth_m` deep with a gentle relief (a few long waves, continuous
//            across tiles) and patches of reflectivity, meshed every `grid_m`
//   objects  0 to `max_objects_per_tile` per tile, away from its borders, each resting on the
//            seabed: boxes, lying pipes, spheres and upright posts of seeded sizes and headings
#pragma once

#include <Eigen/Geometry>
#include <cstdint>

#include "geometry/scene.h"
#include "sim/seabed_relief.h"

namespace sonarcarve {

struct SeabedFieldSpec {
  std::uint64_t seed = 1;
  double depth_m = 20.0;   ///< mean depth of the seabed
  double relief_m = 0.25;  ///< amplitude of the seabed's relief around the mean depth
  double tile_m = 10.0;    ///< side of a tile, the unit the field is built in
  double grid_m = 0.5;     ///< spacing of the seabed mesh
  int max_objects_per_tile = 2;
};

/// Throws Error naming the setting that is out of range.
void validate(const SeabedFieldSpec& spec);

class SeabedField {
 public:
  explicit SeabedField(SeabedFieldSpec spec);
  const SeabedFieldSpec& spec() const { return spec_; }

  /// Depth of the seabed (without objects) under a place, metres.
  double seabedDown(double north_m, double east_m) const;
  /// The tile holding a place: (floor(north / tile), floor(east / tile)).
  Eigen::Vector2i tileOf(double north_m, double east_m) const;
  /// One tile's seabed and objects.
  Scene tile(const Eigen::Vector2i& tile) const;
  /// The tiles that a north-east box (metres) touches, as one scene.
  Scene area(const Eigen::AlignedBox2d& north_east) const;
  /// What a survey of the field looks at: the seabed under the origin.
  InspectionTarget target() const;

 private:
  void addSeabed(const Eigen::Vector2i& tile, Scene& scene) const;
  void addObjects(const Eigen::Vector2i& tile, Scene& scene) const;
  SeabedFieldSpec spec_;
  SeabedRelief relief_;  // three long waves, 15 to 40 m
};

}  // namespace sonarcarve
