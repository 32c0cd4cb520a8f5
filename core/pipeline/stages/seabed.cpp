// seabed relief: before carving, the seabed that the frames image is fitted as a heightfield
// over the whole mission (carve/seabed_field_fit.h), so that seabed-aware carving explains
// each frame's seabed by its relief rather than by one plane per frame.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

#include "carve/seabed_field_fit.h"
#include "carve/seabed_model.h"
#include "common/error.h"
#include "common/quantile.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

// Nodes of the relief every this many metres: five voxels at the default 2 cm, a tenth of the
// shortest wave the simulator's seabeds hold (docs/simulator.md).
constexpr double kReliefCell_m = 0.2;
// A seabed seen in fewer frames than this, or whose planes the frames' main lobes met over
// fewer nodes (4 m^2), is left to the frames' planes.
constexpr std::size_t kMinFrames = 24;
constexpr std::size_t kMinNodes = 100;

RunChoice reliefChoice(const SeabedHeightfield& field, std::size_t frames,
                       const SeabedFieldFitResult& fit) {
  std::vector<double> depths;
  for (std::size_t n = 0; n < field.nodeCount(); ++n) {
    if (field.known(n)) {
      depths.push_back(field.depths()[n]);
    }
  }
  const double area = static_cast<double>(depths.size()) * field.cell() * field.cell();
  const double low = quantile(depths, 0.02);
  const double high = quantile(depths, 0.98);
  RunChoice choice;
  choice.name = "seabed relief";
  char value[96];
  std::snprintf(value, sizeof value, "fitted over %.1f m^2, depths %.2f to %.2f m", area, low,
                high);
  choice.value = value;
  choice.reason =
      "the frames image a seabed: its relief was fitted to them, so that carving "
      "explains each frame's seabed by its shape rather than by one plane a frame";
  char detail[256];
  std::snprintf(detail, sizeof detail,
                "%zu frames, %zu nodes every %.2f m, %zu steps; misfit of the seabed's predicted "
                "images %.3f (first pass) -> %.3f (last pass)",
                frames, depths.size(), field.cell(), fit.steps, fit.misfit_before,
                fit.misfit_after);
  choice.detail = detail;
  return choice;
}

// The fit's progress after the tracking pass's: one pass of `frames` done, `passes` to come.
class FitProgress : public Progress {
 public:
  FitProgress(Progress& inner, std::size_t frames, int passes)
      : inner_(inner), frames_(frames), total_(frames * static_cast<std::size_t>(passes + 1)) {}
  void report(const std::string& stage, std::size_t done, std::size_t) override {
    inner_.report(stage, frames_ + done, total_);
  }
  bool cancelled() const override { return inner_.cancelled(); }
  void overall(double fraction) override { inner_.overall(fraction); }

 private:
  Progress& inner_;
  std::size_t frames_, total_;
};

class SeabedReliefStage : public Stage {
 public:
  SeabedReliefStage() : Stage("seabed relief", 0.2) {}

  void run(RunContext& run, Progress& progress) const override {
    const CarveParams& carve = run.carving.carve;
    if (!run.params.seabed_relief || run.params.engine != Engine::Fast || !carve.seabed_aware ||
        !carvesMainLobe(run.sonar, carve) || !run.carve_frames || run.posed.empty()) {
      return;
    }
    // The frames' planes, tracked in the order carving takes them.
    SeabedTracker tracker;
    std::vector<SeabedFrame> frames;
    std::vector<std::size_t> indices;
    const SeabedFieldFitParams fit_params;
    for (std::size_t n = 0; n < run.posed.size(); ++n) {
      if (progress.cancelled()) {
        throw Cancelled();
      }
      BeforeDetection before;
      Frame frame;
      try {
        frame = run.frames->load(run.posed[n].index, &before);
      } catch (const Error&) {
        continue;  // the carve stage reports it
      }
      const std::optional<SeabedPlane> plane =
          tracker.track(frame.image, run.posed[n].T_world_sonar, run.sonar, &run.pool, &before);
      if (plane) {
        frames.push_back({run.posed[n].T_world_sonar, *plane});
        indices.push_back(run.posed[n].index);
      }
      progress.report("seabed relief", n + 1,
                      run.posed.size() * static_cast<std::size_t>(fit_params.passes + 1));
    }
    if (frames.size() < kMinFrames) {
      return;
    }
    auto field =
        std::make_shared<SeabedHeightfield>(fuseSeabedPlanes(frames, run.sonar, kReliefCell_m));
    if (field->knownCount() < kMinNodes) {
      return;
    }
    const auto pixels_of = [&run, &indices](std::size_t n) -> cv::Mat {
      BeforeDetection before;
      try {
        const Frame frame = run.frames->load(indices[n], &before);
        return behindDetector(&before) ? before.excess : frame.image;
      } catch (const Error&) {
        return {};
      }
    };
    // The fit passes over the frames a plane explained; progress counts them as the mission's.
    FitProgress fitting(progress, run.posed.size(), fit_params.passes);
    const SeabedFieldFitResult fit =
        fitSeabedField(*field, frames, pixels_of, run.sonar, fit_params, &run.pool, fitting);
    if (fit.cancelled) {
      throw Cancelled();
    }
    run.choose(reliefChoice(*field, frames.size(), fit));
    run.carving.carve.seabed_field = std::move(field);
  }
};

}  // namespace

std::unique_ptr<Stage> makeSeabedReliefStage() {
  return std::make_unique<SeabedReliefStage>();
}

}  // namespace sonarcarve
