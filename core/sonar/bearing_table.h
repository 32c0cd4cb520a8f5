// BearingTable: the bearing of every beam (image column) of a sonar, in radians.
// Beams are in increasing bearing order; bearing is positive to starboard (see
// docs/conventions.md). A beam covers the bearings from the midpoint with its left neighbour
// to the midpoint with its right neighbour; the outer beams extend by half their spacing.
// Tables are uniform (field of view split into equal beams) or explicit (a real sonar's own
// non-uniform table, such as the Oculus', used as is).
#pragma once

#include <optional>
#include <vector>

namespace sonarcarve {

class BearingTable {
 public:
  /// `beams` equal beams spanning `fov_rad`, centred on the boresight.
  static BearingTable uniform(double fov_rad, int beams);
  /// Beam centres as given; they must be finite and strictly increasing (throws Error).
  static BearingTable fromCentres(std::vector<double> centres_rad);

  int count() const { return static_cast<int>(centres_.size()); }
  double centre(int beam) const { return centres_[static_cast<std::size_t>(beam)]; }
  const std::vector<double>& centres() const { return centres_; }
  bool isUniform() const { return uniform_; }

  /// Outer edges of the first and last beams.
  double leftEdge() const { return edges_.front(); }
  double rightEdge() const { return edges_.back(); }
  double fieldOfView() const { return fov_rad_; }
  /// Edges between beams: count() + 1 values, increasing.
  const std::vector<double>& edges() const { return edges_; }
  /// The median gap between neighbouring beams' centres (0 for a single beam): a uniform
  /// table's spacing, and what a non-uniform one is taken as where one spacing is needed.
  double medianSpacing() const { return median_spacing_; }

  /// The beam whose interval contains `bearing_rad`, or nothing outside the field of view.
  std::optional<int> beamOf(double bearing_rad) const;

 private:
  BearingTable(std::vector<double> centres_rad, bool uniform);
  std::vector<double> centres_;
  std::vector<double> edges_;
  bool uniform_ = false;
  double fov_rad_ = 0.0;
  double median_spacing_ = 0.0;
};

}  // namespace sonarcarve
