// Navigation from other people's CSV files: a mapping says which column holds what, in which
// unit and which angle convention, and the rows become our NavTrack (world NED, metres,
// radians; docs/conventions.md). The mapping comes from a small YAML file (docs/formats.md,
// "Navigation mapping") and/or from command-line settings; both go through setNavMapping().
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "sonar/nav_track.h"

namespace sonarcarve {

/// A column by header name, or by 0-based index (index >= 0).
struct NavColumn {
  std::string name;
  int index = -1;
  bool given() const { return index >= 0 || !name.empty(); }
  std::string describe() const;
};

struct NavMapping {
  char delimiter = ',';
  bool header = true;
  // Defaults: the columns of the mission format's own nav.csv.
  NavColumn time{"time_s"};
  NavColumn north{"north_m"};
  NavColumn east{"east_m"};
  NavColumn down{"down_m"};  ///< depth, positive down
  NavColumn up;              ///< instead of down: altitude or height, positive up
  NavColumn roll{"roll_deg"};
  NavColumn pitch{"pitch_deg"};
  NavColumn yaw{"yaw_deg"};  ///< heading or yaw, see heading_enu
  /// Instead of north and east (io/mission/nav_positions.h): WGS84 degrees ...
  NavColumn latitude;
  NavColumn longitude;
  /// ... or metres in `crs`.
  NavColumn easting;
  NavColumn northing;
  /// The projected CRS (EPSG:NNNN, a PROJ string) of easting and northing, and of the grid
  /// latitude and longitude are placed on; empty: their first sample's UTM zone.
  std::string crs;
  /// No position column named (the defaults): the kind is the header's, as in nav.csv.
  bool default_positions = true;
  double seconds_per_time_unit = 1.0;  ///< s, ms, us
  double metres_per_unit = 1.0;        ///< m or ft
  bool degrees = true;                 ///< angles in degrees (else radians)
  /// false: heading clockwise from north (compass, = NED yaw); true: yaw counter-clockwise
  /// from east (ENU, as in ROS): yaw_ned = 90 deg - yaw_enu.
  bool heading_enu = false;
  bool pitch_bow_down = false;  ///< positive pitch lowers the bow (ROS FLU body)
  bool roll_port_down = false;  ///< positive roll lowers the port side
};

/// Sets one field of the mapping: `key` is "columns.time" ... "columns.heading" (and
/// "columns.latitude|longitude|easting|northing"), "units.time|position|angles",
/// "conventions.heading|pitch|roll", "delimiter", "header" or "crs" (checked by PROJ).
/// Throws Error(source, "", ...) naming the key and the allowed values on a bad value;
/// callers with a better place (a YAML line) catch and rethrow.
void setNavMapping(NavMapping& mapping, const std::string& key, const std::string& value,
                   const std::string& source);

/// Reads a mapping YAML (docs/formats.md); errors name the file, line and key.
NavMapping readNavMapping(const std::filesystem::path& path);

/// The same from YAML text in memory; `source` names it in messages.
NavMapping parseNavMapping(std::string_view text, const std::string& source);

/// Reads a navigation CSV with a mapping. Errors name the file, the line and the column.
/// `grid_crs` (when given) receives the CRS of the track's grid: the mapping's, or the UTM zone
/// geodetic positions were placed on; empty for NED positions without a CRS.
NavTrack importNavCsv(const std::filesystem::path& path, const NavMapping& mapping,
                      std::string* grid_crs = nullptr);
/// The same from text in memory; `source` names it in messages.
NavTrack importNavCsvText(std::string_view text, const std::string& source,
                          const NavMapping& mapping, std::string* grid_crs = nullptr);

}  // namespace sonarcarve
