// The flags that say how to open a recording (io/frame_source.h): its navigation CSV and the
// CSV's column mapping, the sonar's mounting, a time offset and a vertical aperture, and a
// bag's topics and conventions. Shared by
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
  std::string beam_pattern;                                     ///< "", "sinc" or "clipped"
  std::string sonar_topic, nav_topic, fix_topic, origin_topic;  ///< ROS 2 bags
  std::string sonar_axes = "auto", image_layout = "range-major", time_source = "header";
};

/// Adds --nav --nav-map --nav-column --nav-set --mounting --time-offset --aperture-deg
/// --beam-pattern, and for
/// ROS 2 bags --sonar-topic --nav-topic --sonar-axes --image-layout --time-source.
void addSourceFlags(CLI::App& cmd, SourceFlags& flags);

/// The options the flags describe. Throws Error naming the flag on a bad value.
OpenOptions openOptionsFrom(const SourceFlags& flags);

}  // namespace sonarcarve::cli
