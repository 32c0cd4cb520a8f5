// `sonarcarve-cli bench simulate|carve|reconstruct`: speed of the engine's steps at the seed
// paper's parameters, and of whole reconstructions of long missions (cli/bench_reconstruct.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "carve/carving_geometry.h"
#include "carve/fast_carver.h"
#include "carve/reference_carver.h"
#include "cli/bench_reconstruct.h"
#include "cli/bench_validate.h"
#include "cli/commands.h"
#include "cli/terminal_progress.h"
#include "common/error.h"
#include "common/process_memory.h"
#include "common/thread_pool.h"
#include "io/files/frame_png.h"
#include "occlusion/occlusion_resolver.h"
#include "pipeline/keep_level.h"
#include "pipeline/reconstruction_params.h"
#include "sim/demo_scenes.h"
#include "sim/noise.h"
#include "sim/ray_caster.h"
#include "sim/simulation_run.h"
#include "sim/sonar_simulator.h"

namespace sonarcarve::cli {
namespace {

struct BenchOptions {
  std::string what = "simulate";
  bool region = false;
  bool seabed_aware = CarveParams{}.seabed_aware;
  int reference_frames = 3;
  std::string scene = "riser";
  int frames = 40;
  std::string beam = "clipped";
  bool json = false;
  BenchReconstructOptions reconstruct;
  BenchValidateOptions validate;
};

struct Timings {
  std::vector<double> ms;
  double median() const {
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    return sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  }
  double mean() const {
    double total = 0.0;
    for (double v : ms) {
      total += v;
    }
    return ms.empty() ? 0.0 : total / static_cast<double>(ms.size());
  }
};

template <typename F>
double timeMs(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time of the whole process (every thread), ms: on a shared machine, what a step costs
// whatever else runs, where wall time also counts the waits for a core.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

int benchSimulate(const BenchOptions& o, ThreadPool& pool) {
  const Scene scene = makeDemoScene(o.scene);
  const SonarModel sonar = paperSonar();
  TrajectorySpec spec;
  spec.kind = usualTrajectory(o.scene);
  const Trajectory trajectory = makeTrajectory(spec, scene.target);
  Timings build;
  std::unique_ptr<RayCaster> caster;
  build.ms.push_back(timeMs([&] { caster = std::make_unique<RayCaster>(scene); }));
  ImagingSettings imaging;
  imaging.beam = beamFromName(o.beam);
  const SonarSimulator simulator(*caster, sonar, imaging, pool);
  const NoiseSpec noise;
  Timings render;
  Timings with_noise;
  const std::size_t frames =
      std::min<std::size_t>(static_cast<std::size_t>(o.frames), trajectory.poses.size());
  TerminalProgress progress;
  for (std::size_t i = 0; i < frames && !progress.cancelled(); ++i) {
    // Spread the measured frames over the whole trajectory.
    const std::size_t frame = i * trajectory.poses.size() / frames;
    cv::Mat image;
    render.ms.push_back(timeMs([&] { image = simulator.render(trajectory.T_world_sonar(frame)); }));
    with_noise.ms.push_back(render.ms.back() + timeMs([&] { addNoise(image, noise, sonar, i); }));
    progress.report("bench simulate", i + 1, frames);
  }
  progress.finish();
  const double fps = with_noise.median() > 0.0 ? 1000.0 / with_noise.median() : 0.0;
  if (o.json) {
    nlohmann::json j = {{"bench", "simulate"},
                        {"scene", o.scene},
                        {"beam", o.beam},
                        {"beams", sonar.cols()},
                        {"range_bins", sonar.rows()},
                        {"rays_per_frame", simulator.raysPerFrame()},
                        {"threads", pool.size()},
                        {"frames", render.ms.size()},
                        {"bvh_build_ms", build.median()},
                        {"render_median_ms", render.median()},
                        {"render_mean_ms", render.mean()},
                        {"render_and_noise_median_ms", with_noise.median()},
                        {"frames_per_second", fps}};
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("simulate %s, %s beam: %d x %d image, %zu rays per frame, %u threads, %zu frames\n",
                o.scene.c_str(), o.beam.c_str(), sonar.cols(), sonar.rows(),
                simulator.raysPerFrame(), pool.size(), render.ms.size());
    std::printf("  BVH build            %8.1f ms\n", build.median());
    std::printf("  render (median)      %8.1f ms   mean %.1f ms\n", render.median(), render.mean());
    std::printf("  render + noise       %8.1f ms   -> %.1f frames per second\n",
                with_noise.median(), fps);
  }
  return 0;
}

// Peak resident memory of this process so far (Linux), in MB.
double peakMemoryMb() {
  return megabytes(processMemory().value_or(ProcessMemory{}).peak_resident_bytes);
}

// The whole demo mission in memory (no file I/O in the timings): the fast engine's map
// update and occlusion resolution per frame, then the reference engine on a few frames.
int benchCarve(const BenchOptions& o, ThreadPool& pool) {
  const Scene scene = makeDemoScene(o.scene);
  ImagingSettings imaging;
  imaging.beam = beamFromName(o.beam);
  // Frames of a clipped beam say so (carving stays inside the aperture), as missions do.
  const SonarModel sonar = imaging.beam == SimulatedBeam::Clipped
                               ? paperSonar().withElevationBeam(ElevationBeam::Clipped)
                               : paperSonar();
  TrajectorySpec spec;
  spec.kind = usualTrajectory(o.scene);
  const Trajectory trajectory = makeTrajectory(spec, scene.target);
  const RayCaster caster(scene);
  const SonarSimulator simulator(caster, sonar, imaging, pool);
  CarveParams params;
  params.dark_pixels = CarveParams::DarkPixels::Exact;  // noise-free frames
  params.seabed_aware = o.seabed_aware;
  if (o.region) {
    // A 4 m x 4 m column around the structure's axis, as an analyst would draw it.
    const Eigen::Vector3d axis = scene.target.axis_point_m;
    params.region = Eigen::AlignedBox3d(
        Eigen::Vector3d(axis.x() - 2.0, axis.y() - 2.0, scene.target.top_down_m - 1.0),
        Eigen::Vector3d(axis.x() + 2.0, axis.y() + 2.0, scene.target.bottom_down_m + 0.5));
  }
  const std::size_t frames = trajectory.poses.size();
  std::vector<cv::Mat> images(frames);
  std::vector<Eigen::Isometry3d> poses(frames);
  const CarvingGeometry geometry(sonar, params);
  Eigen::AlignedBox3d bounds;
  for (std::size_t i = 0; i < frames; ++i) {
    poses[i] = trajectory.T_world_sonar(i);
    // In whole counts, as mission files and sonars give them: a float render's faint tails
    // would widen beam-aware carving past where frames on disk reach.
    wholeCounts(simulator.render(poses[i]), "frame " + std::to_string(i))
        .convertTo(images[i], CV_32F);
    bounds.extend(geometry.frustumBounds(poses[i]));
  }
  if (params.region) {
    bounds = bounds.intersection(*params.region);
  }
  if (carvesMainLobe(sonar, params)) {
    SilentProgress quiet;
    params.keep_level =
        measureKeepLevel(
            frames, [&](std::size_t i) { return std::optional<cv::Mat>(images[i]); },
            params.dynamic_range_db, quiet)
            .level;
  }
  const double before_map = peakMemoryMb();
  VoxelMap map(params.voxel_size_m, bounds);
  FastCarver carver(map, sonar, params, pool);
  Timings carve;
  TerminalProgress progress;
  double visited = 0.0, observed = 0.0;
  const double cpu_before = processCpuMs();
  for (std::size_t i = 0; i < frames && !progress.cancelled(); ++i) {
    IntegrateStats stats;
    carve.ms.push_back(timeMs(
        [&] { stats = carver.integrate(images[i], poses[i], static_cast<std::uint32_t>(i + 1)); }));
    visited += static_cast<double>(stats.blocks_visited) / static_cast<double>(frames);
    observed += static_cast<double>(stats.voxels_observed) / static_cast<double>(frames);
    progress.report("bench carve", i + 1, frames);
  }
  const double carve_cpu_ms = (processCpuMs() - cpu_before) / static_cast<double>(carve.ms.size());
  const VoxelValues shell =
      collectVoxels([&](const Carver::VoxelVisitor& visit) { map.forEachOccupiedOnShell(visit); });
  OcclusionResolver resolver(shell.voxels, shell.values, sonar, params);
  const double occlusion_total = timeMs([&] {
    pool.parallelFor(frames, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i)
        resolver.addView(poses[i]);
    });
  });
  // The reference engine, on a few frames in the middle (it takes seconds per frame).
  CarveParams reference_params = params;
  reference_params.region = bounds;
  ReferenceCarver reference(sonar, reference_params);
  Timings reference_ms;
  for (int k = 0; k < o.reference_frames && !progress.cancelled(); ++k) {
    const std::size_t i = frames / 2 + static_cast<std::size_t>(k);
    reference_ms.ms.push_back(timeMs([&] { reference.integrate(images[i], poses[i]); }));
    progress.report("bench reference", static_cast<std::size_t>(k + 1),
                    static_cast<std::size_t>(o.reference_frames));
  }
  progress.finish();
  nlohmann::json j = {
      {"bench", "carve"},
      {"scene", o.scene},
      {"region_of_interest", o.region},
      {"frames", carve.ms.size()},
      {"beam", o.beam},
      {"beam_aware", carvesMainLobe(sonar, params)},
      {"seabed_aware", params.seabed_aware},
      {"threads", pool.size()},
      {"map_blocks", map.boxBlockCount()},
      {"fast_carve_median_ms", carve.median()},
      {"fast_carve_mean_ms", carve.mean()},
      {"fast_carve_cpu_ms_per_frame", carve_cpu_ms},
      {"blocks_visited_per_frame", visited},
      {"voxels_observed_per_frame", observed},
      {"occlusion_ms_per_frame", occlusion_total / static_cast<double>(frames)},
      {"surface_points", resolver.result(ReconstructionParams::kDefaultMinViews).size()},
      {"map_megabytes", static_cast<double>(map.memoryBytes()) / 1e6},
      {"peak_memory_mb", peakMemoryMb()},
      {"images_and_scene_mb", before_map},
      {"reference_carve_median_ms", reference_ms.median()},
      {"reference_frames", reference_ms.ms.size()}};
  if (o.json) {
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("carve %s%s: %zu frames, 650 x 500 images, 2 cm voxels, %u threads\n",
                o.scene.c_str(), o.region ? " (4 m region of interest)" : " (whole frustum)",
                carve.ms.size(), pool.size());
    std::printf("  fast map update      median %7.1f ms   mean %.1f ms\n", carve.median(),
                carve.mean());
    std::printf("  CPU, all threads     %7.1f ms per frame\n", carve_cpu_ms);
    std::printf("  blocks visited       %7.0f per frame, %.1f M voxels observed\n", visited,
                observed / 1e6);
    std::printf("  occlusion resolution %7.2f ms per frame\n",
                occlusion_total / static_cast<double>(frames));
    std::printf("  reference map update median %7.0f ms (%zu frames)\n", reference_ms.median(),
                reference_ms.ms.size());
    std::printf("  map %.1f MB, peak memory %.0f MB (of which images and scene %.0f MB)\n",
                static_cast<double>(map.memoryBytes()) / 1e6, peakMemoryMb(), before_map);
  }
  return 0;
}

}  // namespace

