// runSimulation: the simulator end to end. Renders every frame of a trajectory over a scene,
// adds noise, and writes a mission folder (format v1) with the navigation a vehicle would
// record, plus ground truth:
//   ground_truth.ply          the scene mesh in the world frame
//   ground_truth_poses.csv    the true vehicle poses (navigation CSV format)
//   visible_points.ply        the surface points the sonar saw (1 cm cells)
//   simulation.yaml           scene, trajectory, imaging, noise and navigation-error settings
// Over a seabed field (`field` given, sim/seabed_field.h, in place of the request's scene) only the
// tiles near the sonar are traced (sim/frame_renderer.h) and the ground truth is the field's tiles
// under the track. Cancelling through Progress stops between frames and still writes a valid,
// shorter mission.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "common/progress.h"
#include "common/thread_pool.h"
#include "geometry/scene.h"
#include "sim/noise.h"
#include "sim/scene_seabed.h"
#include "sim/seabed_field.h"
#include "sim/sonar_simulator.h"
#include "sim/trajectory.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

struct SimulationRequest {
  Scene scene;
  std::string scene_source;  ///< demo name or mesh path, recorded in simulation.yaml
  SonarModel sonar;
  TrajectorySpec trajectory;
  ImagingSettings imaging;
  NoiseSpec noise;
  NavErrorSpec nav_error;
  bool empty_water = false;       ///< frames of empty water (no scene returns): noise only
  std::optional<int> max_frames;  ///< stop after this many frames
  std::filesystem::path output;
  /// The elevation beam mission.yaml declares, which may differ from the simulated one
  /// (ImagingSettings::elevation_beam); not given: clipped for the clipped beam, else the
  /// sonar's own (a real beam).
  std::optional<ElevationBeam> declared_beam = std::nullopt;
};

struct SimulationResult {
  std::size_t frames_written = 0;
  std::size_t visible_points = 0;
  std::size_t most_triangles_traced = 0;  ///< the most scene triangles held at once
  std::size_t ground_truth_triangles = 0;
  bool cancelled = false;
};

/// The seed paper's sonar: 2 cm range bins to 10 m, 130 degrees in 650 beams, 20 degrees.
SonarModel paperSonar(const std::string& id = "sim-sonar");

/// Renders each frame in parallel on `pool`, and noises, encodes and writes it on a thread of
/// its own while the next one renders. With `field`, surveys that seabed field instead of the
/// request's scene (whose name and target are then unused). `relief`: the one the scene's
/// seabed was built with (sim/scene_seabed.h), recorded in simulation.yaml.
SimulationResult runSimulation(const SimulationRequest& request, Progress& progress,
                               ThreadPool& pool,
                               const std::optional<SeabedFieldSpec>& field = std::nullopt,
                               const SeabedReliefSpec& relief = {});

}  // namespace sonarcarve
