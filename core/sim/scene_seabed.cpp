#include "sim/scene_seabed.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "common/error.h"
#include "sim/scene_shapes.h"

namespace sonarcarve {
namespace {

constexpr double kReliefRamp_m = 2.0;  // from levelled to the full relief
constexpr double kReliefGrid_m = 0.25;

double smoothstep(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

void validate(const SeabedReliefSpec& spec) {
  const auto require = [](double value, double lo, double hi, const char* name) {
    if (!(value >= lo && value <= hi)) {
      std::ostringstream text;
      text << "is " << value << ": expected " << lo << " to " << hi;
      throw Error("seabed relief", name, text.str());
    }
  };
  require(spec.relief_m, 0.0, 5.0, "relief_m");
  require(spec.wavelength_m, 1.0, 1000.0, "wavelength_m");
}

SceneSeabed::SceneSeabed(double floor_m, double slope_deg, const SeabedReliefSpec& relief,
                         const Eigen::Vector2d& site, double flat_radius_m)
    : floor_m_(floor_m), slope_deg_(slope_deg), site_(site), flat_radius_m_(flat_radius_m) {
  validate(relief);
  if (relief.relief_m > 0.0) {
    relief_.emplace(relief.seed ^ 0x5ce7e5eabedULL, relief.relief_m, relief.wavelength_m,
                    2.0 * relief.wavelength_m);
    relief_at_site_ = relief_->offsetDown(site_);
  }
}

double SceneSeabed::relief(const Eigen::Vector2d& p) const {
  if (!relief_) {
    return 0.0;
  }
  // Levelled around the site (at the plane's depth there), the full relief further out.
  const double levelled = flat_radius_m_ > 0.0
                              ? smoothstep(((p - site_).norm() - flat_radius_m_) / kReliefRamp_m)
                              : 1.0;
  return levelled * (relief_->offsetDown(p) - relief_at_site_);
}

double SceneSeabed::downAt(double north_m, double east_m) const {
  // The flat seabed's formula, as the scenes have always placed things on it.
  const double plane = floor_m_ + north_m * std::tan(slope_deg_ * std::numbers::pi / 180.0);
  return relief_ ? plane + relief({north_m, east_m}) : plane;
}

Scene SceneSeabed::mesh(double size_m, int flat_resolution, float reflectivity) const {
  if (!relief_) {
    return seabedSquare({site_.x(), site_.y(), floor_m_}, size_m, slope_deg_, flat_resolution,
                        reflectivity);
  }
  const int cells = static_cast<int>(std::ceil(size_m / kReliefGrid_m));
  const double step = size_m / cells;
  const auto down = [&](const Eigen::Vector2d& p) { return downAt(p.x(), p.y()); };
  // The normals from central differences of the depth (the levelling makes it piecewise).
  const auto slope = [&](const Eigen::Vector2d& p) {
    constexpr double h = 1e-3;
    const double n = p.x();
    const double e = p.y();
    return Eigen::Vector2d((downAt(n + h, e) - downAt(n - h, e)) / (2.0 * h),
                           (downAt(n, e + h) - downAt(n, e - h)) / (2.0 * h));
  };
  const Eigen::Vector2d corner(site_.x() - 0.5 * size_m, site_.y() - 0.5 * size_m);
  return heightfieldMesh(corner, cells, step, down, slope,
                         [&](const Eigen::Vector2d&) { return reflectivity; });
}

}  // namespace sonarcarve
