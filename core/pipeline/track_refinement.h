// Pose refinement in post-processing (issue 15): every frame is aligned to a COMPLETE map
// carved from the whole mission, and the corrections are solved jointly over the track.
//   1. Carve every frame at its current pose. In the first pass each frame's lit returns are
//      widened by `first_pass_tolerance_m` in range and across beams (grey dilation), so a
//      frame only carves where the image is dark that far around: true surface survives views
//      placed that far off each other, and the map is fat but complete.
//   2. Measure every frame against that map (carve/pose_refiner.h), searched from its current
//      correction, its measured leading edges widened as the map's frames were (compared like
//      with like: without drift a frame agrees with the fat map at its own pose), residuals
//      capped at the tolerance.
//   3. Solve the correction track from all measurements and the navigation's random-walk model
//      (carve/track_smoother.h), then carve again; `passes` times, each pass's tolerance half
//      the one before.
// The final carving at the refined poses is the carving stage's own.
#pragma once

#include <vector>

#include "carve/carver.h"
#include "carve/pose_refiner.h"
#include "common/progress.h"
#include "pipeline/frame_stage.h"

namespace sonarcarve {

struct TrackRefinementSetup {
  const SonarModel& sonar;
  CarverEngine engine;
  CarveParams carve;  ///< with the map's region set
  PoseRefinementParams params;
  ThreadPool& pool;
};

/// The last pass's measurement of every frame with its correction replaced by the smoothed
/// track's (frames that fail to load are measured as not aligned; the stage skips them), or
/// empty when cancelled.
std::vector<PoseCorrection> refineTrack(const TrackRefinementSetup& setup,
                                        const std::vector<PosedFrame>& frames,
                                        const DenoisedFrames& source, Progress& progress);

/// The image with its lit returns widened by `radius_bins` range bins and `radius_beams`
/// beams each way (grey dilation: each pixel takes the brightest value around it).
cv::Mat widenedReturns(const cv::Mat& image, int radius_bins, int radius_beams);

}  // namespace sonarcarve
