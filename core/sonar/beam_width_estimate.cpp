#include "sonar/beam_width_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/angles.h"
#include "common/error.h"
#include "common/quantile.h"
#include "sonar/bearing_deblur.h"

namespace sonarcarve {
namespace {

// The cutoff is looked for above this many cycles per beam (a scene's own largest features
// dominate under it) ...
constexpr double kLowBand = 0.05;
// ... and half an octave under the Nyquist frequency at most, so that its fall can be
// measured over the octave about it.
constexpr double kHalfOctave = 1.41421356;
// Band-limited rows: their spectrum falls this much more over the octave about its cutoff
// than over the octave under that. A scene's own spectrum bends little: 1 to 4 dB in our
// scenes with beams as wide as their spacing. A cutoff bends it 14 dB (with noise formed by
// the beams) to 23 to 37 dB (without).
constexpr double kMinKneeDb = 10.0;
// Within an octave of Nyquist (above 0.25 cycles per beam), beams too narrow to cut off
// under Nyquist still bend the spectrum by their triangle's slope: 0.3 degree beams 0.2
// degree apart bend it 8 dB there. A margin: a cutoff there must bend it this much.
constexpr double kMinKneeNearNyquistDb = 20.0;
// Widths are searched up to this many beam spacings: a wider beam's cutoff lies within the
// low band, under kLowBand cycles per beam (0.8845 / 20 = 0.044).
constexpr double kWidestInSpacings = 20.0;

double toDb(double ratio) {
  return 10.0 * std::log10(std::max(ratio, 1e-300));
}

// The spectrum at bin k in decibels, averaged over the bins k - m .. k + m (bin 0 and the
// Nyquist bin, which the window halves, left out).
double smoothedDb(const std::vector<double>& power, int k, int m) {
  const int top = static_cast<int>(power.size()) - 2;
  double sum = 0.0;
  int count = 0;
  for (int j = std::max(1, k - m); j <= std::min(top, k + m); ++j, ++count) {
    sum += power[static_cast<std::size_t>(j)];
  }
  return toDb(count > 0 ? sum / count : 0.0);
}

// The bin among [from, to] where the smoothed spectrum falls most steeply in decibels: a
// band-limited spectrum's cutoff, which an object's smooth decay or a floor's level hardly
// moves.
int steepestFall(const std::vector<double>& power, int from, int to, int m) {
  int steepest = from;
  double fall = 0.0;
  for (int k = from; k <= to; ++k) {
    const double slope = smoothedDb(power, k + m, m) - smoothedDb(power, k - m, m);
    if (slope < fall) {
      fall = slope;
      steepest = k;
    }
  }
  return steepest;
}

// The blur kernel's power spectrum at the bins of an n-beam row, as a Hann-windowed row shows
// a broadband scene through it: spread over the window's power response (1/4 in the bin,
// 1/16 in each neighbour).
std::vector<double> kernelPower(double width_rad, double spacing_rad, int n) {
  const std::vector<float> k = bearingBlurKernel(width_rad, spacing_rad, n - 1);
  const int half = static_cast<int>(k.size() / 2);
  std::vector<double> power(static_cast<std::size_t>(n / 2 + 1));
  for (std::size_t bin = 0; bin < power.size(); ++bin) {
    double h = 0.0;
    for (int d = -half; d <= half; ++d) {
      h += k[static_cast<std::size_t>(d + half)] *
           std::cos(2.0 * std::numbers::pi * static_cast<double>(bin) * d / n);
    }
    power[bin] = h * h;
  }
  std::vector<double> seen(power.size());
  for (std::size_t bin = 0; bin < power.size(); ++bin) {
    const double below = power[bin > 0 ? bin - 1 : 1];  // the spectrum is even about 0
    const double above = bin + 1 < power.size() ? power[bin + 1] : power[bin - 1];
    seen[bin] = 0.25 * power[bin] + 0.0625 * (below + above);
  }
  return seen;
}

}  // namespace

BearingSpectrum::BearingSpectrum(int beams)
    : beams_(beams), window_(1, beams, CV_32F), power_(static_cast<std::size_t>(beams / 2 + 1)) {
  for (int c = 0; c < beams; ++c) {
    window_.at<float>(c) =
        static_cast<float>(0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (c + 0.5) / beams));
  }
}

void BearingSpectrum::add(const cv::Mat& image) {
  if (image.type() != CV_32FC1 || image.cols != beams_) {
    throw Error("beam width", "frame",
                "expected a float image " + std::to_string(beams_) + " beams wide");
  }
  // The rows that hold anything, their means out and windowed (a dark row adds nothing).
  cv::Mat rows(image.rows, beams_, CV_32F);
  int count = 0;
  const float* window = window_.ptr<float>(0);
  for (int r = 0; r < image.rows; ++r) {
    const float* in = image.ptr<float>(r);
    if (!std::any_of(in, in + beams_, [&](float v) { return v != in[0]; })) {
      continue;
    }
    const double mean = cv::mean(image.row(r))[0];
    float* out = rows.ptr<float>(count++);
    for (int c = 0; c < beams_; ++c) {
      out[c] = (in[c] - static_cast<float>(mean)) * window[c];
    }
  }
  if (count == 0) {
    return;
  }
  // Real transforms, packed (CCS): Re 0, then Re k, Im k for k = 1 ..., then Re n/2 if n
  // is even.
  cv::Mat spectrum;
  cv::dft(rows.rowRange(0, count), spectrum, cv::DFT_ROWS);
  const int last = static_cast<int>(power_.size()) - 1;
  for (int r = 0; r < count; ++r) {
    const float* z = spectrum.ptr<float>(r);
    power_[0] += static_cast<double>(z[0]) * z[0];
    for (int k = 1; k <= last; ++k) {
      const int re = 2 * k - 1;
      if (re + 1 < beams_) {
        power_[static_cast<std::size_t>(k)] +=
            static_cast<double>(z[re]) * z[re] + static_cast<double>(z[re + 1]) * z[re + 1];
      } else {  // the Nyquist bin of an even row: real
        power_[static_cast<std::size_t>(k)] += static_cast<double>(z[re]) * z[re];
      }
    }
  }
}

