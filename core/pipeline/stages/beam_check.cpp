// beam check: whether the frames show the returns the declared elevation beam puts past its
// aperture (pipeline/beam_check.h), for a run that carves beam-aware. A first surface is carved
// inside the aperture only from up to kCheckFrames frames in the middle of the mission (a few
// metres of track: its map stays small whatever the mission); where the tails are missing, the
// run carves inside the aperture too, as for a sonar declared `clipped`.
#include <algorithm>

#include "carve/carving_geometry.h"
#include "common/error.h"
#include "denoise/noise_model.h"
#include "pipeline/beam_check.h"
#include "pipeline/beam_reach.h"
#include "pipeline/keep_level.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"
#include "pipeline/surface_stage.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

constexpr std::size_t kCheckFrames = 24;
// The first surface keeps this many points (for the reach and the surface stage's check); the
// reach follows them through this many views.
constexpr std::size_t kReachPoints = 4000;
constexpr std::size_t kReachFrames = 48;

// The middle of the mission: every other frame of its middle 2 kCheckFrames, or every frame of
// a mission shorter than that, at most kCheckFrames of them.
std::vector<PosedFrame> middleFrames(const std::vector<PosedFrame>& posed) {
  const std::size_t span = std::min(posed.size(), 2 * kCheckFrames);
  const std::size_t stride = span > kCheckFrames ? 2 : 1;
  const std::size_t first = (posed.size() - span) / 2;
  std::vector<PosedFrame> middle;
  for (std::size_t i = first; i < first + span; i += stride) {
    middle.push_back(posed[i]);
  }
  return middle;
}

class BeamCheckStage : public Stage {
 public:
  BeamCheckStage() : Stage("beam check", 0.03) {}

  void run(RunContext& run, Progress& progress) const override {
    if (!carvesMainLobe(run.sonar, run.carving.carve) || !run.carve_frames) {
      return;
    }
    const SonarModel clipped = run.sonar.withElevationBeam(ElevationBeam::Clipped);
    CarveStageParams params = run.carving;
    params.occlusion_aware = false;
    params.refinement.enabled = false;
    params.earlier_map = nullptr;
    const CarveStage first(clipped, params, run.pool);
    const std::vector<PosedFrame> frames = middleFrames(run.posed);
    RenamedProgress checking(progress, "beam check");
    const CarveStageResult carved = first.run(frames, first.mapBounds(frames), *run.frames,
                                              checking, nullptr, [](const FrameProblem&) {});
    if (carved.cancelled) {
      throw Cancelled();
    }
    if (carved.used.empty()) {
      return;  // the carve stage reports the frames that do not load
    }
    const SurfaceStageResult surface =
        resolveSurface(*carved.carver, carved.used, clipped, carved.carve, run.params.min_views,
                       run.pool, checking);
    if (surface.cancelled) {
      throw Cancelled();
    }
    const NoiseModel* background = run.noise.model.get();
    const auto excess = [&](std::size_t i) -> std::optional<cv::Mat> {
      try {
        cv::Mat image = loadFrame(run.mission, carved.used[i].index).image;
        return background ? cv::Mat(image - background->mean()) : image;
      } catch (const Error&) {
        return std::nullopt;
      }
    };
    const std::vector<Eigen::Vector3f> points = positionsOf(surface.surface);
    const BeamTailCheck check = checkBeamTails(points, carved.used, excess, run.sonar,
                                               background ? background->stddev() : cv::Mat());
    const std::size_t step = std::max<std::size_t>(1, points.size() / kReachPoints);
    for (std::size_t p = 0; p < points.size(); p += step) {
      run.first_surface.push_back(points[p]);
    }
    run.first_surface_frames = carved.used.size();
    run.choose(beamTailChoice(check));
    if (!check.tails_present) {
      run.sonar = clipped;
      return;
    }
    findReach(run, run.first_surface, progress);
  }

 private:
  // How far off the axis carving goes (pipeline/beam_reach.h): the first surface (up to
  // kReachPoints points) followed through up to kReachFrames views spread over the frames that
  // can see it, at the run's keep level (measured here once; the choose stage uses it). Only where
  // a dark pixel is exact: behind a detector every frame carves inside the aperture.
  static void findReach(RunContext& run, const std::vector<Eigen::Vector3f>& points,
                        Progress& progress) {
    if (!darkPixelsAreExact(run.noise.detector) || points.empty()) {
      return;
    }
    const std::vector<PosedFrame> views = framesThatMaySee(run, points);
    CarveParams carve = run.carving.carve;  // as the choose stage will make it
    run.measured_keep_level =
        measureKeepLevel(*run.frames, run.posed, carve.dynamic_range_db, progress);
    setKeepLevel(carve, run.measured_keep_level->level, true,
                 run.sonar.intensityScale().darkPower());
    const auto image = [&](std::size_t i) -> std::optional<cv::Mat> {
      try {
        return run.frames->load(views[i].index).image;
      } catch (const Error&) {
        return std::nullopt;
      }
    };
    const ElevationReach reach = reachFromFates(
        followPoints(points, views, image, run.sonar, carve.keep_level),
        0.5 * run.sonar.verticalAperture(), SincSquaredBeam(run.sonar.verticalAperture()).null(1));
    run.choose(elevationReachChoice(reach));
    if (reach.shortened()) {
      run.sonar = run.sonar.withElevationReach(reach.reach_rad);
    }
  }

  // Frames whose sonar lies within its range of the points' box, at most kReachFrames of them
  // evenly spread.
  static std::vector<PosedFrame> framesThatMaySee(const RunContext& run,
                                                  const std::vector<Eigen::Vector3f>& points) {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3f& p : points) {
      box.extend(p.cast<double>());
    }
    const double reach = run.sonar.range().maxRange();
    std::vector<PosedFrame> near;
    for (const PosedFrame& frame : run.posed) {
      if (box.exteriorDistance(frame.T_world_sonar.translation()) <= reach) {
        near.push_back(frame);
      }
    }
    const std::size_t stride = (near.size() + kReachFrames - 1) / kReachFrames;
    std::vector<PosedFrame> spread;
    for (std::size_t i = 0; i < near.size(); i += std::max<std::size_t>(1, stride)) {
      spread.push_back(near[i]);
    }
    return spread;
  }
};

}  // namespace

std::unique_ptr<Stage> makeBeamCheckStage() {
  return std::make_unique<BeamCheckStage>();
}

}  // namespace sonarcarve
