// One run of the workbench as the session keeps it: when it started, its parameters and its
// figures (frames carved, occupied voxels, surface points, mesh triangles, seconds) and, when
// the mission had a ground truth, its accuracy. Plain data, no Qt.
#pragma once

#include <optional>
#include <string>

#include "pipeline/reconstruction_params.h"

namespace sonarcarve {

struct RunAccuracy {
  double fscore = 0.0;  ///< at 5 cm
  double median_m = 0.0;
  double p90_m = 0.0;
  double precision = 0.0;
  double completeness = 0.0;
};

struct RunRecord {
  std::string started;  ///< local time, "2026-11-24 23:10:05"
  ReconstructionParams params;
  std::size_t frames = 0;
  std::size_t occupied_voxels = 0;
  std::size_t surface_points = 0;
  std::size_t mesh_triangles = 0;
  double seconds = 0.0;
  std::optional<RunAccuracy> accuracy;
  /// The run's survey report (report.html), written in the workbench's data folder; empty
  /// for a run that wrote none.
  std::string report;
};

}  // namespace sonarcarve
