// Navigation given in geodetic or projected coordinates, placed on the grid of the mission's
// projected CRS (docs/conventions.md, "Geodetic navigation and CRSs"): world north is the
// grid's northing, east its easting, down the depth as given. Headings, which are from true
// north, are turned by the grid bearing of true north at each sample (the grid convergence),
// which PROJ gives: the grid position of a point a little north of the sample.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "geo/crs_transform.h"
#include "sonar/nav_track.h"

namespace sonarcarve {

/// Where a navigation file's positions come from, for messages: the file and the place of
/// sample i ("line 12").
struct PositionSource {
  std::string file;
  std::function<std::string(std::size_t)> place;
};

class GridProjection {
 public:
  /// From `from_crs` (positions as x = longitude or easting, y = latitude or northing) to the
  /// grid of `grid_crs`. Throws Error(source, place, ...) if PROJ cannot join them.
  GridProjection(const std::string& from_crs, const std::string& grid_crs,
                 const std::string& source, const std::string& place);

  struct GridPoint {
    double north_m = 0.0;
    double east_m = 0.0;
    double true_north_bearing_rad = 0.0;  ///< clockwise from grid north to true north
  };
  /// The grid position of (x, y) and the bearing of true north there. Throws Error naming
  /// `source` and `where` where PROJ cannot place it.
  GridPoint place(double x, double y, const std::string& source, const std::string& where) const;

 private:
  CrsTransform to_grid_;
  CrsTransform to_geodetic_;       // from_crs -> WGS84 longitude, latitude
  CrsTransform geodetic_to_grid_;  // WGS84 longitude, latitude -> grid
};

/// Sets each sample's north and east from `xy[i]` (in the projection's first CRS) on its grid,
/// keeps its down, and turns its attitude from true north to grid north.
void placeOnGrid(std::vector<NavSample>& samples, const std::vector<Eigen::Vector2d>& xy,
                 const GridProjection& grid, const PositionSource& source);

}  // namespace sonarcarve
