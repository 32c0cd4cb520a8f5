// Sonar image noise, realistic and reproducible from a seed:
//  - background: every pixel gets a Rayleigh-distributed amplitude (the envelope of complex
//    Gaussian reverberation) whose mean follows a range- and bearing-dependent level: stronger
//    near the sonar (near-field reverberation) and towards the edges of the fan;
//  - speckle on returns: each return is multiplied by a Gamma variate of mean 1 and shape
//    `looks` (fully developed speckle averaged over `looks` independent looks);
//  - how a return and the background meet in a pixel: added (the return's amplitude plus the
//    background's, the default) or coherent (the envelope of their phasors, the background's
//    phase uniform: a Rician pixel, as a real receiver forms it; a return as strong as the
//    background then raises the pixel's mean by a fraction of itself, not by all of it).
// Beams wider than their spacing (a sonar declaring its horizontal beam width) form both from
// the same scatterers: the background and the speckle are then correlated across bearing as
// the beams' fields overlap. Each is drawn as white complex Gaussian fields filtered across
// bearing by the beam's amplitude pattern (sinc), with the same distribution in each pixel as
// above; the speckle's `looks` are then whole (a fraction is drawn white). Otherwise both are
// white, one draw per pixel.
// An empty-water frame is the background alone: the frames a noise model is learned from.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <random>
#include <string>
#include <vector>

#include "common/enum_names.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// How a return and the background combine in a pixel (see the top of this file).
enum class NoiseCombination { Added, Coherent };
inline constexpr std::array<EnumName<NoiseCombination>, 2> kNoiseCombinationNames{{
    {NoiseCombination::Added, "added"},
    {NoiseCombination::Coherent, "coherent"},
}};
constexpr const auto& enumNamesOf(NoiseCombination) {
  return kNoiseCombinationNames;
}

struct NoiseSpec {
  bool enabled = true;
  double background_mean = 150.0;   ///< mean background amplitude at far range, centre beam
  double near_range_boost = 2.0;    ///< extra background at zero range, as a factor
  double near_range_scale_m = 1.5;  ///< e-folding range of the near-range boost
  double edge_boost = 0.6;          ///< extra background at the edge of the fan, as a factor
  double speckle_looks = 4.0;       ///< Gamma shape of the speckle on returns (>0)
  NoiseCombination combination = NoiseCombination::Added;
  std::uint64_t seed = 1;

  static NoiseSpec none();
  /// The default noise, its returns and background combined coherently.
  static NoiseSpec coherent();
  /// Reads a noise YAML file (keys as the fields above); throws Error naming file and line.
  static NoiseSpec fromYamlFile(const std::string& path);
  std::string toYaml() const;
};

/// Mean background amplitude of a pixel under `spec` (what a noise model should learn).
double backgroundMean(const NoiseSpec& spec, const SonarModel& sonar, int row, int col);

/// Adds noise to a noise-free image, in place, drawing from a stream fixed by the spec's seed
/// and `frame_index` (the same seed and index give the same noise). Values are clamped to
/// [0, 65535], the range frames are stored in.
void addNoise(cv::Mat& image, const NoiseSpec& spec, const SonarModel& sonar,
              std::uint64_t frame_index);

/// addNoise() for many frames of one sonar: the background level of every pixel is computed
/// once, not per frame. The same noise as addNoise().
class FrameNoise {
 public:
  FrameNoise(const NoiseSpec& spec, const SonarModel& sonar);
  /// Throws Error if the image is not the sonar's size. Thread safe.
  void add(cv::Mat& image, std::uint64_t frame_index) const;

 private:
  /// The stream a frame's noise is drawn from, fixed by the seed and the frame.
  std::mt19937_64 frameRandom(std::uint64_t frame_index) const;
  void addWhite(cv::Mat& image, std::uint64_t frame_index) const;
  void addAcrossBeams(cv::Mat& image, std::uint64_t frame_index) const;

  NoiseSpec spec_;
  cv::Mat background_sigma_;  // CV_64F, per pixel: the Rayleigh scale of the background
  // Beams wider than their spacing: the amplitude pattern's weights from beam -h to +h, their
  // squares summing to 1; empty when the beams are not declared wider.
  std::vector<float> field_taps_;
};

}  // namespace sonarcarve
