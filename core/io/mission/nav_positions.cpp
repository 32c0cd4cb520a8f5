#include "io/mission/nav_positions.h"

#include "common/error.h"
#include "common/number_text.h"
#include "geo/crs.h"

namespace sonarcarve {

PositionKind positionKind(bool ned, bool geodetic, bool projected, const std::string& names,
                          const std::string& file, const std::string& place) {
  if (static_cast<int>(ned) + static_cast<int>(geodetic) + static_cast<int>(projected) > 1) {
    throw Error(file, place,
                "positions of two kinds (" + names +
                    "): expected one kind: north_m, east_m (NED metres), or latitude_deg, "
                    "longitude_deg (WGS84 degrees), or easting_m, northing_m (metres in the "
                    "mission's crs)");
  }
  return geodetic    ? PositionKind::Geodetic
         : projected ? PositionKind::Projected
                     : PositionKind::Ned;
}

Eigen::Vector2d geodeticXy(double latitude_deg, double longitude_deg, const std::string& file,
                           const std::string& place) {
  if (!(latitude_deg >= -90.0 && latitude_deg <= 90.0)) {
    throw Error(
        file, place,
        "latitude " + shortestNumber(latitude_deg) + " deg: expected WGS84 degrees within -90..90");
  }
  if (!(longitude_deg >= -180.0 && longitude_deg <= 180.0)) {
    throw Error(file, place,
                "longitude " + shortestNumber(longitude_deg) +
                    " deg: expected WGS84 degrees within -180..180");
  }
  return {longitude_deg, latitude_deg};
}

void placeNavOnGrid(std::vector<NavSample>& samples, const std::vector<Eigen::Vector2d>& xy,
                    PositionKind kind, std::string& grid_crs, const PositionSource& source,
                    const std::string& header_place) {
  if (kind == PositionKind::Ned || samples.empty()) {
    return;
  }
  if (kind == PositionKind::Projected && grid_crs.empty()) {
    throw Error(source.file, header_place,
                "easting and northing without the CRS they are in: expected crs: EPSG:NNNN "
                "(a projected CRS in metres) in mission.yaml or the navigation mapping");
  }
  if (grid_crs.empty()) {
    grid_crs = utmZoneCrs(xy.front().y(), xy.front().x());
  }
  const std::string from = kind == PositionKind::Geodetic ? kWgs84Crs : grid_crs;
  const GridProjection grid(from, grid_crs, source.file, header_place);
  placeOnGrid(samples, xy, grid, source);
}

}  // namespace sonarcarve
