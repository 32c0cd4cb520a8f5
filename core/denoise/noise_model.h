// NoiseModel: per-pixel statistics of empty-water frames (the seed paper's noise model).
// For every pixel: mean and standard deviation of the intensity, and the Rayleigh scale
// sigma = sqrt(E[I^2] / 2) that fits the speckle of sonar backgrounds (the envelope of
// Gaussian reverberation is Rayleigh distributed). It is bound to the geometry it was
// learned with: applying it to another sonar model is an error.
//
// File (OpenCV FileStorage YAML, docs/formats.md): format, version, frames, the geometry
// (rows, cols, range_min_m, range_resolution_m, bearings_rad, vertical_aperture_rad), the
// intensity scale the frames were read on (intensity_full_scale_db and _count, both 0 or
// absent for linear: the statistics are of power), the smoothing the frames got, and the
// matrices mean, stddev, rayleigh_sigma (CV_32F).
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "common/progress.h"
#include "io/mission/mission.h"

namespace sonarcarve {

class NoiseModel {
 public:
  /// Learns from every frame of an empty-water mission; throws Error if fewer than 2 frames
  /// load. Broken frames are skipped (listed in `skipped` when given).
  /// `smoothing`: side of the box filter applied to every frame first (1 = none); a
  /// detector must smooth frames the same way (see Detector).
  static NoiseModel learn(const Mission& empty_water, Progress& progress,
                          std::vector<FrameProblem>* skipped = nullptr, int smoothing = 1);
  /// Throws Error naming the file and what was expected.
  static NoiseModel load(const std::filesystem::path& path);
  void save(const std::filesystem::path& path) const;

  /// Throws Error if `sonar` does not have the geometry the model was learned with.
  void checkGeometry(const SonarModel& sonar, const std::string& what) const;

  const cv::Mat& mean() const { return mean_; }
  const cv::Mat& stddev() const { return stddev_; }
  const cv::Mat& rayleighSigma() const { return rayleigh_sigma_; }
  int frames() const { return frames_; }
  int smoothing() const { return smoothing_; }

  /// A model from given statistics (tests, other learners). All CV_32F of one size.
  NoiseModel(cv::Mat mean, cv::Mat stddev, cv::Mat rayleigh_sigma, const SonarModel& sonar,
             int frames, int smoothing = 1);

 private:
  NoiseModel() = default;
  cv::Mat mean_, stddev_, rayleigh_sigma_;
  double range_min_m_ = 0.0;
  double range_resolution_m_ = 0.0;
  std::vector<double> bearings_rad_;
  double vertical_aperture_rad_ = 0.0;
  IntensityScale intensity_scale_;
  int frames_ = 0;
  int smoothing_ = 1;
};

/// The largest box filter frames are smoothed by (detector.smoothing, noise models): 255 x 255.
inline constexpr int kMaxSmoothingWindow = 255;
/// What is wrong with `size` as the side of that box filter (odd, from 1 to
/// kMaxSmoothingWindow), in words ending with what was expected; nothing when it is valid.
std::optional<std::string> smoothingProblem(int size);

/// The box filter (side `size`, odd, 1 = none) detectors and noise models apply to frames:
/// averaging `size` x `size` pixels of independent speckle divides its variance by size^2.
cv::Mat smoothFrame(const cv::Mat& image, int size);

}  // namespace sonarcarve
