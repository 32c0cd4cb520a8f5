#include "pipeline/track_refinement.h"

#include <cmath>
#include <cstdlib>
#include <opencv2/imgproc.hpp>
#include <string>

#include "carve/track_smoother.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

// Widening across beams is set for a structure at the middle of the range window.
double referenceRange(const SonarModel& sonar) {
  return 0.5 * (sonar.range().min_m + sonar.range().maxRange());
}

}  // namespace

cv::Mat widenedReturns(const cv::Mat& image, int radius_bins, int radius_beams) {
  if (radius_bins <= 0 && radius_beams <= 0) {
    return image;
  }
  cv::Mat out;
  const cv::Mat kernel = cv::getStructuringElement(
      cv::MORPH_RECT,
      cv::Size(2 * std::max(radius_beams, 0) + 1, 2 * std::max(radius_bins, 0) + 1));
  cv::dilate(image, out, kernel);
  return out;
}

std::vector<PoseCorrection> refineTrack(const TrackRefinementSetup& setup,
                                        const std::vector<PosedFrame>& frames,
                                        const DenoisedFrames& source, Progress& progress) {
  const PoseRefinementParams& params = setup.params;
  const double resolution = setup.sonar.range().resolution_m;
  const BearingTable& bearings = setup.sonar.bearings();
  const double beam_arc =
      referenceRange(setup.sonar) * bearings.fieldOfView() / static_cast<double>(bearings.count());
  std::vector<Vector6d> track(frames.size(), Vector6d::Zero());
  std::vector<PoseMeasurement> measured(frames.size());
  const CarveParams& carve = setup.carve;
  double tolerance = params.first_pass_tolerance_m;
  for (int pass = 0; pass < params.passes; ++pass, tolerance *= 0.5) {
    const int bins = static_cast<int>(std::lround(tolerance / resolution));
    const int beams = static_cast<int>(std::lround(tolerance / beam_arc));
    auto carver = makeCarver(setup.engine, CarverSetup{setup.sonar, carve, setup.pool});
    if (carver->blockMap() == nullptr) {
      throw Error("parameters", "pose_refinement", "pose refinement needs the fast engine");
    }
    const std::string stage = "align " + std::to_string(pass + 1);
    for (std::size_t n = 0; n < frames.size(); ++n) {
      if (progress.cancelled()) {
        return {};
      }
      Frame frame;
      try {
        frame = source.load(frames[n].index);
      } catch (const Error&) {
        continue;  // the carving stage reports it
      }
      carver->integrate(widenedReturns(frame.image, bins, beams),
                        PoseCorrection::of(track[n]).applied(frames[n].T_world_sonar),
                        static_cast<std::uint32_t>(n + 1));
      progress.report(stage, n + 1, 2 * frames.size());
    }
    const PoseRefiner refiner(*carver->blockMap(), setup.sonar, carve, params, setup.pool);
    // Residuals are capped at the map's expected error, and at no less than two range bins.
    const double scale = std::max(tolerance, 2.0 * resolution);
    for (std::size_t n = 0; n < frames.size(); ++n) {
      if (progress.cancelled()) {
        return {};
      }
      measured[n] = PoseMeasurement{};
      Frame frame;
      try {
        frame = source.load(frames[n].index);
      } catch (const Error&) {
        continue;  // not measured: the track carries it
      }
      measured[n] = refiner.measure(frame.image, frames[n].T_world_sonar, track[n], scale,
                                    EdgeWidening{bins, beams});
      progress.report(stage, frames.size() + n + 1, 2 * frames.size());
    }
    track = smoothCorrectionTrack(measured, params);
  }
  std::vector<PoseCorrection> corrections(frames.size());
  for (std::size_t n = 0; n < frames.size(); ++n) {
    corrections[n] = measured[n].correction;
    corrections[n].translation_world_m = track[n].head<3>();
    corrections[n].rotation_sonar_rad = track[n].tail<3>();
  }
  return corrections;
}

}  // namespace sonarcarve
