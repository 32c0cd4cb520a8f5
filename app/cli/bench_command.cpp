// `sonarcarve-cli bench simulate`: speed of the engine's steps at the seed paper's parameters.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/terminal_progress.h"
#include "common/thread_pool.h"
#include "sim/demo_scenes.h"
#include "sim/noise.h"
#include "sim/ray_caster.h"
#include "sim/simulation_run.h"
#include "sim/sonar_simulator.h"

namespace sonarcarve::cli {
namespace {

struct BenchOptions {
  std::string what = "simulate";
  std::string scene = "riser";
  int frames = 40;
  bool json = false;
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

int benchSimulate(const BenchOptions& o) {
  const Scene scene = makeDemoScene(o.scene);
  const SonarModel sonar = paperSonar();
  TrajectorySpec spec;
  spec.kind = o.scene == "seabed-objects" ? "lawnmower" : "vertical";
  const Trajectory trajectory = makeTrajectory(spec, scene.target);
  Timings build;
  std::unique_ptr<RayCaster> caster;
  build.ms.push_back(timeMs([&] { caster = std::make_unique<RayCaster>(scene); }));
  const SonarSimulator simulator(*caster, sonar, ImagingSettings{});
  const NoiseSpec noise;
  Timings render;
  Timings with_noise;
  const std::size_t frames =
      std::min<std::size_t>(static_cast<std::size_t>(o.frames), trajectory.poses.size());
  TerminalProgress progress;
  for (std::size_t i = 0; i < frames && !progress.cancelled(); ++i) {
    // Spread the measured frames over the whole trajectory.
    const NavSample& pose = trajectory.poses[i * trajectory.poses.size() / frames];
    Eigen::Isometry3d T_world_vehicle = Eigen::Isometry3d::Identity();
    T_world_vehicle.linear() = pose.q_world_vehicle.toRotationMatrix();
    T_world_vehicle.translation() = pose.position_m;
    cv::Mat image;
    render.ms.push_back(timeMs([&] {
      image = simulator.render(T_world_vehicle * trajectory.mounting.T_vehicle_sonar());
    }));
    with_noise.ms.push_back(render.ms.back() + timeMs([&] { addNoise(image, noise, sonar, i); }));
    progress.report("bench simulate", i + 1, frames);
  }
  progress.finish();
  const double fps = with_noise.median() > 0.0 ? 1000.0 / with_noise.median() : 0.0;
  if (o.json) {
    nlohmann::json j = {{"bench", "simulate"},
                        {"scene", o.scene},
                        {"beams", sonar.cols()},
                        {"range_bins", sonar.rows()},
                        {"rays_per_frame", simulator.raysPerFrame()},
                        {"threads", ThreadPool::shared().size()},
                        {"frames", render.ms.size()},
                        {"bvh_build_ms", build.median()},
                        {"render_median_ms", render.median()},
                        {"render_mean_ms", render.mean()},
                        {"render_and_noise_median_ms", with_noise.median()},
                        {"frames_per_second", fps}};
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("simulate %s: %d x %d image, %zu rays per frame, %u threads, %zu frames\n",
                o.scene.c_str(), sonar.cols(), sonar.rows(), simulator.raysPerFrame(),
                ThreadPool::shared().size(), render.ms.size());
    std::printf("  BVH build            %8.1f ms\n", build.median());
    std::printf("  render (median)      %8.1f ms   mean %.1f ms\n", render.median(), render.mean());
    std::printf("  render + noise       %8.1f ms   -> %.1f frames per second\n",
                with_noise.median(), fps);
  }
  return 0;
}

}  // namespace

void addBenchCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("bench", "Measure the engine's speed at the paper's parameters");
  auto o = std::make_shared<BenchOptions>();
  cmd->add_option("what", o->what, "simulate")
      ->check(CLI::IsMember({"simulate"}))
      ->capture_default_str();
  cmd->add_option("--scene", o->scene, "Demo scene")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Frames to time")->capture_default_str();
  cmd->add_flag("--json", o->json, "Print the figures as JSON");
  cmd->callback([o, &exit_code] { exit_code = benchSimulate(*o); });
}

}  // namespace sonarcarve::cli
