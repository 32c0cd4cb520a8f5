#include "geo/grid_projection.h"

#include <Eigen/Geometry>
#include <cmath>

#include "common/error.h"
#include "common/number_text.h"
#include "geo/crs.h"

namespace sonarcarve {
namespace {

// How far north of a sample the point that gives the bearing of true north lies: 1e-5 deg
// (1.1 m). The grid direction between the two points is true north's to 1e-8 rad (the
// bearing changes by about the step times tan(latitude)), far below any heading sensor.
constexpr double kNorthStep_deg = 1e-5;

}  // namespace

GridProjection::GridProjection(const std::string& from_crs, const std::string& grid_crs,
                               const std::string& source, const std::string& place)
    : to_grid_(from_crs, grid_crs, source, place),
      to_geodetic_(from_crs, kWgs84Crs, source, place),
      geodetic_to_grid_(kWgs84Crs, grid_crs, source, place) {}

GridProjection::GridPoint GridProjection::place(double x, double y, const std::string& source,
                                                const std::string& where) const {
  const auto fail = [&](const CrsTransform& transform) {
    return Error(source, where,
                 "position (" + shortestNumber(x) + ", " + shortestNumber(y) +
                     ") cannot be placed on the mission's grid (" + transform.lastError() +
                     "): expected a position inside the CRS's area");
  };
  const auto grid = to_grid_.apply({x, y, 0.0});
  if (!grid) {
    throw fail(to_grid_);
  }
  const auto geodetic = to_geodetic_.apply({x, y, 0.0});
  if (!geodetic) {
    throw fail(to_geodetic_);
  }
  // A point a little north on the same meridian (south near the north pole).
  const double step = geodetic->y() + kNorthStep_deg <= 90.0 ? kNorthStep_deg : -kNorthStep_deg;
  const auto here = geodetic_to_grid_.apply({geodetic->x(), geodetic->y(), 0.0});
  const auto north = geodetic_to_grid_.apply({geodetic->x(), geodetic->y() + step, 0.0});
  if (!here || !north) {
    throw fail(geodetic_to_grid_);
  }
  const Eigen::Vector2d toward_north = (*north - *here).head<2>() * (step > 0 ? 1.0 : -1.0);
  GridPoint point;
  point.east_m = grid->x();
  point.north_m = grid->y();
  point.true_north_bearing_rad = std::atan2(toward_north.x(), toward_north.y());
  return point;
}

void placeOnGrid(std::vector<NavSample>& samples, const std::vector<Eigen::Vector2d>& xy,
                 const GridProjection& grid, const PositionSource& source) {
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const GridProjection::GridPoint p =
        grid.place(xy[i].x(), xy[i].y(), source.file, source.place(i));
    NavSample& s = samples[i];
    s.position_m.x() = p.north_m;
    s.position_m.y() = p.east_m;
    // A heading from true north is, on the grid, that heading plus true north's grid bearing:
    // a turn about the world's down axis.
    s.q_world_vehicle =
        Eigen::Quaterniond(Eigen::AngleAxisd(p.true_north_bearing_rad, Eigen::Vector3d::UnitZ())) *
        s.q_world_vehicle;
  }
}

}  // namespace sonarcarve
