// Class "where on the Earth" (docs/conventions.md, "Geodetic navigation and CRSs"): CRS codes
// PROJ does not know or that cannot be a map grid, in mission.yaml, its origin and a
// navigation mapping; navigation with two kinds of position; latitudes off the Earth; a
// geodetic origin for navigation with no grid. Each is refused naming the file, the place and
// what was expected.
#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {
namespace {

constexpr const char* kNedHeader = "time_s,north_m,east_m,";
constexpr const char* kGeodeticHeader = "time_s,latitude_deg,longitude_deg,";

void appendTo(const std::filesystem::path& path, const std::string& text) {
  writeBytes(path, readText(path) + text);
}

// The example mission with `text` added to its mission.yaml, through `info`.
CatalogueCase missionYaml(const std::string& name, const std::string& text,
                          const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [text](const Workspace& ws) {
                appendTo(ws.mission() / "mission.yaml", text);
                return std::string("info mission");
              },
          .message = message};
}

}  // namespace

std::vector<CatalogueCase> geoCases() {
  return {
      missionYaml("MissionCrsUnknownCode", "crs: EPSG:99999999\n",
                  {"mission.yaml: line 16: crs: 'EPSG:99999999' is not a CRS PROJ knows",
                   "expected a projected CRS in metres, e.g. EPSG:32631"}),
      missionYaml("MissionCrsGeographic", "crs: EPSG:4326\n",
                  {"mission.yaml: line 16: crs: 'EPSG:4326' (WGS 84) is not a projected CRS",
                   "expected a projected CRS in metres"}),
      missionYaml("MissionCrsInFeet", "crs: EPSG:2263\n",
                  {"mission.yaml: line 16: crs", "does not have two axes in metres"}),
      missionYaml("MissionCrsNotACrs", "crs: +proj=utm +zone=31\n",
                  {"mission.yaml: line 16: crs: '+proj=utm +zone=31' is not a CRS PROJ knows"}),
      missionYaml("OriginCrsUnknownCode",
                  "crs: EPSG:32631\norigin: {easting_m: 500000, northing_m: 4760800, "
                  "depth_m: 0, crs: EPSG:0}\n",
                  {"mission.yaml: line 17: origin.crs: 'EPSG:0' is not a CRS PROJ knows"}),
      missionYaml("GeodeticOriginWithoutAGrid",
                  "origin: {latitude_deg: 43, longitude_deg: 3, depth_m: 0}\n",
                  {"mission.yaml: line 16: origin", "the navigation is NED without a CRS",
                   "expected crs: EPSG:NNNN"}),
      // An origin where no survey lies is the origin's error, not the navigation's (each was
      // blamed on nav.csv's first sample, moved by it beyond 1e8 m).
      missionYaml("OriginNorthingOffTheEarth",
                  "crs: EPSG:32631\norigin: {easting_m: 500000, northing_m: -1e12, depth_m: 0}\n",
                  {"mission.yaml: line 17: origin: position (north, east, down) = "
                   "(-1000000000000, 500000, 0) m: expected finite coordinates within 1e8 m"}),
      missionYaml("OriginEastingOfOneE300",
                  "crs: EPSG:32631\norigin: {easting_m: 1e300, northing_m: 4760800, "
                  "depth_m: 0}\n",
                  {"mission.yaml: line 17: origin: position (north, east, down) =",
                   "expected finite coordinates within 1e8 m"}),
      missionYaml("GeodeticOriginAMillionKilometresDeep",
                  "crs: EPSG:32631\norigin: {latitude_deg: 43, longitude_deg: 3, "
                  "depth_m: 1e9}\n",
                  {"mission.yaml: line 17: origin: position (north, east, down) =",
                   "1000000000) m: expected finite coordinates within 1e8 m"}),
      {.name = "NavWithLatitudeLongitudeAndNorthEast",
       .prepare =
           [](const Workspace& ws) {
             // north_m and longitude_deg: one column of each kind is enough to refuse.
             replaceIn(ws.mission() / "nav.csv", kNedHeader, "time_s,north_m,longitude_deg,");
             return std::string("info mission");
           },
       .message = {"nav.csv: line 1: positions of two kinds", "expected one kind"}},
      {.name = "NavLatitudeOffTheEarth",
       .prepare =
           [](const Workspace& ws) {
             replaceIn(ws.mission() / "nav.csv", kNedHeader, kGeodeticHeader);
             replaceIn(ws.mission() / "nav.csv", "100.25,0,0,10.05", "100.25,95,0,10.05");
             return std::string("info mission");
           },
       .message = {"nav.csv: line 3: latitude 95 deg: expected WGS84 degrees within -90..90"}},
      {.name = "NavEastingNorthingWithoutACrs",
       .prepare =
           [](const Workspace& ws) {
             replaceIn(ws.mission() / "nav.csv", kNedHeader, "time_s,easting_m,northing_m,");
             return std::string("info mission");
           },
       .message = {"nav.csv: line 1: easting and northing without the CRS",
                   "expected crs: EPSG:NNNN"}},
      {.name = "NavMappingCrsUnknownCode",
       .prepare =
           [](const Workspace& ws) {
             writeBytes(ws / "map.yaml",
                        "columns: {time: time_s, latitude: lat, longitude: lon, depth: down_m}\n"
                        "crs: EPSG:31\n");
             return std::string("info mission --nav mission/nav.csv --nav-map map.yaml");
           },
       .message = {"map.yaml: line 2: crs: 'EPSG:31' is not a CRS PROJ knows"}},
      {.name = "NavSetCrsGeographic",
       .prepare =
           [](const Workspace&) {
             return std::string("info mission --nav mission/nav.csv --nav-set crs=EPSG:4326");
           },
       .message = {"--nav-set: crs: 'EPSG:4326' (WGS 84) is not a projected CRS"}},
  };
}

}  // namespace sonarcarve::test
