// Beam-aware carving's keep level (CarveParams::keep_level), from the mission's own frames:
// a fixed dynamic range below its bright returns. A pixel holds the sum of everything its
// beam meets at that range, off-axis returns weighed down by the beam's pattern (side lobes
// at -13 dB); below the dynamic range, a pixel cannot tell a weak return on its axis from a
// strong one far off it, so such a bound does not keep a voxel.
#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/progress.h"
#include "pipeline/frame_stage.h"
#include "pipeline/run_choice.h"

namespace sonarcarve {

struct KeepLevel {
  double bright_returns = 0.0;  ///< the 99.99th percentile of lit pixels (in `unit`)
  double level = 0.0;           ///< bright_returns lowered by the dynamic range
  std::size_t frames = 0;       ///< frames it was measured on
  /// The level was raised to what a dark pixel of whole counts bounds at the aperture's edge
  /// (effectiveKeepLevel): the bright returns are too faint for the dynamic range.
  bool raised_to_a_count = false;
  /// What the levels are in, for words: a linear sonar's counts, else the power its counts
  /// are read as (sonar/intensity_scale.h).
  std::string unit = "counts";
};

/// The level and how it was derived, for an expert.
std::string describeKeepLevel(const KeepLevel& level, double dynamic_range_db);

/// The run's choice "beam-aware carving": the level and why, for an analyst.
RunChoice keepLevelChoice(const KeepLevel& level, double dynamic_range_db);

/// Measured on the `count` images `image(n)` gives (CV_32F, after the detector; nullopt: left
/// out). Level 0 when no pixel is lit. Cancellable (throws Cancelled).
KeepLevel measureKeepLevel(std::size_t count,
                           const std::function<std::optional<cv::Mat>(std::size_t)>& image,
                           double dynamic_range_db, Progress& progress);

/// Measured on at most `max_frames` of `frames` (spread evenly, after the detector); frames
/// that fail to load are left out.
KeepLevel measureKeepLevel(const DenoisedFrames& source, const std::vector<PosedFrame>& frames,
                           double dynamic_range_db, Progress& progress,
                           std::size_t max_frames = 48);

}  // namespace sonarcarve
