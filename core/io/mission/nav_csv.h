// The mission's navigation CSV: one row per sample with the named columns
//   time_s, north_m, east_m, down_m, roll_deg, pitch_deg, yaw_deg
// (any order; other columns are ignored). See docs/formats.md.
#pragma once

#include <filesystem>
#include <string>

#include "sonar/nav_track.h"

namespace sonarcarve {

/// Throws Error naming the file and line on a missing column, a non-finite value or a time
/// that does not increase.
NavTrack readNavCsv(const std::filesystem::path& path);
std::string navCsvText(const NavTrack& track);

}  // namespace sonarcarve
