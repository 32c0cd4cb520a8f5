// `sonarcarve-cli simulate`: a simulated mission with ground truth.
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli/commands.h"
#include "cli/nav_error_flags.h"
#include "cli/output_folder_run.h"
#include "cli/terminal_progress.h"
#include "common/angles.h"
#include "common/error.h"
#include "common/input_limits.h"
#include "geometry/scene_io.h"
#include "io/files/output_folder.h"
#include "io/mission/mission.h"
#include "io/mission/staged_mission.h"
#include "io/rosbag/bag_writer.h"
#include "io/run/staged_outputs.h"
#include "sim/demo_scenes.h"
#include "sim/simulation_run.h"

namespace sonarcarve::cli {
namespace {

struct SimulateOptions {
  std::string scene;
  std::string trajectory = "auto";
  std::string noise = "default";
  std::string out;
  double standoff_m = 4.5;
  double step_m = 0.1;
  TrajectorySpec survey;           // speed, lawnmower, orbit and descents settings, frames
  double tilt_deg = std::nan("");  // given: the sonar's pitch for any trajectory
  std::uint64_t field_seed = 1;
  SeabedReliefSpec relief;  // under a structure scene; its seed is field_seed
  int max_frames = -1;
  std::uint64_t seed = 1;
  NavErrorSpec nav_error;
  double elevation_step_deg = 0.1;
  int rays_per_beam = 2;
  std::string beam = "realistic";
  std::string elevation_beam = "sinc2";
  std::string declared_beam;  // empty: what the chosen --beam declares
  double horizontal_beam_width_deg = 0.0;
  double spreading_exponent = 0.0;
  double tvg_exponent = 0.0;
  std::string intensity = "linear";
  double visible_cell_m = 0.01;
  float reflectivity = 0.8f;
  bool empty_water = false;
  bool force = false;
  std::string format = "folder";
};

NavErrorSpec navErrorWithSeed(NavErrorSpec spec, std::uint64_t seed) {
  spec.seed = seed;
  return spec;
}

SeabedFieldSpec fieldWithSeed(std::uint64_t seed) {
  SeabedFieldSpec spec;
  spec.seed = seed;
  return spec;
}

NoiseSpec noiseFrom(const std::string& choice, std::uint64_t seed) {
  NoiseSpec spec;
  if (choice == "none") {
    spec = NoiseSpec::none();
  } else if (choice == "coherent") {
    spec = NoiseSpec::coherent();
  } else if (choice != "default") {
    spec = NoiseSpec::fromYamlFile(choice);
  }
  spec.seed = seed;
  return spec;
}

// --declared-beam: sinc, clipped, or not given (empty).
std::optional<ElevationBeam> declaredBeam(const std::string& name) {
  if (name.empty()) {
    return std::nullopt;
  }
  return name == "clipped" ? ElevationBeam::Clipped : ElevationBeam::MainLobe;
}

// The rays of one frame, checked before the simulator allocates or traces them.
void requireBoundedRays(const SimulateOptions& o, const SonarModel& sonar) {
  const double elevation_steps =
      std::ceil(sonar.verticalAperture() / degToRad(o.elevation_step_deg));
  const double rays = elevation_steps * o.rays_per_beam * sonar.cols();
  if (rays > kMaxSimRaysPerFrame) {
    std::ostringstream text;
    text << sonar.cols() << " beams x " << o.rays_per_beam << " rays per beam x " << elevation_steps
         << " elevation steps of " << o.elevation_step_deg << " degrees make " << rays
         << " rays per frame: expected at most " << kMaxSimRaysPerFrame
         << "; use a larger --elevation-step or fewer --rays-per-beam";
    throw Error("--rays-per-beam", "", text.str());
  }
}

// The simulated sonar: the paper's geometry, its frames stored in power or, as an ARIS stores
// them, in bytes of 80/255 dB.
SonarModel simulatedSonar(const SimulateOptions& o) {
  return o.intensity == "decibel"
             ? paperSonar().withIntensityScale(IntensityScale::decibel(80.0, 255.0))
             : paperSonar();
}

// What a simulation may write into its folder: the files of an earlier one that a new run
// does not rewrite are removed, so that the folder holds one mission.
const std::vector<std::string>& simulatedMissionFiles() {
  static const std::vector<std::string> files = {kMissionFileName,   "frames",
                                                 "frames.csv",       "nav.csv",
                                                 "ground_truth.ply", "visible_points.ply",
                                                 "simulation.yaml",  "ground_truth_poses.csv",
                                                 "mission.mcap",     "mission.db3"};
  return files;
}

std::string bagFileName(const std::string& format) {
  return format == "db3" ? "mission.db3" : "mission.mcap";
}

// The mission in `folder` as a ROS 2 bag beside its files (ground truth and all).
BagWriteReport writeMissionBag(const std::string& format, const std::filesystem::path& folder) {
  BagWriteOptions bag;
  bag.format = enumFromString<BagFormat>(format).value_or(BagFormat::Mcap);
  return writeRosBag(readMission(folder), folder / bagFileName(format), bag);
}

int runSimulate(const SimulateOptions& o, ThreadPool& pool) {
  const std::filesystem::path out(o.out);
  requireOutputFolder(out);
  requireBoundedRays(o, paperSonar());
  if (std::filesystem::exists(out / "mission.yaml") && !o.force) {
    throw Error(out.string(), "", "already holds a mission; choose another --out or add --force");
  }
  TrajectorySpec trajectory = o.survey;
  trajectory.kind = o.trajectory == "auto" ? usualTrajectory(o.scene) : o.trajectory;
  trajectory.standoff_m = o.standoff_m;
  trajectory.step_m = o.step_m;
  if (!std::isnan(o.tilt_deg)) {
    trajectory.tilt_deg = o.tilt_deg;
    trajectory.view_tilt_deg = o.tilt_deg;
  }
  ImagingSettings imaging;
  imaging.elevation_step_rad = degToRad(o.elevation_step_deg);
  imaging.rays_per_beam = o.rays_per_beam;
  imaging.beam = beamFromName(o.beam);
  if (o.elevation_beam != "sinc2" && imaging.beam != SimulatedBeam::Realistic) {
    throw Error("--elevation-beam", o.elevation_beam,
                "expected --beam realistic: the clipped beam has the seed paper's pattern");
  }
  imaging.elevation_beam = elevationBeamSpec(o.elevation_beam);
  imaging.horizontal_beam_width_rad = degToRad(o.horizontal_beam_width_deg);
  imaging.visible_cell_m = o.visible_cell_m;
  imaging.spreading_exponent = o.spreading_exponent;
  imaging.tvg_exponent = o.tvg_exponent;
  // The seabed field is surveyed as a field: only its tiles near the sonar are built.
  const bool field = o.scene == "seabed-field";
  SeabedReliefSpec relief = o.relief;
  relief.seed = o.field_seed;
  if (relief.relief_m > 0.0 && (field || !isDemoScene(o.scene))) {
    throw Error("--seabed-relief", o.scene,
                "expected a demo scene with a seabed (riser, jacket-node, seabed-objects, "
                "manifold); the seabed field has its own relief and a mesh file its own seabed");
  }
  const SimulationRequest request{
      field                  ? Scene{}
      : isDemoScene(o.scene) ? makeDemoScene(o.scene, relief)
                             : loadSceneMesh(o.scene, o.reflectivity),
      o.scene,
      simulatedSonar(o),
      trajectory,
      imaging,
      noiseFrom(o.noise, o.seed),
      navErrorWithSeed(o.nav_error, o.seed),
      o.empty_water,
      o.max_frames >= 0 ? std::optional<int>(o.max_frames) : std::nullopt,
      out,
      declaredBeam(o.declared_beam)};
  const bool earlier_mission = std::filesystem::exists(out / kMissionFileName);
  // A simulation cut short is no mission: a folder made for it goes with it.
  return runIntoOutputFolder(out, PartialOutput::Removed, [&] {
    // Two runs into one folder would mix their frames, navigation and ground truth.
    const OutputFolderLock lock(out);
    // So would a run that fails part-way over an earlier mission (--force): the mission is
    // written apart and moved in once complete.
    const StagedOutputs staged(out);
    SimulationRequest staged_request = request;
    staged_request.output = staged.staging();
    TerminalProgress progress;
    try {
      const SimulationResult result = runSimulation(
          staged_request, progress, pool,
          field ? std::optional<SeabedFieldSpec>(fieldWithSeed(o.field_seed)) : std::nullopt,
          relief);
      progress.finish();
      const bool bag = o.format != "folder" && !result.cancelled;
      const BagWriteReport bag_written =
          bag ? writeMissionBag(o.format, staged.staging()) : BagWriteReport{};
      for (const std::filesystem::path& removed : publishStagedMission(
               staged, earlier_mission ? simulatedMissionFiles() : std::vector<std::string>{})) {
        std::cerr << "removed " << removed.string() << " of an earlier run\n";
      }
      std::cout << (result.cancelled ? "cancelled: wrote the first " : "wrote ")
                << result.frames_written << " frames of '" << (field ? o.scene : request.scene.name)
                << "' (" << request.trajectory.kind << ") to " << out.string() << "; "
                << result.visible_points << " visible surface points; at most "
                << result.most_triangles_traced << " scene triangles traced at once, "
                << result.ground_truth_triangles << " in the ground truth\n";
      if (bag) {
        std::cout << "wrote " << bag_written.frames << " frames and " << bag_written.poses
                  << " poses as a ROS 2 bag (" << o.format << ") to "
                  << (out / bagFileName(o.format)).string() << "\n";
      }
      return result.cancelled ? 130 : 0;
    } catch (const Error& e) {
      throw staged.nothingChanged(e);
    }
  });
}

}  // namespace

void addSimulateCommand(CLI::App& app, ThreadPool& pool, int& exit_code) {
  auto* cmd = app.add_subcommand("simulate", "Simulate a sonar mission with ground truth");
  auto o = std::make_shared<SimulateOptions>();
  cmd->add_option("--scene", o->scene,
                  "riser | jacket-node | seabed-objects | manifold | seabed-field (a seabed of any "
                  "extent with objects, for long surveys) | mesh file (STL, OBJ, PLY) in world "
                  "NED metres")
      ->required();
  cmd->add_option("--trajectory", o->trajectory,
                  "vertical | orbit | descents (vertical descents from --descents headings around "
                  "the structure) | lawnmower | navigation CSV of vehicle poses; auto picks the "
                  "scene's usual one")
      ->capture_default_str();
  cmd->add_option("--noise", o->noise,
                  "none | default | coherent (the default noise, each return and the background "
                  "combined as phasors: docs/simulator.md) | noise YAML file")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Mission folder to write")->required();
  cmd->add_option("--standoff", o->standoff_m, "Distance from the sonar to the structure's axis, m")
      ->capture_default_str();
  cmd->add_option("--step", o->step_m, "Distance between frames, m")
      ->check(CLI::Range(kMinSimStep_m, kMaxSimStep_m))
      ->capture_default_str();
  cmd->add_option("--speed", o->survey.speed_mps,
                  "Vehicle speed, m/s: with --step it sets the frame rate (0.5 m/s and 0.05 m: "
                  "10 Hz)")
      ->check(CLI::Range(1e-3, 100.0))
      ->capture_default_str();
  cmd->add_option("--frames", o->survey.frames,
                  "orbit and lawnmower: go on for this many frames (more laps, or more lines to "
                  "the east); 0: one lap, or the lines of a --survey-width square")
      ->check(CLI::Range(0, kMaxSimFrames))
      ->capture_default_str();
  cmd->add_option("--laps", o->survey.laps,
                  "orbit: turns around the axis (without --frames), on each level with "
                  "--orbit-levels")
      ->check(CLI::Range(0.01, 10000.0))
      ->capture_default_str();
  cmd->add_option("--line-length", o->survey.line_length_m, "lawnmower: length of a line, m")
      ->check(CLI::Range(0.1, 10000.0))
      ->capture_default_str();
  cmd->add_option("--line-spacing", o->survey.line_spacing_m,
                  "lawnmower: distance between lines, m")
      ->check(CLI::Range(0.01, 1000.0))
      ->capture_default_str();
  cmd->add_option("--survey-width", o->survey.survey_width_m,
                  "lawnmower: east-west extent of the lines, m (without --frames)")
      ->check(CLI::Range(0.0, 10000.0))
      ->capture_default_str();
  cmd->add_option("--altitude", o->survey.altitude_m, "lawnmower: height above the seabed, m")
      ->check(CLI::Range(0.1, 1000.0))
      ->capture_default_str();
  cmd->add_option("--tilt", o->tilt_deg,
                  "Sonar pitch on the vehicle, deg (negative = down). lawnmower: -30 if not "
                  "given; vertical, orbit and descents: level if not given, and when tilted the "
                  "sonar is raised so that its axis meets the structure's axis at the depth it "
                  "inspects")
      ->check(CLI::Range(-79.0, 79.0));
  cmd->add_option("--orbit-levels", o->survey.orbit_levels,
                  "orbit: 0, one circle descending over the structure's depth span; N >= 1, N "
                  "level circles of --laps turns, aimed at depths --level-spacing apart centred "
                  "on the structure's axis point, top first")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  cmd->add_option("--level-spacing", o->survey.level_spacing_m,
                  "orbit levels: distance between the depths they aim at, m")
      ->check(CLI::Range(0.05, 100.0))
      ->capture_default_str();
  cmd->add_option("--descents", o->survey.descents,
                  "descents: how many vertical descents, from headings evenly spaced around the "
                  "structure (the first from the south, as vertical's)")
      ->check(CLI::Range(1, 360))
      ->capture_default_str();
  cmd->add_option("--field-seed", o->field_seed,
                  "seabed-field: seed of the field's relief and objects (the same seed, the same "
                  "field); also of --seabed-relief's waves")
      ->capture_default_str();
  cmd->add_option(
         "--seabed-relief", o->relief.relief_m,
         "Amplitude of a relief, m, replacing the flat seabed of riser, jacket-node (which "
         "then stands on a seabed at 20 m), seabed-objects and manifold: a heightfield of "
         "three waves of seeded headings (--field-seed), levelled where the structure "
         "stands; 0: the flat seabed")
      ->check(CLI::Range(0.0, 5.0))
      ->capture_default_str();
  cmd->add_option("--seabed-wavelength", o->relief.wavelength_m,
                  "With --seabed-relief: the relief's waves have wavelengths between this and "
                  "twice it, m")
      ->check(CLI::Range(1.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--max-frames", o->max_frames, "Stop after this many frames")
      ->check(CLI::Range(0, kMaxSimFrames));
  cmd->add_option("--seed", o->seed, "Seed of the noise and navigation error")
      ->capture_default_str();
  addNavErrorFlags(*cmd, o->nav_error);
  cmd->add_option("--elevation-step", o->elevation_step_deg, "Ray spacing in elevation, deg")
      ->check(CLI::Range(0.01, 90.0))
      ->capture_default_str();
  cmd->add_option("--rays-per-beam", o->rays_per_beam, "Rays across each beam")
      ->check(CLI::Range(1, kMaxRaysPerBeam))
      ->capture_default_str();
  cmd->add_option("--beam", o->beam,
                  "clipped: the seed paper's beam, +-aperture/2 only; realistic: sinc^2 in "
                  "elevation to the second null and leakage between beams (docs/simulator.md)")
      ->check(CLI::IsMember({"clipped", "realistic"}))
      ->capture_default_str();
  cmd->add_option("--elevation-beam", o->elevation_beam,
                  "Realistic beam: the pattern simulated in elevation. -3 dB at +-aperture/2: "
                  "sinc2 (side lobes to the second null); gaussian (traced to -30 dB); "
                  "truncated (sinc^2 cut to 0 past its -6 dB points). table:FILE: a CSV of "
                  "elevation_deg,gain_db, linear in dB, 0 outside. mission.yaml declares "
                  "--declared-beam whatever is simulated (docs/simulator.md)")
      ->capture_default_str();
  cmd->add_option("--declared-beam", o->declared_beam,
                  "The elevation beam mission.yaml declares to the reconstruction: sinc (a real "
                  "beam) or clipped (nothing outside +-aperture/2); default: clipped for --beam "
                  "clipped, else sinc")
      ->check(CLI::IsMember({"sinc", "clipped"}));
  cmd->add_option("--horizontal-beam-width", o->horizontal_beam_width_deg,
                  "Realistic beam: -3 dB width of each beam in bearing, deg, written to "
                  "mission.yaml so that reconstruction takes the blur out; 0 = the bearing "
                  "spacing, not written")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--spreading-loss", o->spreading_exponent,
                  "Returns fall with range as r^-K (K = 2: spherical spreading of intensity one "
                  "way, 4: both ways); 0: none, as if a time-varied gain undid it")
      ->check(CLI::Range(0.0, 8.0))
      ->capture_default_str();
  cmd->add_option("--tvg", o->tvg_exponent,
                  "Time-varied gain of the sonar: returns times r^K; with --spreading-loss, "
                  "the difference is what the images keep of the spreading")
      ->check(CLI::Range(0.0, 8.0))
      ->capture_default_str();
  cmd->add_option("--intensity", o->intensity,
                  "How the frame files store the echo's power: linear (counts are power), "
                  "decibel (bytes 0..255 for 0..80 dB, as ARIS recordings do; the mission says "
                  "so and is read back as power)")
      ->check(CLI::IsMember({"linear", "decibel"}))
      ->capture_default_str();
  cmd->add_option("--visible-cell", o->visible_cell_m,
                  "Ground truth: one seen surface point per cell of this side, m, in "
                  "visible_points.ply; 0: none written (they take memory with the area seen: "
                  "docs/simulator.md)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--reflectivity", o->reflectivity, "Reflectivity of a loaded mesh, 0..1")
      ->capture_default_str();
  cmd->add_flag("--empty-water", o->empty_water,
                "Frames of empty water (noise only), to learn a noise model from");
  cmd->add_flag("--force", o->force, "Overwrite a mission already in --out");
  cmd->add_option("--format", o->format,
                  "folder: the mission folder only; mcap (zstd chunks), mcap-lz4, mcap-none, "
                  "mcap-unchunked, db3: also the mission as a ROS 2 bag, DIR/mission.mcap or "
                  "DIR/mission.db3 (docs/formats.md)")
      ->check(CLI::IsMember({"folder", "mcap", "mcap-lz4", "mcap-none", "mcap-unchunked", "db3"}))
      ->capture_default_str();
  cmd->callback([o, &pool, &exit_code] { exit_code = runSimulate(*o, pool); });
}

}  // namespace sonarcarve::cli
