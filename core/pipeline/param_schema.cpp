#include "pipeline/param_schema.h"

#include <type_traits>

#include "common/angles.h"
#include "sonar/sonar_ranges.h"

namespace sonarcarve {
namespace {

using Params = ReconstructionParams;

// The ParamType of a field type that a ParamValue holds as it is.
template <typename T>
constexpr ParamType heldType() {
  if constexpr (std::is_same_v<T, double>) {
    return ParamType::Number;
  } else if constexpr (std::is_same_v<T, bool>) {
    return ParamType::Bool;
  } else if constexpr (std::is_same_v<T, std::string>) {
    return ParamType::Path;
  } else {
    static_assert(std::is_same_v<T, OptionalBox>, "no ParamType for this field type");
    return ParamType::Box;
  }
}

// `ref` is a generic lambda returning a reference to the field, so that one lambda serves both
// the const getter and the setter; the field's C++ type decides the entry's ParamType (an enum
// is an Enum, with the names of its enum_names.h table).
template <typename Ref>
ParamAccess field(Ref ref) {
  using T = std::remove_cvref_t<decltype(ref(std::declval<Params&>()))>;
  ParamAccess a;
  if constexpr (std::is_enum_v<T>) {
    a.type = ParamType::Enum;
    a.choices = enumNames<T>();
    a.get = [ref](const Params& p) { return ParamValue(std::string(toString(ref(p)))); };
    a.set = [ref](Params& p, const ParamValue& v) {
      if (const auto value = enumFromString<T>(std::get<std::string>(v))) {
        ref(p) = *value;
      }
    };
  } else if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    a.type = ParamType::Integer;
    a.get = [ref](const Params& p) { return ParamValue(static_cast<long long>(ref(p))); };
    a.set = [ref](Params& p, const ParamValue& v) {
      ref(p) = static_cast<T>(std::get<long long>(v));
    };
  } else {
    a.type = heldType<T>();
    a.get = [ref](const Params& p) { return ParamValue(ref(p)); };
    a.set = [ref](Params& p, const ParamValue& v) { ref(p) = std::get<T>(v); };
  }
  return a;
}

// The detector a run may use: `auto` runs the Z-test with the given model or one it learns
// from the mission's frames (none only on noise-free frames), so what tunes the Z-test tunes it.
DetectorMode detectorRun(const Params& p) {
  return p.detector.mode == DetectorMode::Auto ? DetectorMode::ZTest : p.resolvedDetectorMode();
}
bool usesZTest(const Params& p) {
  return detectorRun(p) == DetectorMode::ZTest;
}
bool usesCfar(const Params& p) {
  return detectorRun(p) == DetectorMode::Cfar;
}
bool usesDetector(const Params& p) {
  return detectorRun(p) != DetectorMode::None;
}
bool usesFastEngine(const Params& p) {
  return p.engine == Engine::Fast;
}
bool refinesPoses(const Params& p) {
  return p.engine == Engine::Fast && p.pose_refinement.enabled;
}
bool fitsMap(const Params& p) {
  return p.engine == Engine::Fast && p.fit.enabled;
}
bool buildsMesh(const Params& p) {
  return p.mesh_enabled;
}
bool meshesOccupancy(const Params& p) {
  return p.mesh_enabled && p.mesh.method == MeshMethod::Occupancy;
}
bool meshesImplicit(const Params& p) {
  return p.mesh_enabled && p.mesh.method == MeshMethod::Implicit;
}

constexpr ParamRange kAny{};
constexpr ParamRange kPositive{.min = 0.0, .min_open = true};
constexpr ParamRange kNonNegative{.min = 0.0};
constexpr ParamRange kAtLeastOne{.min = 1.0};
// Upper ends of entries whose value sets the work or the memory of a run: each is well above
// what any run needs (and above the panel's own bounds), and below what makes a run take
// minutes or gigabytes (docs/reliability.md, "Limits"). Windows along a beam span at most the
// longest beam.
constexpr double kMaxCfarWindow = 16384;          // kMaxRangeBins
constexpr double kMaxMeshSmoothingPasses = 1000;  // 1e8 ran past 60 s and took 2.4 GB
constexpr double kMaxOccupancySigma = 100;        // voxels: the grid's border is 2 sigma
// Physically meaningful ends (sonar/sonar_ranges.h): a map voxel of 10 m holds no structure a
// sonar images; ranges within the farthest a sonar may declare.
constexpr double kMaxVoxelSize_m = 10.0;

// Designated initializers leave the fields they do not name at their defaults on purpose; GCC
// 12 warns about each of them under -Wextra.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
std::vector<ParamSpec> makeSchema() {
  return {
      // Denoising: what the analyst tunes first.
      {.key = "detector.mode",
       .help = "what separates returns from noise before carving: auto (ztest, with the given "
               "noise model or one learned from the mission's own frames; none on noise-free "
               "frames), none, ztest or cfar (needs no noise model)",
       .flag = "--detector",
       .gui = {.group = "Denoising", .label = "Detector"},
       .access = field([](auto& p) -> auto& { return p.detector.mode; })},
      {.key = "detector.z",
       .unit = "σ",
       .help = "Z-test: a pixel is kept where its smoothed value exceeds the noise model's mean "
               "by this many standard deviations",
       .flag = "--z",
       .gui = {.group = "Denoising",
               .label = "Z threshold",
               .min = 0.1,
               .max = 20.0,
               .step = 0.25,
               .suffix = " σ"},
       .access = field([](auto& p) -> auto& { return p.detector.z; }),
       .applies = usesZTest},
      {.key = "detector.cfar_pfa",
       .range = {.min = 0.0, .max = 1.0, .min_open = true, .max_open = true},
       .help = "CFAR: false-alarm probability per cell",
       .flag = "--cfar-pfa",
       .gui = {.group = "Denoising",
               .label = "CFAR Pfa",
               .min = 0.0001,
               .max = 0.5,
               .step = 0.01,
               .decimals = 4},
       .access = field([](auto& p) -> auto& { return p.detector.cfar_pfa; }),
       .applies = usesCfar},
      {.key = "detector.smoothing",
       .unit = "pixels",
       .odd = true,
       .range = {.min = 1.0, .max = kMaxSmoothingWindow},
       .help = "side of the box filter averaged before the test (1 = none); the noise model "
               "must be learned with the same",
       .flag = "--smoothing",
       .gui = {.group = "Denoising", .label = "Smoothing", .min = 1, .max = 15, .step = 2},
       .access = field([](auto& p) -> auto& { return p.detector.smoothing; }),
       .applies = usesDetector},
      {.key = "noise_model",
       .help = "per-pixel empty-water statistics (sonarcarve-cli noise-model) for the ztest; "
               "none: learned from the mission's own frames; in a YAML file, relative to the "
               "file's folder",
       .flag = "--noise-model",
       .gui = {.group = "Denoising",
               .label = "Noise model",
               .min_text = "none: learned from the mission"},
       .access = field([](auto& p) -> auto& { return p.noise_model; })},
      {.key = "detector.cfar_guard",
       .unit = "range bins",
       .range = {.min = 0.0, .max = kMaxCfarWindow},
       .help = "CFAR: cells skipped on each side of the cell under test",
       .flag = "--cfar-guard",
       .gui = {.group = "Denoising", .label = "CFAR guard", .advanced = true, .max = 100},
       .access = field([](auto& p) -> auto& { return p.detector.cfar_guard; }),
       .applies = usesCfar},
      {.key = "detector.cfar_train",
       .unit = "range bins",
       .range = {.min = 1.0, .max = kMaxCfarWindow},
       .help = "CFAR: cells averaged on each side beyond the guard",
       .flag = "--cfar-train",
       .gui =
           {.group = "Denoising", .label = "CFAR training", .advanced = true, .min = 1, .max = 500},
       .access = field([](auto& p) -> auto& { return p.detector.cfar_train; }),
       .applies = usesCfar},
      // Carving.
      {.key = "intensity_threshold",
       .unit = "counts",
       .help = "a pixel at or below this intensity (after the detector) is empty water and "
               "carves its arc",
       .flag = "--threshold",
       .gui = {.group = "Carving",
               .label = "Intensity threshold",
               .max = 65535,
               .step = 10,
               .decimals = 1},
       .access = field([](auto& p) -> auto& { return p.carve.intensity_threshold; })},
      {.key = "beam_aware_carving",
       .help = "fast engine: carve over the beam's whole elevation main lobe, each pixel "
               "weighed by the sinc^2 beam's gain (-3 dB at +-aperture/2); false: the seed "
               "paper's +-aperture/2",
       .flag = "--beam-aware-carving",
       .gui = {.group = "Carving", .label = "Beam-aware carving"},
       .access = field([](auto& p) -> auto& { return p.carve.beam_aware; }),
       .applies = usesFastEngine},
      {.key = "dynamic_range_db",
       .unit = "dB",
       .range = kPositive,
       .help = "beam-aware carving: a voxel is kept only while every view allows it a return "
               "on the beam's axis within this far below the mission's bright returns",
       .flag = "--dynamic-range",
       .gui = {.group = "Carving",
               .label = "Dynamic range",
               .advanced = true,
               .min = 1,
               .max = 80,
               .step = 1,
               .decimals = 1,
               .suffix = " dB"},
       .access = field([](auto& p) -> auto& { return p.carve.dynamic_range_db; }),
       .applies = usesFastEngine},
      {.key = "carve_votes",
       .unit = "views",
       .range = {.min = 1.0, .max = 255.0},
       .help = "fast engine: a voxel is carved once this many views have found it empty; 1 "
               "is the seed paper's rule, more tolerate views a little off their navigation",
       .flag = "--carve-votes",
       .gui = {.group = "Carving", .label = "Carve votes", .advanced = true, .min = 1, .max = 255},
       .access = field([](auto& p) -> auto& { return p.carve.carve_votes; }),
       .applies = usesFastEngine},
      {.key = "shadow_aware_carving",
       .help = "fast engine: a frame carves a voxel only where no surface it may see lies "
               "nearer on the voxel's ray, so a structure's acoustic shadow does not carve "
               "what other views see; auto: on where the views' headings span over 20 "
               "degrees (orbits, several passes, lawnmowers); false: the seed paper's rule",
       .flag = "--shadow-aware-carving",
       .gui = {.group = "Carving", .label = "Shadow-aware carving", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.shadow_aware_carving; }),
       .applies = usesFastEngine},
      {.key = "heading_sectors",
       .help = "fast engine: where the views come from several headings around a structure "
               "(a track within 1.5 times the sonar's range), each 60-degree sector of headings "
               "is also carved alone, and the surface it keeps where it swept its elevation "
               "beam over it, which views from other headings carved at grazing incidence, is "
               "set back; false: one carve of every view",
       .flag = "--heading-sectors",
       .gui = {.group = "Carving", .label = "Heading sectors", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.heading_sectors; }),
       .applies = usesFastEngine},
      {.key = "seabed_aware_carving",
       .help = "fast engine, beam-aware: each frame fits the seabed it images and carves the "
               "water over it by what the seabed leaves of each pixel; false: the water "
               "within about a quarter of the sonar's height over a flat seabed is never "
               "carved",
       .flag = "--seabed-aware-carving",
       .gui = {.group = "Carving", .label = "Seabed-aware carving", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.carve.seabed_aware; }),
       .applies = usesFastEngine},
      {.key = "fit_seabed_relief",
       .help = "fast engine, seabed-aware: before carving, the seabed the frames image is fitted "
               "as a heightfield over the mission (every 0.2 m), and each frame's seabed is "
               "explained by its relief instead of one plane a frame (experimental: it gains "
               "over relief and loses over a flat seabed with objects); false: a plane a frame",
       .flag = "--fit-seabed-relief",
       .gui = {.group = "Carving", .label = "Seabed relief", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.seabed_relief; }),
       .applies = usesFastEngine},
      {.key = "voxel_size_m",
       .unit = "m",
       .range = {.min = 0.0, .max = kMaxVoxelSize_m, .min_open = true},
       .help = "edge of a map voxel; also the mesh's sampling",
       .flag = "--voxel-size",
       .gui = {.group = "Carving",
               .label = "Voxel size",
               .min = 0.5,
               .max = 50,
               .step = 0.5,
               .decimals = 1,
               .factor = 100,
               .suffix = " cm"},
       .access = field([](auto& p) -> auto& { return p.carve.voxel_size_m; })},
      {.key = "elevation_step_deg",
       .unit = "degrees",
       .degrees = true,
       .range = {.min = 0.01, .max = 90.0},
       .help = "step along each pixel's elevation arc (reference engine) and in occlusion "
               "resolution",
       .flag = "--elevation-step",
       .gui = {.group = "Carving",
               .label = "Elevation step",
               .min = 0.01,
               .max = 5,
               .step = 0.05,
               .suffix = "°"},
       .access = field([](auto& p) -> auto& { return p.carve.elevation_step_rad; })},
      {.key = "vertical_aperture_deg",
       .unit = "degrees",
       .degrees = true,
       .range = {.min = kVerticalAperture.min,
                 .max = kVerticalAperture.max,
                 .max_open = true,
                 .or_zero = true},
       .help = "vertical aperture used for carving; 0 = the sonar's own",
       .flag = "--vertical-aperture",
       .gui = {.group = "Carving",
               .label = "Vertical aperture",
               .max = 90,
               .decimals = 1,
               .suffix = "°",
               .min_text = "sonar's own"},
       .access = field([](auto& p) -> auto& { return p.vertical_aperture_rad; })},
      {.key = "horizontal_beam_width_deg",
       .unit = "degrees",
       .degrees = true,
       .range = {.min = kHorizontalBeamWidth.min, .max = 30.0, .or_zero = true},
       .help = "each beam's -3 dB width in bearing, whose blur is taken out of the frames when "
               "wider than the beams' spacing; 0 = the sonar's own (none if it gives none)",
       .flag = "--horizontal-beam-width",
       .gui = {.group = "Carving",
               .label = "Beam width",
               .max = 30,
               .decimals = 2,
               .suffix = "°",
               .min_text = "sonar's own"},
       .access = field([](auto& p) -> auto& { return p.horizontal_beam_width_rad; })},
      {.key = "range_min_m",
       .unit = "m",
       .range = {.min = 0.0, .max = kMaxFarRange_m},
       .help = "nearest range used; 0 = the sonar's own",
       .flag = "--range-min",
       .gui = {.group = "Carving", .label = "Range min", .max = 500, .step = 0.1, .suffix = " m"},
       .access = field([](auto& p) -> auto& { return p.carve.range_min_m; })},
      {.key = "range_max_m",
       .unit = "m",
       .range = {.min = 0.0, .max = kMaxFarRange_m},
       .help = "farthest range used, above range_min_m; 0 = the sonar's own",
       .flag = "--range-max",
       .gui = {.group = "Carving",
               .label = "Range max",
               .max = 500,
               .step = 0.5,
               .suffix = " m",
               .min_text = "sonar's own"},
       .access = field([](auto& p) -> auto& { return p.carve.range_max_m; })},
      {.key = "engine",
       .help = "fast: voxel-centric, multi-threaded; reference: the seed paper's arcs in an "
               "OctoMap, about 3 s a frame (use a region)",
       .flag = "--engine",
       .gui = {.group = "Carving", .label = "Engine", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.engine; })},
      {.key = "region",
       .unit = "m",
       .help = "only this box of the world (NED) is mapped; unset: everything the frames see",
       .flag = "--region",
       .gui = {.group = "Carving",
               .label = "Region",
               .advanced = true,
               .min_text = "everything the frames see (N0 E0 D0 N1 E1 D1)"},
       .access = field([](auto& p) -> auto& { return p.carve.region; })},
      {.key = "occlusion_aware_carving",
       .help = "experimental, fast engine: carve a second time, each frame updating only the "
               "voxels it can see past the first carving's surfaces",
       .flag = "--occlusion-aware-carving",
       .gui = {.group = "Carving", .label = "Occlusion-aware carving", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.occlusion_aware_carving; }),
       .applies = usesFastEngine},
      {.key = "memory_budget_mb",
       .unit = "MB",
       .range = kNonNegative,
       .help = "memory the run may hold, in MB of 2^20 bytes: past it the run stops between "
               "frames with an error naming the figures (after letting finished blocks go, "
               "evict_blocks); 0 = 80 % of the memory available when the run starts",
       .flag = "--memory-budget",
       .gui = {.group = "Carving",
               .label = "Memory budget",
               .advanced = true,
               .max = 1048576,
               .step = 256,
               .suffix = " MB",
               .min_text = "80 % of the available"},
       .access = field([](auto& p) -> auto& { return p.memory_budget_mb; })},
      {.key = "evict_blocks",
       .help = "fast engine: let finished regions of the map go once their surface is resolved "
               "(the same outputs, memory bounded by the area in view); runs that need the "
               "whole map keep it (map viewer, --save-map, --load-map, occlusion-aware "
               "carving, pose refinement)",
       .flag = "--evict-blocks",
       .gui = {.group = "Carving", .label = "Let finished blocks go", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.evict_blocks; }),
       .applies = usesFastEngine},
      {.key = "set_aside_after_frames",
       .unit = "frames",
       .range = kNonNegative,
       .help = "with evict_blocks: map pages no frame reaches for more than this many frames "
               "(a lawnmower's next line) wait in a temporary file, held again as they were "
               "before a frame comes back (the same outputs, memory flat along the survey); "
               "0 = kept in memory",
       .flag = "--set-aside-after",
       .gui = {.group = "Carving",
               .label = "Set pages aside after",
               .advanced = true,
               .max = 1000000,
               .suffix = " frames",
               .min_text = "never"},
       .access = field([](auto& p) -> auto& { return p.set_aside_after_frames; }),
       .applies = usesFastEngine},

      // Navigation.
      {.key = "pose_refinement.enabled",
       .help = "fast engine: carve the mission, align every frame to that map within a window "
               "around its navigation, solve the track, carve again (drifting navigation); "
               "false: carve at the navigation's poses",
       .flag = "--pose-refinement",
       .gui = {.group = "Navigation", .label = "Pose refinement"},
       .access = field([](auto& p) -> auto& { return p.pose_refinement.enabled; }),
       .applies = usesFastEngine},
      {.key = "pose_refinement.max_translation_m",
       .unit = "m",
       .range = kNonNegative,
       .help = "pose refinement: the farthest a frame is moved from its navigation, on each axis",
       .flag = "--refine-max-translation",
       .gui = {.group = "Navigation",
               .label = "Largest shift",
               .advanced = true,
               .max = 500,
               .step = 1,
               .decimals = 1,
               .factor = 100,
               .suffix = " cm"},
       .access = field([](auto& p) -> auto& { return p.pose_refinement.max_translation_m; }),
       .applies = refinesPoses},
      {.key = "pose_refinement.max_rotation_deg",
       .unit = "degrees",
       .degrees = true,
       .range = {.min = 0.0, .max = 90.0},
       .help = "pose refinement: the farthest a frame is turned from its navigation, about each "
               "axis",
       .flag = "--refine-max-rotation",
       .gui = {.group = "Navigation",
               .label = "Largest turn",
               .advanced = true,
               .max = 90,
               .step = 0.5,
               .suffix = "°"},
       .access = field([](auto& p) -> auto& { return p.pose_refinement.max_rotation_rad; }),
       .applies = refinesPoses},
      {.key = "pose_refinement.first_pass_tolerance_m",
       .unit = "m",
       .range = kNonNegative,
       .help = "pose refinement: the first alignment map is carved from frames whose returns are "
               "widened by this much in range and across beams, so that true surface survives "
               "views this far off each other",
       .flag = "--refine-tolerance",
       .gui = {.group = "Navigation",
               .label = "First-pass tolerance",
               .advanced = true,
               .max = 50,
               .step = 1,
               .decimals = 1,
               .factor = 100,
               .suffix = " cm"},
       .access = field([](auto& p) -> auto& { return p.pose_refinement.first_pass_tolerance_m; }),
       .applies = refinesPoses},
      {.key = "pose_refinement.passes",
       .unit = "passes",
       .range = {.min = 1.0, .max = 8.0},
       .help = "pose refinement: how often the mission is carved, every frame aligned to that map "
               "and the track solved, before the final carving (each pass halves the tolerance)",
       .flag = "--refine-passes",
       .gui = {.group = "Navigation",
               .label = "Alignment passes",
               .advanced = true,
               .min = 1,
               .max = 8},
       .access = field([](auto& p) -> auto& { return p.pose_refinement.passes; }),
       .applies = refinesPoses},

      // Model-based fit.
      {.key = "fit.enabled",
       .help = "experimental, fast engine: after carving, fit the carved band's occupancy and "
               "reflectance to every frame by the speckle likelihood of the forward model, and "
               "take the surface from the fitted map (slower; docs/model.md)",
       .flag = "--fit",
       .gui = {.group = "Fit", .label = "Fit the map to the frames"},
       .access = field([](auto& p) -> auto& { return p.fit.enabled; }),
       .applies = usesFastEngine},
      {.key = "fit.passes",
       .unit = "passes",
       .range = {.min = 1.0, .max = 50.0},
       .help = "fit: passes over every frame",
       .flag = "--fit-passes",
       .gui = {.group = "Fit", .label = "Passes", .advanced = true, .min = 1, .max = 50},
       .access = field([](auto& p) -> auto& { return p.fit.passes; }),
       .applies = fitsMap},
      {.key = "fit.band_voxels",
       .unit = "voxels",
       .range = {.min = 1.0, .max = 16.0},
       .help = "fit: half-thickness of the band around the carved surface that the fit may "
               "change",
       .flag = "--fit-band",
       .gui = {.group = "Fit", .label = "Band", .advanced = true, .min = 1, .max = 16},
       .access = field([](auto& p) -> auto& { return p.fit.band_voxels; }),
       .applies = fitsMap},
      {.key = "fit.beam",
       .help = "fit: also fit the elevation beam profile from the frames, starting from the "
               "declared one (which then only holds where no frame says otherwise)",
       .flag = "--fit-beam",
       .gui = {.group = "Fit", .label = "Fit the elevation beam", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.fit.beam; }),
       .applies = fitsMap},
      {.key = "fit.background",
       .help = "fit: also fit the background per range bin from the frames, starting from the "
               "noise model's mean",
       .flag = "--fit-background",
       .gui = {.group = "Fit", .label = "Fit the background", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.fit.background; }),
       .applies = fitsMap},

      // Frames.
      {.key = "frames.first",
       .unit = "index",
       .range = kNonNegative,
       .help = "the first frame used",
       .flag = "--first-frame",
       .gui = {.group = "Frames", .label = "First", .max = 10000000},
       .access = field([](auto& p) -> auto& { return p.first_frame; })},
      {.key = "frames.last",
       .unit = "index",
       .range = {.min = -1.0},
       .help = "one past the last frame used; -1 = to the end",
       .flag = "--last-frame",
       .gui = {.group = "Frames",
               .label = "Last (exclusive)",
               .min = -1,
               .max = 10000000,
               .min_text = "end"},
       .access = field([](auto& p) -> auto& { return p.last_frame; })},
      {.key = "frames.stride",
       .unit = "frames",
       .range = kAtLeastOne,
       .help = "use every n-th frame",
       .flag = "--stride",
       .gui = {.group = "Frames", .label = "Stride", .min = 1, .max = 1000},
       .access = field([](auto& p) -> auto& { return p.stride; })},

      // Surface points and mesh.
      {.key = "min_views",
       .unit = "views",
       .range = kAtLeastOne,
       .help = "a surface voxel must be the first return along a beam in at least this many "
               "views",
       .flag = "--min-views",
       .gui = {.group = "Surface", .label = "Min views", .min = 1, .max = 1000},
       .access = field([](auto& p) -> auto& { return p.min_views; })},
      {.key = "mesh.enabled",
       .help = "build a surface mesh from the surface points",
       .flag = "--mesh",
       .gui = {.group = "Surface", .label = "Build a mesh"},
       .access = field([](auto& p) -> auto& { return p.mesh_enabled; })},
      {.key = "mesh.method",
       .help = "occupancy: the points' voxels smoothed and contoured; implicit: signed distance "
               "to the points' tangent planes (minutes on the riser)",
       .flag = "--mesh-method",
       .gui = {.group = "Mesh", .label = "Method", .advanced = true},
       .access = field([](auto& p) -> auto& { return p.mesh.method; }),
       .applies = buildsMesh},
      {.key = "mesh.occupancy_sigma_voxels",
       .unit = "voxels",
       .range = {.min = 0.0, .max = kMaxOccupancySigma, .min_open = true},
       .help = "occupancy: Gaussian smoothing of the voxels",
       .flag = "--mesh-occupancy-sigma",
       .gui = {.group = "Mesh",
               .label = "Occupancy sigma",
               .advanced = true,
               .min = 0.05,
               .max = 10,
               .step = 0.1},
       .access = field([](auto& p) -> auto& { return p.mesh.occupancy_sigma_voxels; }),
       .applies = meshesOccupancy},
      {.key = "mesh.occupancy_iso",
       .range = kPositive,
       .help = "occupancy: contour level of the smoothed field",
       .flag = "--mesh-occupancy-iso",
       .gui = {.group = "Mesh",
               .label = "Occupancy iso",
               .advanced = true,
               .min = 0.01,
               .max = 1,
               .step = 0.05},
       .access = field([](auto& p) -> auto& { return p.mesh.occupancy_iso; }),
       .applies = meshesOccupancy},
      {.key = "mesh.max_distance_voxels",
       .unit = "voxels",
       .range = kPositive,
       .help = "implicit: triangles farther than this from every point are removed",
       .flag = "--mesh-max-distance",
       .gui = {.group = "Mesh",
               .label = "Max distance",
               .advanced = true,
               .min = 0.1,
               .max = 50,
               .step = 0.5},
       .access = field([](auto& p) -> auto& { return p.mesh.max_distance_voxels; }),
       .applies = meshesImplicit},
      {.key = "mesh.smoothing_iterations",
       .range = {.min = 0.0, .max = kMaxMeshSmoothingPasses},
       .help = "windowed-sinc smoothing passes; 0 = none",
       .flag = "--mesh-smoothing",
       .gui = {.group = "Mesh", .label = "Smoothing passes", .advanced = true, .max = 500},
       .access = field([](auto& p) -> auto& { return p.mesh.smoothing_iterations; }),
       .applies = buildsMesh},
      {.key = "mesh.smoothing_passband",
       .range = {.min = 0.0, .max = 2.0, .min_open = true},
       .help = "windowed-sinc pass band: lower smooths more",
       .flag = "--mesh-passband",
       .gui = {.group = "Mesh",
               .label = "Smoothing pass band",
               .advanced = true,
               .min = 0.001,
               .max = 2,
               .step = 0.01,
               .decimals = 3},
       .access = field([](auto& p) -> auto& { return p.mesh.smoothing_passband; }),
       .applies = buildsMesh},
      {.key = "mesh.decimate",
       .range = {.min = 0.0, .max = 0.95},
       .help = "fraction of the triangles removed",
       .flag = "--mesh-decimate",
       .gui = {.group = "Mesh", .label = "Decimate", .advanced = true, .max = 0.95, .step = 0.05},
       .access = field([](auto& p) -> auto& { return p.mesh.decimate; }),
       .applies = buildsMesh},
      {.key = "mesh.min_fragment_triangles",
       .unit = "triangles",
       .range = kAtLeastOne,
       .help = "connected pieces with fewer triangles are removed",
       .flag = "--mesh-min-fragment",
       .gui =
           {.group = "Mesh", .label = "Min fragment", .advanced = true, .min = 1, .max = 1000000},
       .access = field([](auto& p) -> auto& { return p.mesh.min_fragment_triangles; }),
       .applies = buildsMesh},
  };
}
#pragma GCC diagnostic pop

}  // namespace

double ParamSpec::toShown(double value) const {
  return degrees ? radToDeg(value) : value;
}

double ParamSpec::fromShown(double shown) const {
  return degrees ? degToRad(shown) : shown;
}

const std::vector<ParamSpec>& paramSchema() {
  static const std::vector<ParamSpec> schema = makeSchema();
  return schema;
}

const ParamSpec* findParam(std::string_view key) {
  for (const ParamSpec& spec : paramSchema()) {
    if (spec.key == key) {
      return &spec;
    }
  }
  return nullptr;
}

}  // namespace sonarcarve
