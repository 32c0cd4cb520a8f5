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

// Behind a Z-test a leading edge stands this many standard deviations of the raw background
// above its mean (a kept pixel carries its estimate less the mean). Against the noise-free
// frames of the same poses (riser, 10 frames): at the keep level alone 2,643 beams begin at a
// false alarm and 610 match; at two deviations 83 false and 627 matching; at three 1 false and
// 462 matching within 2 bins (docs/navigation.md).
constexpr double kEdgeBackgroundSigmas = 3.0;

// Per pixel, the level a return must pass to begin a leading edge; empty without a detector
// that knows its background.
cv::Mat edgeLevel(const DenoisedFrames& source, double keep_level) {
  const cv::Mat sigma = source.detector().backgroundSigma();
  if (sigma.empty()) {
    return {};
  }
  cv::Mat level = cv::max(sigma * kEdgeBackgroundSigmas, keep_level);
  return level;
}

// The frame as the alignment sees it: only returns over the edge level.
cv::Mat returnsOverLevel(const cv::Mat& image, const cv::Mat& level) {
  if (level.empty()) {
    return image;
  }
  cv::Mat out(image.size(), CV_32F, cv::Scalar(0.0f));
  image.copyTo(out, image > level);
  return out;
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
  const cv::Mat level = edgeLevel(source, carve.keep_level);
  double tolerance = params.first_pass_tolerance_m;
  for (int pass = 0; pass < params.passes; ++pass, tolerance *= 0.5) {
    const int bins = static_cast<int>(std::lround(tolerance / resolution));
    const int beams = static_cast<int>(std::lround(tolerance / beam_arc));
    auto carver = makeCarver(setup.engine, CarverSetup{setup.sonar, carve, setup.pool});
    if (carver->blockMap() == nullptr) {
      throw Error("parameters", "pose_refinement", "pose refinement needs the fast engine");
    }
    const std::string stage = "align " + std::to_string(pass + 1);
    std::vector<Eigen::Isometry3d> poses;
    poses.reserve(frames.size());
    for (std::size_t n = 0; n < frames.size(); ++n) {
      poses.push_back(PoseCorrection::of(track[n]).applied(frames[n].T_world_sonar));
    }
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
      carver->integrate(widenedReturns(returnsOverLevel(frame.image, level), bins, beams), poses[n],
                        static_cast<std::uint32_t>(n + 1));
      progress.report(stage, n + 1, 2 * frames.size());
    }
    PoseRefiner refiner(*carver->blockMap(), setup.sonar, carve, params, setup.pool);
    refiner.setEdgeLevel(level);
    // Edges are predicted only from voxels that enough frames see, as occlusion resolution
    // takes surface points: behind a detector what few frames see stays in the map uncarved
    // (dark pixels carve only inside +-aperture/2), and the background near the sonar would
    // predict edges in most beams.
    refiner.keepVoxelsSeenBy(poses);
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
      measured[n] = refiner.measure(returnsOverLevel(frame.image, level), frames[n].T_world_sonar,
                                    track[n], scale, EdgeWidening{bins, beams});
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
