// A noise model learned from a mission's own frames, for the many surveys that record no
// empty water. Returns from structure must not enter it: a pixel's statistics over frames
// are sigma-clipped (structure is bright, so the frames that lit it fall above the median by
// more than 3 robust standard deviations and are left out), and where structure stays at the
// same pixels in most frames (a vertical inspection keeps the riser at one range and bearing),
// the pixel is recognised against the background's smooth, separable shape and given the
// shape's value instead.
//
// Physics behind the shape: the background is reverberation and electronic noise after the
// sonar's time-varying gain, a smooth function of range, times the beam pattern's smooth
// variation across the fan: log level(r, b) = rho(r) + beta(b), fitted by median polish (a
// robust fit that ignores anything covering less than half a row or a column).
//
// Returns that fill a whole range bin across most beams in most frames (a seabed seen at one
// range for the whole mission, as in a lawnmower pitched down) pass both tests; they are told
// by the ratio of mean to standard deviation, which a background's scaled distribution keeps
// the same at every pixel and a speckled return raises, and scaled out of those bins' means.
// Limits: a return as strong as the background in every frame of a bin raises the ratio
// less than its mean would say (its own speckle adds deviation), so some of it stays in the
// model (docs/denoising.md).
#pragma once

#include <vector>

#include "common/progress.h"
#include "denoise/noise_model.h"
#include "io/mission/mission.h"

namespace sonarcarve {

struct MissionNoiseStats {
  std::size_t frames_used = 0;
  double structure_fraction = 0.0;  ///< pixels given the background shape's value
  int full_row_bins = 0;  ///< range bins whose mean a return in most frames raised, scaled out
  double background_median = 0.0;  ///< median over pixels of the learned mean intensity
  double dark_fraction = 0.0;      ///< pixels whose learned mean is 0: dark in most frames
  /// True when the frames carry a background (speckle), which lies over every pixel. Frames
  /// with no background are dark wherever nothing returns: noise-free frames of a riser are
  /// dark almost everywhere, those of a seabed survey at least in the water before the
  /// seabed's first return, while the seabed lights most pixels in every frame.
  bool has_background() const {
    return background_median > 0.0 && dark_fraction <= kMaxDarkFractionWithBackground;
  }
  /// A background may leave this many pixels dark (a sonar that blanks its first range
  /// bins, counts quantised to 0 where the background is lowest).
  static constexpr double kMaxDarkFractionWithBackground = 0.05;
};

/// Fewest frames a model is learned from: a pixel's median and quartiles need three samples;
/// with fewer than about ten the clipping is coarse and the background's fitted shape does
/// most of the work.
inline constexpr std::size_t kMinNoiseFrames = 3;

/// Learns from at most `max_frames` of `frames` (indices into the mission, spread evenly),
/// smoothed with a box of side `smoothing` as the detector will. Broken frames are skipped.
/// Throws Error if fewer than kMinNoiseFrames frames load, and
/// Cancelled if `progress` asks to stop.
NoiseModel learnNoiseFromMission(const Mission& mission, const std::vector<std::size_t>& frames,
                                 int smoothing, Progress& progress,
                                 MissionNoiseStats* stats = nullptr, std::size_t max_frames = 48);

}  // namespace sonarcarve
