// The mission's navigation CSV: one row per sample with the named columns
//   time_s, north_m, east_m, down_m, roll_deg, pitch_deg, yaw_deg
// (any order; other columns are ignored), or latitude_deg, longitude_deg (WGS84) or
// easting_m, northing_m (in the mission's CRS) in place of north_m, east_m
// (io/mission/nav_positions.h). See docs/formats.md.
#pragma once

#include <filesystem>
#include <string>

#include "sonar/nav_track.h"

namespace sonarcarve {

/// Reads NED navigation (north_m, east_m). Throws Error naming the file and line on a missing
/// column, a non-finite value or a time that does not increase, and on geodetic or projected
/// columns, which need a mission's CRS (the overload below).
NavTrack readNavCsv(const std::filesystem::path& path);
/// Reads any kind of position, geodetic and projected ones placed on the grid of `grid_crs`
/// (in: the mission's declared CRS, maybe empty; out: the grid's, io/mission/nav_positions.h).
NavTrack readNavCsv(const std::filesystem::path& path, std::string& grid_crs);
std::string navCsvText(const NavTrack& track);

}  // namespace sonarcarve
