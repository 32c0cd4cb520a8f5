// The flags that say how to open a recording (io/frame_source.h): its navigation CSV and the
// CSV's column mapping, the sonar's mounting, a time offset and a vertical aperture. Shared by
// every verb that opens recordings (reconstruct, info, frame, import).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "io/frame_source.h"

namespace sonarcarve::cli {

struct SourceFlags {
  std::string nav, nav_map, mounting;
  std::vector<std::string> nav_columns, nav_settings;
  double time_offset_s = 0.0;
  double aperture_deg = 0.0;
};

/// Adds --nav --nav-map --nav-column --nav-set --mounting --time-offset --aperture-deg.
void addSourceFlags(CLI::App& cmd, SourceFlags& flags);

/// The options the flags describe. Throws Error naming the flag on a bad value.
OpenOptions openOptionsFrom(const SourceFlags& flags);

}  // namespace sonarcarve::cli
