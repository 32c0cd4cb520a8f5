// The three kinds of position a navigation CSV may hold (docs/formats.md, "Navigation"):
//   NED        north_m, east_m: world metres as they are (a grid's northing and easting when
//              the mission declares its CRS)
//   geodetic   latitude_deg, longitude_deg: WGS84 degrees
//   projected  easting_m, northing_m: metres in the mission's CRS (mission.yaml `crs:`)
// plus down_m in each. Geodetic and projected positions are placed on the mission's grid by
// PROJ (geo/grid_projection.h); a file holds one kind only.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geo/grid_projection.h"
#include "sonar/nav_track.h"

namespace sonarcarve {

enum class PositionKind { Ned, Geodetic, Projected };

/// The kind whose columns are named; throws Error(file, place, ...) when columns of two kinds
/// are, naming them and the three kinds expected. NED when none is.
PositionKind positionKind(bool ned, bool geodetic, bool projected, const std::string& names,
                          const std::string& file, const std::string& place);

/// (longitude, latitude) from a row's latitude and longitude in degrees; throws Error(file,
/// place, ...) outside -90..90 and -180..180.
Eigen::Vector2d geodeticXy(double latitude_deg, double longitude_deg, const std::string& file,
                           const std::string& place);

/// Places samples whose positions were read as `xy` (geodetic: longitude, latitude; projected:
/// easting, northing) on the grid of `grid_crs` (in: the mission's declared CRS, maybe empty;
/// out: the grid's: geodetic navigation without one takes its first sample's UTM zone).
/// Projected positions without a CRS are an error naming `header_place`. NED: nothing to do.
void placeNavOnGrid(std::vector<NavSample>& samples, const std::vector<Eigen::Vector2d>& xy,
                    PositionKind kind, std::string& grid_crs, const PositionSource& source,
                    const std::string& header_place);

}  // namespace sonarcarve