void addBenchCommand(CLI::App& app, ThreadPool& pool, int& exit_code) {
  auto* cmd = app.add_subcommand("bench", "Measure the engine's speed at the paper's parameters");
  auto o = std::make_shared<BenchOptions>();
  cmd->add_option("what", o->what,
                  "simulate | carve | reconstruct (a whole run of MISSION: ms per frame of every "
                  "stage, the real-time factor, memory against frames carved) | validate (the "
                  "validation set simulated and reconstructed: accuracy, points, time)")
      ->check(CLI::IsMember({"simulate", "carve", "reconstruct", "validate"}))
      ->capture_default_str();
  cmd->add_option("mission", o->reconstruct.mission, "reconstruct: the mission to reconstruct");
  cmd->add_option("--params", o->reconstruct.params_file,
                  "reconstruct: parameters YAML (default: the defaults)");
  cmd->add_option("--csv", o->reconstruct.csv,
                  "reconstruct: write the memory samples to this CSV (time_s, stage, done, total, "
                  "frames_carved, rss_mb, peak_rss_mb, rss_anon_mb)");
  cmd->add_option("--sample-every", o->reconstruct.sample_every,
                  "reconstruct: units of a stage (frames) between memory samples")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cmd->add_flag("--region", o->region, "carve: map a 4 m column around the structure only");
  cmd->add_option("--seabed-aware-carving", o->seabed_aware,
                  "carve: fit the seabed in each frame and carve the water over it")
      ->capture_default_str();
  cmd->add_option("--reference-frames", o->reference_frames,
                  "carve: frames to time the reference engine on (0: none)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  cmd->add_option("--scene", o->scene, "Demo scene")->capture_default_str();
  cmd->add_option("--frames", o->frames,
                  "Frames to time; reconstruct: the mission's first this many; validate: each "
                  "mission's first this many (default: all)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cmd->add_option("--beam", o->beam,
                  "clipped | realistic (docs/simulator.md); carve: beam-aware on realistic")
      ->check(CLI::IsMember({"clipped", "realistic"}))
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "Print the figures as JSON");
  cmd->add_option("--out", o->validate.out,
                  "validate: folder for the missions, their runs and validation.md");
  cmd->add_option("--only", o->validate.only, "validate: these missions only")
      ->check(CLI::IsMember(validationMissions()));
  cmd->callback([cmd, o, &pool, &exit_code] {
    if (o->what == "reconstruct") {
      if (o->reconstruct.mission.empty()) {
        throw Error("bench reconstruct", "", "expected a MISSION to reconstruct");
      }
      BenchReconstructOptions r = o->reconstruct;
      r.frames = cmd->count("--frames") > 0 ? o->frames : 0;
      r.json = o->json;
      exit_code = benchReconstruct(r, pool);
      return;
    }
    if (o->what == "validate") {
      if (o->validate.out.empty()) {
        throw Error("bench validate", "--out", "expected a folder for the missions and the table");
      }
      BenchValidateOptions v = o->validate;
      v.max_frames = cmd->count("--frames") > 0 ? o->frames : 0;
      v.program = std::filesystem::read_symlink("/proc/self/exe").string();
      exit_code = benchValidate(v);
      return;
    }
    exit_code = o->what == "carve" ? benchCarve(*o, pool) : benchSimulate(*o, pool);
  });
}

}  // namespace sonarcarve::cli
