#include "carve/seabed_heightfield.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"

namespace sonarcarve {
namespace {

// Nodes a heightfield may hold: 4e7 (a 1.3 x 1.3 km survey at 0.2 m), 640 MB of doubles.
constexpr double kMaxNodes = 4e7;

}  // namespace

SeabedHeightfield::SeabedHeightfield(const Eigen::Vector2d& min, const Eigen::Vector2d& max,
                                     double cell_m)
    : origin_(min), cell_(cell_m) {
  const Eigen::Vector2d span = (max - min) / cell_m;
  if (!(cell_m > 0.0) || !span.allFinite() || span.minCoeff() < 0.0 ||
      (span.x() + 2.0) * (span.y() + 2.0) > kMaxNodes) {
    throw Error("seabed relief", "heightfield",
                "a grid of " + std::to_string(cell_m) +
                    " m cells over the seabed seen: expected at most 4e7 nodes");
  }
  nx_ = static_cast<int>(std::ceil(span.x())) + 1;
  ny_ = static_cast<int>(std::ceil(span.y())) + 1;
  const auto n = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  depth_.assign(n, 0.0);
  weight_.assign(n, 0.0);
  known_.assign(n, 0);
}

bool SeabedHeightfield::cellOf(double north, double east, int& i, int& j, double& fx,
                               double& fy) const {
  const double x = (north - origin_.x()) / cell_;
  const double y = (east - origin_.y()) / cell_;
  if (!(x >= 0.0) || !(y >= 0.0) || x >= nx_ - 1 || y >= ny_ - 1) {
    return false;
  }
  i = static_cast<int>(x);
  j = static_cast<int>(y);
  fx = x - i;
  fy = y - j;
  return true;
}

void SeabedHeightfield::stencil(double north, double east, std::size_t nodes[4],
                                double weights[4]) const {
  int i = 0, j = 0;
  double fx = 0.0, fy = 0.0;
  if (!cellOf(north, east, i, j, fx, fy)) {
    for (int k = 0; k < 4; ++k) {
      nodes[k] = 0;
      weights[k] = 0.0;
    }
    return;
  }
  const auto base =
      static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
  nodes[0] = base;
  nodes[1] = base + 1;
  nodes[2] = base + static_cast<std::size_t>(nx_);
  nodes[3] = base + static_cast<std::size_t>(nx_) + 1;
  weights[0] = (1.0 - fx) * (1.0 - fy);
  weights[1] = fx * (1.0 - fy);
  weights[2] = (1.0 - fx) * fy;
  weights[3] = fx * fy;
}

void SeabedHeightfield::gradientStencil(double north, double east, std::size_t nodes[4],
                                        double d_north[4], double d_east[4]) const {
  double w[4];
  stencil(north, east, nodes, w);
  int i = 0, j = 0;
  double fx = 0.0, fy = 0.0;
  if (!cellOf(north, east, i, j, fx, fy)) {
    for (int k = 0; k < 4; ++k) {
      d_north[k] = d_east[k] = 0.0;
    }
    return;
  }
  // Nodes 00, 10 (next north), 01 (next east), 11.
  d_north[0] = -(1.0 - fy) / cell_;
  d_north[1] = (1.0 - fy) / cell_;
  d_north[2] = -fy / cell_;
  d_north[3] = fy / cell_;
  d_east[0] = -(1.0 - fx) / cell_;
  d_east[1] = -fx / cell_;
  d_east[2] = (1.0 - fx) / cell_;
  d_east[3] = fx / cell_;
}

void SeabedHeightfield::add(double north, double east, double depth_m, double weight) {
  std::size_t nodes[4];
  double w[4];
  stencil(north, east, nodes, w);
  for (int k = 0; k < 4; ++k) {
    depth_[nodes[k]] += w[k] * weight * depth_m;
    weight_[nodes[k]] += w[k] * weight;
  }
}

void SeabedHeightfield::finish(double min_weight) {
  for (std::size_t n = 0; n < depth_.size(); ++n) {
    known_[n] = weight_[n] >= min_weight && weight_[n] > 0.0 ? 1 : 0;
    depth_[n] = known_[n] != 0 ? depth_[n] / weight_[n] : 0.0;
  }
}

bool SeabedHeightfield::covers(double north, double east) const {
  std::size_t nodes[4];
  double w[4];
  stencil(north, east, nodes, w);
  if (w[0] + w[1] + w[2] + w[3] < 0.5) {
    return false;  // outside the grid
  }
  return known_[nodes[0]] != 0 && known_[nodes[1]] != 0 && known_[nodes[2]] != 0 &&
         known_[nodes[3]] != 0;
}

double SeabedHeightfield::depthAt(double north, double east, Eigen::Vector2d* gradient) const {
  int i = 0, j = 0;
  double fx = 0.0, fy = 0.0;
  if (!cellOf(north, east, i, j, fx, fy)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const auto base =
      static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
  const double d00 = depth_[base];
  const double d10 = depth_[base + 1];
  const double d01 = depth_[base + static_cast<std::size_t>(nx_)];
  const double d11 = depth_[base + static_cast<std::size_t>(nx_) + 1];
  if (gradient != nullptr) {
    gradient->x() = ((d10 - d00) * (1.0 - fy) + (d11 - d01) * fy) / cell_;
    gradient->y() = ((d01 - d00) * (1.0 - fx) + (d11 - d10) * fx) / cell_;
  }
  return (d00 * (1.0 - fx) + d10 * fx) * (1.0 - fy) + (d01 * (1.0 - fx) + d11 * fx) * fy;
}

Eigen::Vector3d SeabedHeightfield::upNormal(double north, double east) const {
  Eigen::Vector2d g;
  depthAt(north, east, &g);
  return Eigen::Vector3d(g.x(), g.y(), -1.0).normalized();
}

std::size_t SeabedHeightfield::knownCount() const {
  return static_cast<std::size_t>(std::count(known_.begin(), known_.end(), 1));
}

Eigen::Vector2d SeabedHeightfield::nodePosition(std::size_t node) const {
  const auto nx = static_cast<std::size_t>(nx_);
  return origin_ +
         cell_ * Eigen::Vector2d(static_cast<double>(node % nx), static_cast<double>(node / nx));
}

double SeabedSurface::rayRange(const Eigen::Vector3d& origin,
                               const Eigen::Vector3d& direction) const {
  const double towards = plane.normal.dot(direction);
  const double height = plane.normal.dot(origin) - plane.offset;
  if (!(towards < -1e-9) || !(height > 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  const double on_plane = height / -towards;
  if (field == nullptr) {
    return on_plane;
  }
  // Newton on g(r) = depth of the ray's point - the seabed's depth under it (0 where it meets).
  constexpr int kSteps = 6;
  constexpr double kConverged_m = 1e-5;
  double r = on_plane;
  for (int step = 0; step < kSteps; ++step) {
    const Eigen::Vector3d p = origin + r * direction;
    if (!field->covers(p.x(), p.y())) {
      return on_plane;
    }
    Eigen::Vector2d grad;
    const double g = p.z() - field->depthAt(p.x(), p.y(), &grad);
    const double slope = direction.z() - grad.dot(direction.head<2>());
    if (!(slope > 0.02)) {
      return on_plane;  // grazing the relief: the plane's answer
    }
    r -= g / slope;
    if (std::abs(g) < kConverged_m) {
      break;
    }
  }
  return r > 0.0 ? r : std::numeric_limits<double>::infinity();
}

Eigen::Vector3d SeabedSurface::upNormal(const Eigen::Vector3d& at) const {
  if (field != nullptr && field->covers(at.x(), at.y())) {
    return field->upNormal(at.x(), at.y());
  }
  return plane.normal;
}

}  // namespace sonarcarve
