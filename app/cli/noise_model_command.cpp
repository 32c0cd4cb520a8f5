// `sonarcarve-cli noise-model EMPTY_WATER_MISSION --out noise.yaml`: per-pixel statistics of
// empty-water frames, for the ztest detector. With --from-mission, the model `reconstruct`
// learns from a mission's own frames when given none (denoise/mission_noise_model.h), saved so
// that every shard of a sharded run denoises alike (docs/scaling.md).
#include <iostream>
#include <numeric>

#include "cli/commands.h"
#include "cli/param_flags.h"
#include "cli/terminal_progress.h"
#include "denoise/detector.h"
#include "denoise/mission_noise_model.h"
#include "denoise/noise_model.h"
#include "io/files/output_folder.h"
#include "io/mission/mission.h"

namespace sonarcarve::cli {

void addNoiseModelCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("noise-model", "Learn a noise model from empty-water frames");
  struct Options {
    std::string mission, out;
    int smoothing = DetectorParams::kDefaultSmoothing;
    bool from_mission = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option(
         "mission", o->mission,
         "Mission of empty water (the same sonar, no target); with --from-mission, any mission")
      ->required();
  cmd->add_option("--out", o->out, "Noise model file to write (YAML)")->required();
  cmd->add_option("--smoothing", o->smoothing,
                  "Box filter side applied to frames first (odd; match the detector's)")
      ->capture_default_str()
      ->check(schemaCheck("detector.smoothing"));
  cmd->add_flag("--from-mission", o->from_mission,
                "Learn from a mission with structure, as reconstruct does without a noise model "
                "(returns from structure left out; docs/denoising.md)");
  cmd->callback([o, &exit_code] {
    // The target is checked, and its folder held, before the frames are learned from.
    const auto hold = holdOutputFile(o->out);
    const Mission mission = readMission(o->mission);
    TerminalProgress progress;
    std::vector<FrameProblem> skipped;
    MissionNoiseStats stats;
    const auto learned = [&] {
      if (!o->from_mission) {
        return NoiseModel::learn(mission, progress, &skipped, o->smoothing);
      }
      std::vector<std::size_t> frames(mission.frames.size());
      std::iota(frames.begin(), frames.end(), std::size_t{0});
      return learnNoiseFromMission(mission, frames, o->smoothing, progress, &stats);
    };
    const NoiseModel model = learned();
    if (o->from_mission) {
      std::cerr << "learned from " << stats.frames_used << " of the mission's frames; "
                << 100.0 * stats.structure_fraction << " % of pixels held structure\n";
    }
    progress.finish();
    for (const auto& p : skipped) {
      std::cerr << "skipped: " << p.message << "\n";
    }
    model.save(o->out);
    std::cout << "noise model of " << model.frames() << " frames (" << model.mean().cols
              << " beams x " << model.mean().rows << " bins): mean background "
              << cv::mean(model.mean())[0] << ", stddev " << cv::mean(model.stddev())[0]
              << "; written to " << o->out << "\n";
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
