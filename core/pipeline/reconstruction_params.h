// ReconstructionParams: everything that decides a reconstruction, as one plain struct with
// the seed paper's defaults, saved to and loaded from YAML so that a GUI session and a CLI run
// with the same file give the same map. The YAML keys, their units (degrees at the file
// boundary), ranges and help are in the parameter schema (param_schema.h), which the reader,
// the writer, the CLI flags, the workbench's panel and the docs all follow.
#pragma once

#include <cstdint>
#include <string>

#include "carve/carve_params.h"
#include "carve/carver.h"
#include "carve/pose_refiner.h"
#include "common/enum_names.h"
#include "denoise/detector.h"
#include "fit/map_fit_params.h"
#include "mesh/surface_mesher.h"

namespace YAML {
class Node;
}

namespace sonarcarve {

/// fast: voxel-centric and multi-threaded; reference: the seed paper's arcs in an OctoMap.
/// The carving engine (carve/carver.h); YAML and the command line name the built-in ones.
using Engine = CarverEngine;
inline constexpr std::array<EnumName<Engine>, 2> kEngineNames{{
    {Engine::Fast, "fast"},
    {Engine::Reference, "reference"},
}};
constexpr const auto& enumNamesOf(Engine) {
  return kEngineNames;
}

/// Shadow-aware carving (CarveParams::shadow_aware): on, off, or `auto`, on for missions
/// that view the scene from several sides (pipeline/shadow_carving.h).
enum class ShadowCarving { Auto, On, Off };
inline constexpr std::array<EnumName<ShadowCarving>, 3> kShadowCarvingNames{{
    {ShadowCarving::Auto, "auto"},
    {ShadowCarving::On, "true"},
    {ShadowCarving::Off, "false"},
}};
constexpr const auto& enumNamesOf(ShadowCarving) {
  return kShadowCarvingNames;
}

struct ReconstructionParams {
  Engine engine = Engine::Fast;
  CarveParams carve;
  DetectorParams detector;
  /// Surface mesh from the surface points (voxel_size_m follows carve.voxel_size_m).
  bool mesh_enabled = true;
  MeshParams mesh;
  /// Noise model file for the ztest detector ("" = none).
  std::string noise_model;
  std::size_t first_frame = 0;
  long last_frame = -1;  ///< exclusive; -1 means to the end
  std::size_t stride = 1;
  std::uint32_t min_views = kDefaultMinViews;
  /// Vertical aperture used for carving, radians; 0 = the sonar model's own. Analysts
  /// narrow it when the data sheet's -3 dB aperture overstates what returns energy.
  double vertical_aperture_rad = 0.0;
  /// Width of each beam in bearing (-3 dB), radians; 0 = the sonar model's own. For logs that
  /// do not say how wide their beams are (sonar/bearing_deblur.h).
  double horizontal_beam_width_rad = 0.0;
  /// Fast engine, experimental: carve a second time, letting each frame update only the
  /// voxels it can see (not hidden behind the first carving's surface), so that surfaces
  /// shadowed from some views are not carved away by them. On the riser demo it gained 0.7 %
  /// completeness for 2.7 times the carving time: off by default.
  bool occlusion_aware_carving = false;
  /// Fast engine: whether frames carve shadow-aware (sets carve.shadow_aware for the run).
  ShadowCarving shadow_aware_carving = ShadowCarving::Auto;
  /// Fast engine: a mission that views a structure from several headings has each heading
  /// carved alone too, and what each keeps that the others carved at grazing incidence set
  /// back (pipeline/sector_restore.h).
  bool heading_sectors = true;
  /// Fast engine, seabed-aware: the seabed's relief fitted over the mission before carving,
  /// which explains each frame's seabed in place of its plane (carve/seabed_field_fit.h).
  /// Off by default: on a flat seabed with objects it cost F (docs/reconstruction.md).
  bool seabed_relief = false;
  /// Fast engine: each frame aligned to the map carved so far before it carves (issue 15).
  PoseRefinementParams pose_refinement;
  /// Fast engine, experimental: the carved map fitted to the frames (fit/map_fit.h).
  MapFitParams fit;
  /// What the run may hold in memory, MiB (2^20 bytes); 0 = a share of the memory available
  /// when the run starts (pipeline/memory_budget.h). Past it the run stops with an Error.
  std::uint64_t memory_budget_mb = 0;
  /// Fast engine: let the map's finished regions go as the run passes them (their surface
  /// points resolved first; docs/scaling.md), so that memory follows the area in view, not
  /// the mission's. The outputs are the same; runs that need the whole map keep it (a map
  /// viewer, --save-map, --load-map, occlusion-aware carving, pose refinement).
  bool evict_blocks = true;
  /// An evicting run sets its map's pages aside in a temporary file while no frame touches
  /// them for more than this many frames, and holds them again before one does (a lawnmower's
  /// next line; docs/scaling.md): 10 s at 10 Hz, long against a page's own frames (a view
  /// spans 10 m: 200 frames at 5 cm), short against a line. 0: never. The outputs are the
  /// same either way.
  std::int32_t set_aside_after_frames = 100;

  /// A surface voxel must be the first return in this many views: ghosts of the elevation
  /// ambiguity are first returns in fewer views than a real surface, seen from every view
  /// whose aperture covers it (about 15 for the paper's 10 cm steps at 4.5 m).
  static constexpr std::uint32_t kDefaultMinViews = 5;

  /// The detector that runs: `auto` made concrete by whether a noise model is given.
  DetectorMode resolvedDetectorMode() const { return detector.resolved(!noise_model.empty()).mode; }

  /// Throws Error naming the file, line and key on a bad value; absent keys keep defaults.
  static ReconstructionParams fromYamlFile(const std::string& path);
  /// The same from YAML text embedded in another file (a GUI session); `source` names that
  /// file in errors and anchors a relative noise model path.
  static ReconstructionParams fromYamlText(const std::string& text, const std::string& source);
  /// The same from a node of a document already parsed, so that errors give its lines.
  static ReconstructionParams fromYamlNode(const YAML::Node& node, const std::string& source);
  std::string toYaml() const;
  /// Throws Error naming the key if a value is out of range (the schema's ranges) or two
  /// values contradict each other.
  void validate() const;
};

}  // namespace sonarcarve
