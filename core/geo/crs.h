// Coordinate reference systems as PROJ names them: an authority code (EPSG:32631), a PROJ
// string (+proj=utm +zone=31 +datum=WGS84) or WKT. PROJ (Debian's libproj-dev, its database
// in proj-data) checks and transforms them; SonarCarve computes no projection itself
// (docs/conventions.md, "Geodetic navigation and CRSs").
#pragma once

#include <optional>
#include <string>

namespace sonarcarve {

/// WGS84 longitude and latitude in degrees: the CRS of nav.csv's latitude_deg, longitude_deg.
inline constexpr const char* kWgs84Crs = "EPSG:4326";

/// What is wrong with `definition` as the CRS of a map grid (a mission's, an export's): not a
/// CRS PROJ knows, or not a projected CRS whose two axes are in metres. In words ending with
/// what was expected; nothing when it is one.
std::optional<std::string> gridCrsProblem(const std::string& definition);

/// Throws Error(file, field, ...) when gridCrsProblem finds something.
void requireGridCrs(const std::string& definition, const std::string& file,
                    const std::string& field);

/// PROJ's name of a CRS ("WGS 84 / UTM zone 31N"), or the definition itself if PROJ has none.
std::string crsName(const std::string& definition);

/// The CRS as OGC WKT 1 in GDAL's dialect (what LAS 1.4's WKT record and GeoTIFF readers expect),
/// from PROJ (proj_as_wkt); a CRS WKT 1 cannot express comes as WKT2:2019. Throws Error(file,
/// field, ...) when PROJ does not know it.
std::string crsWkt(const std::string& definition, const std::string& file,
                   const std::string& field);

/// The WGS84 UTM zone CRS ("EPSG:32631") whose zone holds `longitude_deg`, north or south of
/// the equator by `latitude_deg`: zones of 6 degrees from 180 W, without the Norway and
/// Svalbard exceptions. A zone number only: PROJ projects.
std::string utmZoneCrs(double latitude_deg, double longitude_deg);

/// The first word of the comment that carries a CRS in an output's header (PLY, OBJ, .bt).
inline constexpr const char* kCrsCommentKeyword = "crs";
/// "crs EPSG:32631": the rest of the line is the CRS (a WKT's line breaks become spaces).
std::string crsComment(const std::string& crs);

}  // namespace sonarcarve
