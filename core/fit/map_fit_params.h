// MapFitParams: the settings of the model-based fit of the carved map to the frames
// (fit/map_fit.h, docs/model.md "The fit").
#pragma once

namespace sonarcarve {

struct MapFitParams {
  /// Whether the fit runs after carving (off: the carved surface is the run's output).
  bool enabled = false;
  /// Passes over every frame; each pass takes a step every `frames_per_step` frames.
  int passes = 3;
  int frames_per_step = 4;
  /// Half-thickness, in voxels, of the band around the carved surface that the fit may change.
  int band_voxels = 3;
  /// Elevation step of the fit's rays, radians (coarser than the simulator's: the fit needs
  /// the surface's range, not the fine structure of the beam).
  double elevation_step_rad = 0.4 * 3.14159265358979323846 / 180.0;
  /// Ray samples per range bin (one: the bins are as fine as the voxels).
  int samples_per_bin = 1;
  /// Whether the fit also takes the elevation beam profile and the background per range bin
  /// from the frames (fit/beam_background_fit.h), starting from the declared ones.
  bool beam = true;
  bool background = true;
};

}  // namespace sonarcarve
