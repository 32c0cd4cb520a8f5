// fit: the carved map's band fitted to every frame by the forward model (fit/map_fit.h), its
// surface then taken from the fitted map (fit/fitted_surface.h). Only in runs that ask for it
// (fit.enabled), after the surface stage and before the mesh.
#include <cstdio>

#include "common/angles.h"
#include "fit/fitted_surface.h"
#include "fit/initial_grid.h"
#include "fit/map_fit.h"
#include "io/mission/mission.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

// Bytes a band voxel holds while the fit runs: logit and reflectance, the log reflectance,
// two optimiser moments for each, the band mask, and the gradient's two doubles for the
// step and for each thread's share.
double bytesPerVoxel(std::size_t threads) {
  return 4.0 * 2 + 4.0 + 4.0 * 4 + 1.0 + 16.0 * static_cast<double>(threads + 1);
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
  return text;
}

std::vector<double> backgroundPerBin(const RunContext& run) {
  std::vector<double> background;
  if (!run.noise.model) {
    return background;
  }
  const cv::Mat& mean = run.noise.model->mean();
  for (int row = 0; row < mean.rows; ++row) {
    background.push_back(cv::mean(mean.row(row))[0]);
  }
  return background;
}

RunChoice fitChoice(const MapFitSummary& summary, std::size_t carved_points,
                    std::size_t fitted_points) {
  RunChoice choice;
  choice.name = "map fit";
  choice.value = "on";
  choice.reason = "the frames' returns left unexplained: " + percent(summary.after.unexplained) +
                  " by the fitted map, " + percent(summary.before.unexplained) +
                  " by the carved one";
  choice.detail = "band of " + std::to_string(summary.band_voxels) + " voxels; gain " +
                  std::to_string(summary.gain) + "; speckle NLL per pixel " +
                  std::to_string(summary.before.nll_per_pixel) + " -> " +
                  std::to_string(summary.after.nll_per_pixel) + "; surface points " +
                  std::to_string(carved_points) + " carved -> " + std::to_string(fitted_points) +
                  " fitted";
  return choice;
}

std::string degrees(double radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f deg", radToDeg(radians));
  return text;
}

// The fitted elevation beam beside the declared one: -3 and -10 dB widths, and the knots.
RunChoice beamChoice(const MapFitSummary& summary) {
  const ElevationProfile& declared = *summary.declared_profile;
  const ElevationProfile& fitted = *summary.fitted_profile;
  RunChoice choice;
  choice.name = "fitted elevation beam";
  choice.value = "fitted";
  choice.reason = "the frames' elevation beam: -3 dB wide " + degrees(fitted.width(-3.0)) +
                  " (declared " + degrees(declared.width(-3.0)) + "), -10 dB wide " +
                  degrees(fitted.width(-10.0)) + " (declared " + degrees(declared.width(-10.0)) +
                  ")";
  std::string knots;
  for (std::size_t m = 0; m < fitted.knotsDb().size(); ++m) {
    char text[64];
    std::snprintf(text, sizeof text, "%s%.1f: %.1f (%.1f)", m == 0 ? "" : ", ",
                  radToDeg(fitted.knotAngle(static_cast<int>(m))), fitted.knotsDb()[m],
                  declared.knotsDb()[m]);
    knots += text;
  }
  choice.detail = "level in dB at elevations in deg, fitted (declared): " + knots +
                  "; background mean " + std::to_string(summary.fitted_background) + " (start " +
                  std::to_string(summary.declared_background) + ")";
  return choice;
}

class FitStage : public Stage {
 public:
  FitStage() : Stage("fit", 1.0) {}

  std::optional<MemoryNeed> memoryNeed(const RunContext& run) const override {
    const int side = 2 * run.params.fit.band_voxels + 1;
    const double voxels = static_cast<double>(run.result.surface.size()) * side * side * side;
    return MemoryNeed{{{"fit band", voxels * bytesPerVoxel(run.pool.size())}}, "before the fit"};
  }

  void run(RunContext& run, Progress& progress) const override {
    ReconstructionResult& result = run.result;
    if (result.cancelled || result.surface.empty()) {
      return;
    }
    if (!result.map) {
      RunChoice off;
      off.name = "map fit";
      off.value = "off";
      off.reason = "the run did not keep its carved map whole (the reference engine)";
      off.warning = true;
      run.choose(off);
      return;
    }
    FitGrid grid = initialGrid(*result.map, result.surface, run.params.fit.band_voxels);
    std::vector<MapFitFrame> frames;
    for (const PosedFrame& posed : run.carved.used) {
      frames.push_back({posed.index, posed.T_world_sonar});
    }
    const MapFit fit(run.sonar, run.params.fit, run.pool);
    const Mission& mission = run.mission;
    const MapFitSummary summary = fit.run(
        grid, frames, [&mission](std::size_t index) { return loadFrame(mission, index).image; },
        backgroundPerBin(run), progress);
    SurfacePoints fitted = fittedSurface(grid.grid, run.sonar, frames, run.params.fit,
                                         run.params.min_views, run.pool, progress);
    run.choose(fitChoice(summary, result.surface.size(), fitted.size()));
    if (run.params.fit.beam && summary.fitted_profile) {
      run.choose(beamChoice(summary));
    }
    result.surface = std::move(fitted);
  }
};

}  // namespace

std::unique_ptr<Stage> makeFitStage() {
  return std::make_unique<FitStage>();
}

}  // namespace sonarcarve
