#include "io/mission/mission_place.h"

#include "common/error.h"
#include "geo/crs.h"
#include "geo/crs_transform.h"
#include "io/mission/nav_positions.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// A grid CRS at `node` (key `path`), checked by PROJ.
std::string gridCrsAt(const YAML::Node& node, const YamlFields& fields, const std::string& path) {
  const std::string crs = fields.text(node, path);
  if (const auto problem = gridCrsProblem(crs)) {
    fields.fail(node, path, *problem);
  }
  return crs;
}

}  // namespace

std::string declaredCrs(const YAML::Node& root, const YamlFields& fields) {
  return root["crs"] ? gridCrsAt(root["crs"], fields, "crs") : std::string();
}

std::optional<Eigen::Vector3d> declaredOrigin(const YAML::Node& root, const YamlFields& fields,
                                              const std::string& grid_crs) {
  const YAML::Node origin = root["origin"];
  if (!origin) {
    return std::nullopt;
  }
  if (!origin.IsMap()) {
    fields.fail(origin, "origin",
                "expected {latitude_deg, longitude_deg, depth_m} or {northing_m, easting_m, "
                "depth_m, crs}");
  }
  const bool geodetic = origin["latitude_deg"] || origin["longitude_deg"];
  const bool projected = origin["northing_m"] || origin["easting_m"];
  if (geodetic == projected) {
    fields.fail(origin, "origin",
                std::string(geodetic ? "keys of both kinds" : "no position") +
                    ": expected latitude_deg, longitude_deg (WGS84) or northing_m, easting_m "
                    "(projected), with depth_m");
  }
  const double depth_m = fields.number(fields.child(origin, "origin", "depth_m"), "origin.depth_m");
  if (grid_crs.empty()) {
    fields.fail(origin, "origin",
                "a geodetic or projected origin, but the navigation is NED without a CRS: "
                "expected crs: EPSG:NNNN (the navigation's projected CRS) in mission.yaml");
  }
  Eigen::Vector3d from;  // x first: longitude or easting
  std::string from_crs = kWgs84Crs;
  if (geodetic) {
    const YAML::Node lat = fields.child(origin, "origin", "latitude_deg");
    const YAML::Node lon = fields.child(origin, "origin", "longitude_deg");
    try {
      from.head<2>() = geodeticXy(fields.number(lat, "origin.latitude_deg"),
                                  fields.number(lon, "origin.longitude_deg"), "", "");
    } catch (const Error& e) {
      fields.fail(lat, "origin", e.message());
    }
  } else {
    from.x() = fields.number(fields.child(origin, "origin", "easting_m"), "origin.easting_m");
    from.y() = fields.number(fields.child(origin, "origin", "northing_m"), "origin.northing_m");
    from_crs = origin["crs"] ? gridCrsAt(origin["crs"], fields, "origin.crs") : grid_crs;
  }
  from.z() = 0.0;
  const CrsTransform to_grid(from_crs, grid_crs, fields.file(), "origin");
  const auto grid = to_grid.apply(from);
  if (!grid) {
    fields.fail(origin, "origin",
                "PROJ cannot place it on the grid of " + grid_crs + " (" + to_grid.lastError() +
                    "): expected a point inside the CRS's area");
  }
  // Where no survey lies, the origin is the error, not the navigation moved by it.
  const Eigen::Vector3d placed(grid->y(), grid->x(), depth_m);
  try {
    requirePlausiblePosition(placed, "", "");
  } catch (const Error& e) {
    fields.fail(origin, "origin", e.message());
  }
  return placed;
}

}  // namespace sonarcarve
