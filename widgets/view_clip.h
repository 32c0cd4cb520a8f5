// ViewClip: what part of the world the 3D view draws: a box (north, east, down limits in
// metres) and an axis-aligned cross-section (a slab across north, east or down at a position,
// of a thickness). Both together draw what lies in both. Plain data, no Qt.
#pragma once

#include <Eigen/Geometry>
#include <optional>

namespace sonarcarve::widgets {

struct ViewClip {
  enum class Axis { North = 0, East = 1, Down = 2 };
  struct Section {
    Axis axis = Axis::North;
    double position_m = 0.0;   ///< the slab's centre along its axis
    double thickness_m = 0.1;  ///< its thickness
  };
  std::optional<Eigen::AlignedBox3d> box;
  std::optional<Section> section;

  bool active() const { return box.has_value() || section.has_value(); }
  /// The region drawn: the box and the slab intersected (infinite where neither limits it).
  Eigen::AlignedBox3d region() const;
  bool contains(const Eigen::Vector3f& p) const;
};

}  // namespace sonarcarve::widgets