BeamWidthEstimate estimateBeamWidth(const BearingSpectrum& spectrum, const BearingTable& table) {
  BeamWidthEstimate estimate;
  const std::vector<double>& s = spectrum.power();
  const int n = spectrum.beams();
  const int m = std::max(1, n / 128);
  const int from = std::max(m + 1, static_cast<int>(kLowBand * n));
  const int top = n / 2 - 1 - m;  // the highest bin whose smoothing stays under Nyquist
  const int to = static_cast<int>(top / kHalfOctave);
  if (to <= from + m) {
    estimate.reason = "too few beams for a spectrum across bearing";
    return estimate;
  }
  if (*std::max_element(s.begin() + 1, s.end()) <= 0.0) {
    estimate.reason = "the frames hold no returns";
    return estimate;
  }
  // The cutoff: where the spectrum falls most steeply, and by how much over an octave.
  const int cut = steepestFall(s, from, top - m, m);
  estimate.cutoff = static_cast<double>(cut) / n;
  char text[240];
  if (cut > to) {
    std::snprintf(text, sizeof text,
                  "the rows' spectrum falls most steeply at %.3f cycles per beam, "
                  "within an octave's half of Nyquist: beams under about 2.5 spacings wide, or "
                  "none",
                  estimate.cutoff);
    estimate.reason = text;
    estimate.cutoff = 0.0;
    return estimate;
  }
  const auto level = [&](double k) { return smoothedDb(s, static_cast<int>(std::lround(k)), m); };
  estimate.drop_db = level(cut / kHalfOctave) - level(cut * kHalfOctave);
  estimate.knee_db =
      estimate.drop_db - (level(cut / (2.0 * kHalfOctave)) - level(cut / kHalfOctave));
  const bool near_nyquist = cut > n / 4;
  const double min_knee = near_nyquist ? kMinKneeNearNyquistDb : kMinKneeDb;
  if (estimate.knee_db < min_knee) {
    std::snprintf(text, sizeof text,
                  "the rows are not band-limited across bearing (where their spectrum "
                  "falls most steeply, %.3f cycles per beam, it bends by %.0f dB; a cutoff there "
                  "bends it %.0f dB or more)",
                  estimate.cutoff, estimate.knee_db, min_knee);
    estimate.reason = text;
    estimate.cutoff = 0.0;
    return estimate;
  }
  // The width whose kernel's spectrum falls most steeply there (lower as the width grows):
  // searched over widths 1 % apart, from twice the spacing.
  const double spacing = table.medianSpacing();
  const double widest = std::min(table.fieldOfView(), kWidestInSpacings * spacing);
  int best_gap = n;
  // Each width's spectrum as the rows would show it: its kernel's, as bright as the rows'
  // an octave under the cutoff, over the rows' floor (the counts' rounding, or noise), which
  // draws the steepest fall down a little when it lies near.
  std::vector<double> floor_band(s.begin() + top - top / 8, s.begin() + top + 1);
  const double floor = quantile(floor_band, 0.5);
  const int under = std::max(1, cut / 2);
  const double rows_under = std::pow(10.0, smoothedDb(s, under, m) / 10.0);
  // Widths that tie (their kernels fall most steeply in the same bin): the geometric middle.
  double tied_first = 0.0, tied_last = 0.0;
  for (double width = 2.0 * spacing; width < widest; width *= 1.01) {
    std::vector<double> model = kernelPower(width, spacing, n);
    const double scale = rows_under / std::pow(10.0, smoothedDb(model, under, m) / 10.0);
    for (double& p : model) {
      p = scale * p + floor;
    }
    const int gap = std::abs(steepestFall(model, from, top - m, m) - cut);
    if (gap < best_gap) {
      best_gap = gap;
      tied_first = width;
    }
    if (gap == best_gap) {
      tied_last = width;
    }
  }
  if (best_gap > m) {
    std::snprintf(text, sizeof text,
                  "the rows' spectrum falls most steeply at %.3f cycles per beam, "
                  "where no beam from twice the spacing to %.0f times it cuts off",
                  estimate.cutoff, kWidestInSpacings);
    estimate.reason = text;
    estimate.cutoff = 0.0;
    return estimate;
  }
  estimate.width_rad = std::sqrt(tied_first * tied_last);
  std::snprintf(text, sizeof text,
                "%.2f degree beams: the rows cut off across bearing at %.3f cycles per beam "
                "(falling %.0f dB over an octave, %.0f dB more than under it)",
                radToDeg(estimate.width_rad), estimate.cutoff, estimate.drop_db, estimate.knee_db);
  estimate.reason = text;
  return estimate;
}

}  // namespace sonarcarve
