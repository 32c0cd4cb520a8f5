#include "sim/seabed_field.h"

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "common/error.h"
#include "sim/scene_shapes.h"

namespace sonarcarve {
namespace {

constexpr double kObjectMargin_m = 2.0;  // objects keep this far from a tile's borders
constexpr double kMaxAreaTiles = 1.0e5;  // what one call of area() may build

// A well-mixed 64-bit hash (splitmix64's finaliser).
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t tileSeed(std::uint64_t seed, const Eigen::Vector2i& tile) {
  const auto n = static_cast<std::uint32_t>(tile.x());
  const auto e = static_cast<std::uint32_t>(tile.y());
  return mix(mix(seed) ^ ((static_cast<std::uint64_t>(n) << 32) | e));
}

void requireIn(double value, double lo, double hi, const char* name) {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream text;
    text << "is " << value << ": expected " << lo << " to " << hi;
    throw Error("seabed field", name, text.str());
  }
}

}  // namespace

void validate(const SeabedFieldSpec& spec) {
  requireIn(spec.depth_m, 1.0, 11000.0, "depth_m");
  requireIn(spec.relief_m, 0.0, 0.5 * spec.depth_m, "relief_m");
  requireIn(spec.tile_m, 2.5 * kObjectMargin_m, 1000.0, "tile_m");
  requireIn(spec.grid_m, spec.tile_m / 1000.0, spec.tile_m, "grid_m");
  requireIn(spec.max_objects_per_tile, 0, 20, "max_objects_per_tile");
}

SeabedField::SeabedField(SeabedFieldSpec spec)
    : spec_((validate(spec), spec)),
      relief_(mix(spec_.seed ^ 0x5eabedULL), spec_.relief_m, 15.0, 40.0) {}

double SeabedField::seabedDown(double north_m, double east_m) const {
  return spec_.depth_m + relief_.offsetDown(Eigen::Vector2d(north_m, east_m));
}

Eigen::Vector2i SeabedField::tileOf(double north_m, double east_m) const {
  return {static_cast<int>(std::floor(north_m / spec_.tile_m)),
          static_cast<int>(std::floor(east_m / spec_.tile_m))};
}

void SeabedField::addSeabed(const Eigen::Vector2i& tile, Scene& scene) const {
  const int cells = static_cast<int>(std::round(spec_.tile_m / spec_.grid_m));
  const double step = spec_.tile_m / cells;
  const Eigen::Vector2d origin = spec_.tile_m * tile.cast<double>();
  scene.append(heightfieldMesh(
      origin, cells, step, [&](const Eigen::Vector2d& p) { return seabedDown(p.x(), p.y()); },
      [&](const Eigen::Vector2d& p) { return relief_.slope(p); },
      [&](const Eigen::Vector2d& centre) {
        // Sediment patches: the reflectivity varies slowly over tens of metres.
        return static_cast<float>(
            0.3 + 0.05 * std::sin(0.7 * relief_.wave(1).dot(centre) + relief_.phase(2)));
      }));
}

void SeabedField::addObjects(const Eigen::Vector2i& tile, Scene& scene) const {
  std::mt19937_64 rng(tileSeed(spec_.seed, tile));
  std::uniform_int_distribution<int> count(0, spec_.max_objects_per_tile), kind(0, 3);
  std::uniform_real_distribution<double> place(kObjectMargin_m, spec_.tile_m - kObjectMargin_m),
      unit(0.0, 1.0);
  const auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  const Eigen::Vector2d origin = spec_.tile_m * tile.cast<double>();
  const int objects = count(rng);
  for (int o = 0; o < objects; ++o) {
    const double north = origin.x() + place(rng), east = origin.y() + place(rng);
    const double floor = seabedDown(north, east) + 0.05;  // resting 5 cm into the seabed
    const float reflectivity = static_cast<float>(between(0.7, 0.9));
    const double heading = between(0.0, std::numbers::pi);
    switch (kind(rng)) {
      case 0: {  // a box, up to 1.5 m
        const Eigen::Vector3d size(between(0.5, 1.5), between(0.4, 1.2), between(0.3, 1.0));
        scene.append(boxShape({north, east, floor - 0.5 * size.z()}, size,
                              heading * 180.0 / std::numbers::pi, reflectivity));
        break;
      }
      case 1: {  // a pipe lying on the seabed, up to 3 m long
        const double radius = between(0.1, 0.35), half = 0.5 * between(1.0, 3.0);
        const Eigen::Vector3d centre(north, east, floor - radius);
        const Eigen::Vector3d along(std::cos(heading), std::sin(heading), 0.0);
        scene.append(
            tubeShape(centre - half * along, centre + half * along, radius, 24, reflectivity));
        break;
      }
      case 2: {  // a sphere (a buoy, a boulder)
        const double radius = between(0.2, 0.6);
        scene.append(sphereShape({north, east, floor - radius}, radius, reflectivity, 32));
        break;
      }
      default: {  // an upright post
        const double radius = between(0.08, 0.2), height = between(0.5, 2.0);
        scene.append(tubeShape({north, east, floor + 0.05}, {north, east, floor - height}, radius,
                               16, reflectivity));
        break;
      }
    }
  }
}

Scene SeabedField::tile(const Eigen::Vector2i& tile) const {
  Scene scene;
  scene.name = "seabed-field";
  addSeabed(tile, scene);
  addObjects(tile, scene);
  scene.target = target();
  return scene;
}

Scene SeabedField::area(const Eigen::AlignedBox2d& north_east) const {
  const Eigen::Vector2i lo = tileOf(north_east.min().x(), north_east.min().y());
  const Eigen::Vector2i hi = tileOf(north_east.max().x(), north_east.max().y());
  const double tiles = (hi - lo + Eigen::Vector2i::Ones()).cast<double>().prod();
  if (north_east.isEmpty() || !(tiles <= kMaxAreaTiles)) {
    std::ostringstream text;
    text << "an area of " << tiles << " tiles: expected 1 to " << kMaxAreaTiles;
    throw Error("seabed field", "area", text.str());
  }
  Scene scene;
  scene.name = "seabed-field";
  for (int n = lo.x(); n <= hi.x(); ++n) {
    for (int e = lo.y(); e <= hi.y(); ++e) {
      scene.append(tile({n, e}));
    }
  }
  scene.target = target();
  return scene;
}

InspectionTarget SeabedField::target() const {
  // The mean depth: a survey keeps its depth while the relief passes under it.
  const double seabed = spec_.depth_m;
  return {Eigen::Vector3d(0.0, 0.0, seabed), seabed - 2.0, seabed, seabed};
}

}  // namespace sonarcarve
