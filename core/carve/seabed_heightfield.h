// A seabed with relief: its depth on a grid of the world's north and east, bilinear between
// nodes (docs/reconstruction.md, "A seabed with relief"). A plane per frame cannot follow
// relief over a footprint of several metres: a wave of 15 m and 0.25 m amplitude leaves a
// plane 14 cm off at the edges of a 5 m footprint. The grid is fitted to every frame that
// images the seabed (carve/seabed_field_fit.h) and carving explains each frame's seabed with
// it where it is known, with the frame's plane elsewhere.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "carve/seabed_model.h"

namespace sonarcarve {

class SeabedHeightfield {
 public:
  /// Nodes every `cell_m` over [min, max] (north, east), none known yet.
  SeabedHeightfield(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double cell_m);

  /// A depth measured at (north, east) with a weight, shared among the 4 nodes around it
  /// bilinearly; `finish` turns the sums into depths.
  void add(double north, double east, double depth_m, double weight);
  /// Each node with weight at least `min_weight` takes the weighted mean of its measures and is
  /// known; the others stay unknown.
  void finish(double min_weight);

  /// Whether the 4 nodes around (north, east) are known.
  bool covers(double north, double east) const;
  /// The depth at (north, east), bilinear, and its gradient (d depth / d north, d depth /
  /// d east) where given. Only where `covers`.
  double depthAt(double north, double east, Eigen::Vector2d* gradient = nullptr) const;
  /// The unit normal at (north, east), pointing up into the water (its z negative).
  Eigen::Vector3d upNormal(double north, double east) const;

  /// The nodes and their bilinear weights at (north, east) (4 of each), where `covers`.
  void stencil(double north, double east, std::size_t nodes[4], double weights[4]) const;
  /// The same nodes and how the depth's gradient there moves with each node's depth:
  /// d (d depth / d north) / d node and d (d depth / d east) / d node.
  void gradientStencil(double north, double east, std::size_t nodes[4], double d_north[4],
                       double d_east[4]) const;

  double cell() const { return cell_; }
  int columns() const { return nx_; }  ///< nodes along north
  int rows() const { return ny_; }     ///< nodes along east
  std::size_t nodeCount() const { return depth_.size(); }
  std::size_t knownCount() const;
  bool known(std::size_t node) const { return known_[node] != 0; }
  /// Node depths, node (i north, j east) at j * columns() + i; the fit moves them.
  std::vector<double>& depths() { return depth_; }
  const std::vector<double>& depths() const { return depth_; }
  /// The node's position (north, east).
  Eigen::Vector2d nodePosition(std::size_t node) const;

 private:
  bool cellOf(double north, double east, int& i, int& j, double& fx, double& fy) const;
  Eigen::Vector2d origin_;
  double cell_;
  int nx_ = 0, ny_ = 0;
  std::vector<double> depth_, weight_;
  std::vector<unsigned char> known_;
};

/// The seabed as carving explains a frame with it: the frame's plane, and the heightfield
/// where it is known (none: the plane alone, as before).
struct SeabedSurface {
  SeabedPlane plane;
  const SeabedHeightfield* field = nullptr;

  /// The range along a world ray (unit `direction`) from `origin` at which it meets the
  /// seabed, +inf where it does not: the plane's, then, where the heightfield is known there,
  /// Newton's steps onto it.
  double rayRange(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const;
  /// The unit normal up into the water at a point of the seabed.
  Eigen::Vector3d upNormal(const Eigen::Vector3d& at) const;
};

}  // namespace sonarcarve
