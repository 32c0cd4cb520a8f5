#include "denoise/mission_noise_model.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace sonarcarve {
namespace {

// Standard deviation of a Gaussian from its interquartile range.
constexpr float kIqrToSigma = 1.0f / 1.349f;
// Samples farther than this many robust standard deviations from the median are clipped.
constexpr float kClipSigmas = 3.0f;
// A pixel brighter than the background's shape by this many robust spreads of the fit's
// residuals is structure.
constexpr double kStructureSpreads = 5.0;
// Range bins over which the ratio of mean to deviation is smoothed (a running median), and
// the rise of that ratio over the background's taken for a return rather than for the ratio's
// sampling error (a bin's median over hundreds of beams and kRatioRows bins: a few tenths of a
// per cent).
constexpr int kRatioRows = 11;
constexpr double kRatioNoise = 0.01;

struct PixelStats {
  float mean = 0.0f;
  float stddev = 0.0f;
};

// Sigma-clipped mean and standard deviation of one pixel's samples (sorted in place).
PixelStats clippedStats(std::vector<float>& v) {
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) { return v[static_cast<std::size_t>(q * (v.size() - 1) + 0.5)]; };
  const float median = at(0.5);
  const float spread = (at(0.75) - at(0.25)) * kIqrToSigma;
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  for (const float x : v) {
    if (std::abs(x - median) <= kClipSigmas * spread) {
      sum += x;
      sum_sq += static_cast<double>(x) * x;
      ++n;
    }
  }
  if (n < 2) {
    return {median, 0.0f};
  }
  const double mean = sum / n;
  const double variance = std::max(0.0, (sum_sq / n - mean * mean) * n / (n - 1));
  // A 3-sigma clip keeps 99.73 % of a Gaussian and shrinks its standard deviation by 1.3 %.
  return {static_cast<float>(mean), static_cast<float>(std::sqrt(variance) / 0.9866)};
}

double median(std::vector<double>& v) {
  if (v.empty()) {
    return 0.0;
  }
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Median polish of log(field) over its positive pixels: log field ~ rho(row) + beta(col).
// Returns the fitted field (0 where a row or column has no positive pixel).
cv::Mat separableFit(const cv::Mat& field) {
  const int rows = field.rows, cols = field.cols;
  std::vector<double> rho(static_cast<std::size_t>(rows), 0.0);
  std::vector<double> beta(static_cast<std::size_t>(cols), 0.0);
  std::vector<double> scratch;
  for (int iteration = 0; iteration < 4; ++iteration) {
    for (int r = 0; r < rows; ++r) {
      scratch.clear();
      for (int c = 0; c < cols; ++c) {
        const float x = field.at<float>(r, c);
        if (x > 0.0f) {
          scratch.push_back(std::log(x) - beta[static_cast<std::size_t>(c)]);
        }
      }
      rho[static_cast<std::size_t>(r)] = scratch.empty() ? -INFINITY : median(scratch);
    }
    for (int c = 0; c < cols; ++c) {
      scratch.clear();
      for (int r = 0; r < rows; ++r) {
        const float x = field.at<float>(r, c);
        if (x > 0.0f && std::isfinite(rho[static_cast<std::size_t>(r)])) {
          scratch.push_back(std::log(x) - rho[static_cast<std::size_t>(r)]);
        }
      }
      beta[static_cast<std::size_t>(c)] = scratch.empty() ? -INFINITY : median(scratch);
    }
  }
  cv::Mat fit(rows, cols, CV_32F);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const double log_level = rho[static_cast<std::size_t>(r)] + beta[static_cast<std::size_t>(c)];
      fit.at<float>(r, c) =
          std::isfinite(log_level) ? static_cast<float>(std::exp(log_level)) : 0.0f;
    }
  }
  return fit;
}

// Returns that fill whole range bins in most frames (a seabed seen at one range for the
// whole survey) pass the clipping above and are learned as background. The background's
// amplitude is one distribution scaled by its level (reverberation and electronic noise after
// the sonar's gain: Rayleigh, mean / deviation 1.91), so the ratio of its mean to its standard
// deviation is the same at every pixel; a weak return with its own speckle adds more to the
// mean than to the deviation and raises it (a seabed 10 % of the background: 1.91 -> 2.09).
// Per range bin the ratio, over the beams' median of the raw frames' pixels and a running
// median over kRatioRows bins, is compared with the background's, taken where it is lowest
// (the 10th percentile of bins: the water before the seabed's first return); a bin whose
// ratio is higher takes the background's fitted shape (`mean_fit`) scaled down by the two
// ratios as its mean. Returns the number of range bins whose ratio is higher by more than
// kRatioNoise.
int scaleOutFullRowReturns(const std::vector<cv::Mat>& raw, const cv::Mat& mean_fit,
                           cv::Mat& mean) {
  const int rows = mean.rows, cols = mean.cols;
  std::vector<float> samples(raw.size());
  std::vector<double> ratio(static_cast<std::size_t>(rows), 0.0), scratch;
  for (int r = 0; r < rows; ++r) {
    scratch.clear();
    for (int c = 0; c < cols; ++c) {
      for (std::size_t k = 0; k < raw.size(); ++k) {
        samples[k] = raw[k].at<float>(r, c);
      }
      const PixelStats s = clippedStats(samples);
      if (s.stddev > 0.0f) {
        scratch.push_back(s.mean / s.stddev);
      }
    }
    ratio[static_cast<std::size_t>(r)] = median(scratch);
  }
  std::vector<double> smoothed(ratio.size());
  for (int r = 0; r < rows; ++r) {
    scratch.assign(ratio.begin() + std::max(0, r - kRatioRows / 2),
                   ratio.begin() + std::min(rows, r + kRatioRows / 2 + 1));
    smoothed[static_cast<std::size_t>(r)] = median(scratch);
  }
  scratch = smoothed;
  std::sort(scratch.begin(), scratch.end());
  const double background = scratch[scratch.size() / 10];
  if (!(background > 0.0)) {
    return 0;
  }
  // Every bin over the background's ratio is scaled: a bin of background alone by its
  // ratio's sampling error, a few tenths of a per cent (a threshold of 1 % left the seabed's
  // far bins, where it returns a few per cent of the background, in the model: noisy
  // manifold 0.401 against 0.468). Bins higher by more than kRatioNoise are counted.
  int scaled = 0;
  for (int r = 0; r < rows; ++r) {
    const double k = smoothed[static_cast<std::size_t>(r)];
    if (k > background) {
      for (int c = 0; c < cols; ++c) {
        mean.at<float>(r, c) = static_cast<float>(mean_fit.at<float>(r, c) * background / k);
      }
      scaled += k > background * (1.0 + kRatioNoise) ? 1 : 0;
    }
  }
  return scaled;
}

}  // namespace

