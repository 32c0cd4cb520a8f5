// ReconstructionParams: everything that decides a reconstruction, as one plain struct with
// the seed paper's defaults, saved to and loaded from YAML so that a GUI session and a CLI run
// with the same file give the same map. YAML keys (degrees at the file boundary):
//   engine: fast | reference
//   voxel_size_m, intensity_threshold, elevation_step_deg, range_min_m, range_max_m
//   region: {min_m: [n, e, d], max_m: [n, e, d]}     (optional)
//   frames: {first: 0, last: -1, stride: 1}          (last -1 = to the end)
//   min_views, occlusion_aware_carving, vertical_aperture_deg (0 = the sonar's own)
//   detector: {mode: none|ztest|cfar|probability, z, cfar_guard, cfar_train, cfar_pfa,
//              arc_prior, carve_log_odds, smoothing}
//   noise_model: PATH                                (relative to the YAML file's folder)
//   mesh: {enabled, method: implicit|occupancy, smoothing_iterations, decimate,
//          min_fragment_triangles}
#pragma once

#include <cstdint>
#include <string>

#include "carve/carve_params.h"
#include "denoise/detector.h"
#include "mesh/surface_mesher.h"

namespace sonarcarve {

struct ReconstructionParams {
  std::string engine = "fast";
  CarveParams carve;
  DetectorParams detector;
  /// Surface mesh from the surface points (voxel_size_m follows carve.voxel_size_m).
  bool mesh_enabled = true;
  MeshParams mesh;
  /// Noise model file for the ztest and probability detectors ("" = none).
  std::string noise_model;
  std::size_t first_frame = 0;
  long last_frame = -1;  ///< exclusive; -1 means to the end
  std::size_t stride = 1;
  std::uint32_t min_views = kDefaultMinViews;
  /// Vertical aperture used for carving, radians; 0 = the sonar model's own. Analysts
  /// narrow it when the data sheet's -3 dB aperture overstates what returns energy.
  double vertical_aperture_rad = 0.0;
  /// Fast engine, experimental: carve a second time, letting each frame update only the
  /// voxels it can see (not hidden behind the first carving's surface), so that surfaces
  /// shadowed from some views are not carved away by them. On the riser demo it gained 0.7 %
  /// completeness for 2.7 times the carving time: off by default.
  bool occlusion_aware_carving = false;

  /// A surface voxel must be the first return in this many views: ghosts of the elevation
  /// ambiguity are first returns in fewer views than a real surface, seen from every view
  /// whose aperture covers it (about 15 for the paper's 10 cm steps at 4.5 m).
  static constexpr std::uint32_t kDefaultMinViews = 5;

  /// Throws Error naming the file, line and key on a bad value; absent keys keep defaults.
  static ReconstructionParams fromYamlFile(const std::string& path);
  /// The same from YAML text embedded in another file (a GUI session); `source` names that
  /// file in errors and anchors a relative noise model path.
  static ReconstructionParams fromYamlText(const std::string& text, const std::string& source);
  std::string toYaml() const;
  /// Throws Error if a value is out of range.
  void validate() const;
};

}  // namespace sonarcarve
