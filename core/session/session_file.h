// A workbench session saved to a YAML file: the mission, the reconstruction parameters (the same
// keys as a params YAML, embedded), the camera, the frame shown and the colouring. Qt-free.
//   format: sonarcarve-session
//   version: 1
//   mission: /path/to/mission
//   frame: 12
//   colour_by: intensity | depth | error
//   camera: {position: [n, e, d], focal_point: [...], view_up: [...], parallel: false,
//            parallel_scale: 1, view_angle_deg: 30}
//   params: {...}
//   runs:                 (optional: the run history, oldest first)
//     - {started: "2026-11-24 23:10:05", frames: 98, occupied_voxels: 41234, surface_points:
//        9000, mesh_triangles: 20000, seconds: 9.8, params: {...},
//        accuracy: {fscore: 0.94, median_m: 0.005, p90_m: 0.013, precision: 0.95,
//                   completeness: 0.93}}        (accuracy only with a ground truth)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/reconstruction_params.h"
#include "session/camera_state.h"
#include "session/run_record.h"

namespace sonarcarve {

struct Session {
  std::string mission;
  ReconstructionParams params;
  CameraState camera;
  int frame = 0;
  std::string colour_by = "intensity";
  std::vector<RunRecord> runs;
};

/// Writes atomically; throws Error if the file cannot be written.
void saveSession(const Session& session, const std::filesystem::path& file);
/// Throws Error naming the file, line and key on a missing or bad value.
Session loadSession(const std::filesystem::path& file);
/// True if `path` is a file that says it is a session (`format: sonarcarve-session` in its
/// first 4 KB), whatever its name. Never throws.
bool looksLikeSessionFile(const std::filesystem::path& path);

}  // namespace sonarcarve
