// Reading how wide a sonar's beams are from its frames, for logs that do not say.
//
// Each image row is the scene's returns across bearing blurred by the beams' power pattern. A
// sinc^2 pattern (a uniform aperture's) whose -3 dB width is w passes no spatial frequency
// above 0.8845 / w cycles per radian: its spectrum is a triangle, the aperture's
// autocorrelation. Beams wider than their spacing put that cutoff under the Nyquist frequency
// of the beam spacing (0.5 cycles per beam) once they are about 1.8 spacings wide, and the
// rows' summed power spectrum then bends down at the cutoff, whatever the scene: it falls 14 dB
// an octave more there than under it with noise formed by the beams, 23 to 37 dB without,
// where a scene's own spectrum (an edge's falls 6 dB an octave) bends 1 to 4 dB. The
// width is the one whose blur kernel's spectrum (sonar/bearing_deblur.h) falls most steeply
// at the same frequency.
//
// What it cannot read, and then finds nothing and says why:
//   beams under about 2.5 spacings wide (the cutoff must lie an octave's half under Nyquist
//   for its fall to be measured);
//   noise added after the beams are formed, white across bearing (a simulator's that draws
//   each pixel's independently), which hides the fall; likewise saturated or coarsely
//   quantised frames.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "sonar/bearing_table.h"

namespace sonarcarve {

/// The power spectrum across bearing of a mission's image rows, summed over the rows added
/// (so that bright rows, least touched by rounding, weigh most).
class BearingSpectrum {
 public:
  explicit BearingSpectrum(int beams);
  /// Adds every row of a CV_32F power image `beams` wide; throws Error otherwise.
  void add(const cv::Mat& image);
  int beams() const { return beams_; }
  /// Power per frequency bin k = 0 .. beams / 2 (k / beams cycles per beam), rows' means out.
  const std::vector<double>& power() const { return power_; }

 private:
  int beams_;
  cv::Mat window_;  // Hann, 1 x beams
  std::vector<double> power_;
};

struct BeamWidthEstimate {
  double width_rad = 0.0;  ///< -3 dB width found; 0: none
  double cutoff = 0.0;     ///< cycles per beam where the spectrum falls most steeply
  double drop_db = 0.0;    ///< how far it falls over the octave about there
  double knee_db = 0.0;    ///< drop_db less its fall over the octave under that
  std::string reason;      ///< what was found, or why nothing was, in words
};

/// Reads the beams' width from a spectrum of the sonar's frames (see the top of this file).
BeamWidthEstimate estimateBeamWidth(const BearingSpectrum& spectrum, const BearingTable& table);

}  // namespace sonarcarve
