// IntensityScale: how a sonar's pixel counts relate to the echo's power. The engine works in
// linear power: beam-aware carving divides a pixel by the beam's power gain, and the keep level
// is a ratio of powers (docs/carving.md). A sonar that stores its samples on a decibel scale
// (ARIS: bytes 0..255 for 0..80 dB) gives frames that readers convert on loading, and that
// writers and displays convert back to the sonar's own counts. A sonar that compresses its
// samples by a gamma (an Oculus asked for gamma 0.5 sends 8-bit samples of (x / X)^0.5) is
// read back to its linear scale the same way.
//
//   linear:   power = count
//   decibel:  power = 10^(count / full_scale_count * full_scale_db / 10) for count > 0,
//             0 for count 0 (the bottom of the scale: no echo); full scale is
//             10^(full_scale_db / 10)
//   gamma:    power = full_scale_count * (count / full_scale_count)^(1 / gamma): the sonar's
//             linear scale, full scale where its counts are
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <tuple>

namespace sonarcarve {

class IntensityScale {
 public:
  /// The widest decibel scale: its full-scale power, 10^30, fits a float with room to sum.
  static constexpr double kMostDecibels = 300.0;
  /// The largest gamma taken (beyond any sonar's: its counts would hardly move with the echo).
  static constexpr double kLargestGamma = 10.0;

  /// Counts are the echo's power (simulators, most sonars' 16-bit images).
  static IntensityScale linear() { return {}; }
  /// Counts 0..full_scale_count span 0..full_scale_db decibels. Throws Error unless both are
  /// positive and the full scale's power fits a float (at most kMostDecibels).
  static IntensityScale decibel(double full_scale_db, double full_scale_count);
  /// Counts 0..full_scale_count are the linear scale raised to `gamma` (gamma 1 is linear).
  /// Throws Error unless the full scale is positive and gamma at most kLargestGamma and large
  /// enough that half a count is a float over its smallest normal (0.12 for 65,535 counts).
  static IntensityScale gamma(double gamma, double full_scale_count);

  bool isLinear() const { return full_scale_db_ == 0.0 && gamma_ == 0.0; }
  bool isDecibel() const { return full_scale_db_ != 0.0; }
  double fullScaleDb() const { return full_scale_db_; }        ///< 0 unless decibel
  double gammaExponent() const { return gamma_; }              ///< 0 unless gamma
  double fullScaleCount() const { return full_scale_count_; }  ///< 0 if linear
  /// The power under which a pixel reads count 0 (half a count's): what a dark pixel of an
  /// image without noise may hold.
  double darkPower() const;
  /// The power of the full scale's count: 10^(full_scale_db / 10) (decibel), full_scale_count
  /// (gamma); a linear scale has none (0).
  double fullScalePower() const;
  /// In words, for reports: "linear", "decibel (255 counts = 80 dB)" or "gamma 0.5 (255
  /// counts full scale)".
  std::string describe() const;

  /// The echo's power of every count of a CV_32F image (in place; nothing to do if linear).
  /// Decibel counts of 0 or less are no echo: power 0. Throws Error (naming `what`, `place`
  /// if given, and the pixel) on a decibel count over the full scale.
  void countsToPower(cv::Mat& image, const std::string& what, const std::string& place = {}) const;
  /// The sonar's own counts of a CV_32F power image (a new image; a copy if linear). Decibel:
  /// powers of 1 (0 dB) and less, zero included (a detector's cleared pixels), give count 0.
  cv::Mat powerToCounts(const cv::Mat& image) const;

  bool operator==(const IntensityScale&) const = default;
  /// Orders scales (for maps keyed on what frames share).
  using Key = std::tuple<double, double, double>;
  Key key() const { return {full_scale_db_, gamma_, full_scale_count_}; }

 private:
  double full_scale_db_ = 0.0;  ///< 0: not decibel
  double gamma_ = 0.0;          ///< 0: not gamma
  double full_scale_count_ = 0.0;
};

}  // namespace sonarcarve
