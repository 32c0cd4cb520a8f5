// A mission's place on the Earth, declared in mission.yaml (docs/formats.md, "mission.yaml"):
//   crs: EPSG:32631      the projected CRS of the navigation's grid (world north = northing,
//                        east = easting; docs/conventions.md, "Geodetic navigation and CRSs")
//   origin:              the mission origin, geodetic or projected:
//     {latitude_deg: 43.0, longitude_deg: 3.0, depth_m: 0}
//     {northing_m: 4760800, easting_m: 500000, depth_m: 0, crs: EPSG:32631}  (crs: the
//                        mission's when absent)
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "io/files/yaml_fields.h"

namespace sonarcarve {

/// The `crs` key of mission.yaml's `root`, checked by PROJ (errors name the file, the line and
/// the key); empty when absent.
std::string declaredCrs(const YAML::Node& root, const YamlFields& fields);

/// The `origin` of mission.yaml's `root` on the grid of `grid_crs` (world NED: northing,
/// easting, depth), placed by PROJ; nothing when absent. Errors name the file, the line and
/// the key: a geodetic origin without a grid, keys of both kinds, a point PROJ cannot place.
std::optional<Eigen::Vector3d> declaredOrigin(const YAML::Node& root, const YamlFields& fields,
                                              const std::string& grid_crs);

}  // namespace sonarcarve