NoiseModel learnNoiseFromMission(const Mission& mission, const std::vector<std::size_t>& frames,
                                 int smoothing, Progress& progress, MissionNoiseStats* stats,
                                 std::size_t max_frames) {
  const int rows = mission.sonar.rows(), cols = mission.sonar.cols();
  const std::size_t wanted = std::min(frames.size(), std::max<std::size_t>(max_frames, 1));
  std::vector<cv::Mat> images, raw_images;
  for (std::size_t k = 0; k < wanted; ++k) {
    if (progress.cancelled()) {
      throw Cancelled();
    }
    // Evenly spread over the mission: structure moves through the image along the track.
    const std::size_t index = frames[k * frames.size() / wanted];
    try {
      const cv::Mat raw = loadFrame(mission, index).image;
      images.push_back(smoothFrame(raw, smoothing).clone());
      raw_images.push_back(raw.clone());
    } catch (const Error&) {
      continue;  // the carving stage reports broken frames
    }
    progress.report("noise model", k + 1, wanted);
  }
  if (images.size() < kMinNoiseFrames) {
    throw Error(mission.folder.string(), "noise model",
                "only " + std::to_string(images.size()) + " frames could be read: at least " +
                    std::to_string(kMinNoiseFrames) +
                    " are needed to learn the noise from the mission itself; give an "
                    "empty-water noise model (--noise-model)");
  }

  cv::Mat mean(rows, cols, CV_32F), stddev(rows, cols, CV_32F);
  std::vector<float> samples(images.size());
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      for (std::size_t k = 0; k < images.size(); ++k) {
        samples[k] = images[k].at<float>(r, c);
      }
      const PixelStats s = clippedStats(samples);
      mean.at<float>(r, c) = s.mean;
      stddev.at<float>(r, c) = s.stddev;
    }
  }

  // Pixels lit by structure in most frames stand out above the background's shape.
  const cv::Mat mean_fit = separableFit(mean);
  const cv::Mat stddev_fit = separableFit(stddev);
  std::vector<double> residuals;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      if (mean.at<float>(r, c) > 0.0f && mean_fit.at<float>(r, c) > 0.0f) {
        residuals.push_back(std::log(mean.at<float>(r, c) / mean_fit.at<float>(r, c)));
      }
    }
  }
  std::size_t replaced = 0;
  if (!residuals.empty()) {
    const double centre = median(residuals);
    for (double& d : residuals) {
      d = std::abs(d - centre);
    }
    const double spread = 1.4826 * median(residuals);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        const float fitted = mean_fit.at<float>(r, c);
        if (fitted > 0.0f && std::log(std::max(mean.at<float>(r, c), 1e-30f) / fitted) - centre >
                                 kStructureSpreads * spread) {
          mean.at<float>(r, c) = fitted;
          stddev.at<float>(r, c) = stddev_fit.at<float>(r, c);
          ++replaced;
        }
      }
    }
  }
  const int seabed_rows = scaleOutFullRowReturns(raw_images, mean_fit, mean);
  cv::Mat second = mean.mul(mean) + stddev.mul(stddev);
  cv::Mat sigma;
  cv::sqrt(second / 2.0, sigma);
  if (stats != nullptr) {
    stats->frames_used = images.size();
    stats->structure_fraction = static_cast<double>(replaced) / (static_cast<double>(rows) * cols);
    stats->full_row_bins = seabed_rows;
    std::vector<double> levels(mean.begin<float>(), mean.end<float>());
    stats->background_median = median(levels);
    stats->dark_fraction = static_cast<double>(std::count(levels.begin(), levels.end(), 0.0)) /
                           static_cast<double>(levels.size());
  }
  return NoiseModel(mean, stddev, sigma, mission.sonar, static_cast<int>(images.size()), smoothing);
}

}  // namespace sonarcarve
