#include "fit/map_fit.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "common/error.h"
#include "fit/adam.h"
#include "fit/beam_background_fit.h"
#include "model/forward_model.h"
#include "model/speckle_likelihood.h"

namespace sonarcarve {
namespace {

constexpr double kLogitLearningRate = 1.0;
constexpr double kReflectanceLearningRate = 0.2;
constexpr double kFinalLearningRateShare = 0.3;  // of the first, at the last step
// Reflectance within 10 dB of the start's either way (the gain makes the start's 1 the
// mean): a surface brighter than that would rather be a faint haze of high reflectance in
// front of it, which explains the returns without occluding what lies behind.
constexpr double kMinReflectance = 0.1;
constexpr double kMaxReflectance = 10.0;
constexpr float kMinLogit = -12.0f;
constexpr float kMaxLogit = 12.0f;
// Frames spread over the mission that set the background's floor and the gain and on which
// the fit's figures are measured (before and after), so that they cost no full pass.
constexpr int kSampleFrames = 16;
// A step's gradient traces every second beam, the next step the others: half the rays a step,
// every beam in two (neighbouring beams see nearly the same surface).
constexpr int kStepBeamStride = 2;
// The background's floor, as a share of the brightest returns (99th percentile of the pixels
// that return anything): the smallest mean the speckle model may predict.
constexpr double kFloorShare = 1e-3;

cv::Mat asDouble(const cv::Mat& image) {
  cv::Mat out;
  image.convertTo(out, CV_64F);
  return out;
}

cv::Mat backgroundImage(const std::vector<double>& background, int cols) {
  cv::Mat image(static_cast<int>(background.size()), cols, CV_64F);
  for (int row = 0; row < image.rows; ++row) {
    image.row(row).setTo(background[static_cast<std::size_t>(row)]);
  }
  return image;
}

// Frames spread evenly over the mission, at most `count`.
std::vector<std::size_t> spread(std::size_t size, std::size_t count) {
  std::vector<std::size_t> picks;
  const std::size_t n = std::min(size, count);
  for (std::size_t k = 0; k < n; ++k) {
    picks.push_back(k * size / n);
  }
  return picks;
}

double brightReturn(const std::vector<cv::Mat>& images) {
  std::vector<float> values;
  for (const cv::Mat& image : images) {
    for (int row = 0; row < image.rows; ++row) {
      const auto* p = image.ptr<float>(row);
      for (int col = 0; col < image.cols; ++col) {
        if (p[col] > 0.0f) {
          values.push_back(p[col]);
        }
      }
    }
  }
  if (values.empty()) {
    return 1.0;
  }
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(values.size() * 99 / 100);
  std::nth_element(values.begin(), at, values.end());
  return std::max(1e-12, static_cast<double>(*at));
}

}  // namespace

ElevationProfile declaredProfile(const SonarModel& sonar) {
  if (sonar.elevationBeam() == ElevationBeam::Clipped) {
    return ElevationProfile::clipped(sonar.beamPattern(), sonar.beamPattern().firstNull(), 9);
  }
  const SincSquaredBeam beam(sonar.verticalAperture());
  return ElevationProfile::sincSquared(sonar.verticalAperture(), beam.null(2), 13);
}

MapFit::MapFit(const SonarModel& sonar, MapFitParams params, ThreadPool& pool)
    : sonar_(sonar), params_(params), pool_(pool) {
  if (params_.passes < 0 || params_.frames_per_step < 1 || params_.band_voxels < 0 ||
      !(params_.elevation_step_rad > 0.0)) {
    throw Error("map fit", "settings",
                "expected passes >= 0, frames_per_step >= 1, band_voxels >= 0 and a positive "
                "elevation step");
  }
}

MapFitSummary MapFit::run(FitGrid& fit, const std::vector<MapFitFrame>& frames,
                          const FrameImageLoader& load, std::vector<double> background,
                          Progress& progress) const {
  BlockGrid& grid = fit.grid;
  MapFitSummary summary;
  summary.band_voxels =
      static_cast<std::size_t>(std::count(fit.in_band.begin(), fit.in_band.end(), 1));
  if (frames.empty() || summary.band_voxels == 0) {
    return summary;
  }
  ModelSettings settings;
  settings.elevation_step_rad = params_.elevation_step_rad;
  settings.samples_per_bin = params_.samples_per_bin;
  const ForwardModel model(sonar_, settings, pool_);

  // The background, raised to a floor; the gain from the frames' energy where the map returns.
  const std::vector<std::size_t> sampled = spread(frames.size(), kSampleFrames);
  std::vector<cv::Mat> sample;
  for (const std::size_t k : sampled) {
    sample.push_back(load(frames[k].index));
  }
  background.resize(static_cast<std::size_t>(sonar_.rows()), 0.0);
  summary.background_floor = kFloorShare * brightReturn(sample);
  for (double& b : background) {
    b = std::max(b, summary.background_floor);
  }
  const cv::Mat background_image = backgroundImage(background, sonar_.cols());
  FrameView view{Eigen::Isometry3d::Identity(), declaredProfile(sonar_), 1.0, {}};
  double observed = 0.0;
  double predicted = 0.0;
  // The sampled frames' returns at unit gain: the frames before the fit are these times the
  // gain, plus the background.
  std::vector<cv::Mat> unit_returns;
  for (std::size_t s = 0; s < sample.size(); ++s) {
    view.T_world_sonar = frames[sampled[s]].T_world_sonar;
    const cv::Mat returned = model.predict(grid, view);
    unit_returns.push_back(returned);
    const cv::Mat excess = cv::max(asDouble(sample[s]) - background_image, 0.0);
    cv::Mat where_returned;
    cv::Mat(returned > 0.0).convertTo(where_returned, CV_64F, 1.0 / 255.0);
    observed += cv::sum(excess.mul(where_returned))[0];
    predicted += cv::sum(returned)[0];
  }
  view.gain = predicted > 0.0 ? observed / predicted : 1.0;
  view.background = background;
  summary.gain = view.gain;
  summary.declared_profile = view.profile;
  const auto mean = [](const std::vector<double>& values) {
    return std::accumulate(values.begin(), values.end(), 0.0) /
           static_cast<double>(std::max<std::size_t>(1, values.size()));
  };
  summary.declared_background = mean(view.background);
  BeamBackgroundFit view_fit(view, summary.background_floor, {params_.beam, params_.background});

  std::vector<float> log_reflectance(grid.voxelCount());
  for (std::size_t i = 0; i < log_reflectance.size(); ++i) {
    log_reflectance[i] = std::log(std::max(grid.reflectance()[i], 1e-6f));
  }
  AdamState logit_steps(grid.voxelCount());
  AdamState reflectance_steps(grid.voxelCount());
  const auto per_step = static_cast<std::size_t>(params_.frames_per_step);
  const std::size_t steps_per_pass = (frames.size() + per_step - 1) / per_step;
  const std::size_t total_steps = steps_per_pass * static_cast<std::size_t>(params_.passes);
  const std::size_t work =
      frames.size() * static_cast<std::size_t>(params_.passes) + 2 * sampled.size();
  std::size_t done = 0;

  // Sum of |observed - background| over the sampled frames, for the figures' ratio.
  double returns = 0.0;
  FrameTrace trace;
  auto score = [&](const cv::Mat& prediction, const cv::Mat& image, FitPassFigures& figures,
                   cv::Mat* dloss) {
    figures.nll_per_pixel += speckleNll(prediction, image, dloss);
    figures.unexplained += cv::norm(image, prediction, cv::NORM_L1);
  };
  // One look at a frame: its figures, and the gradient when asked.
  auto look = [&](const ForwardModel& with, const MapFitFrame& frame, FitPassFigures& figures,
                  ModelGradient* gradient) {
    if (progress.cancelled()) {
      throw Cancelled();
    }
    view.T_world_sonar = frame.T_world_sonar;
    // With a gradient to take, one march serves the prediction and the gradient.
    if (gradient) {
      with.trace(grid, view, trace);
    }
    const cv::Mat prediction = gradient ? with.predict(trace, view) : with.predict(grid, view);
    cv::Mat dloss;
    score(prediction, asDouble(load(frame.index)), figures, gradient ? &dloss : nullptr);
    if (gradient) {
      gradient->add(with.gradient(trace, grid, view, dloss));
    }
    progress.report("fit", ++done, work);
  };
  auto finish = [&](FitPassFigures figures) {
    figures.nll_per_pixel /= static_cast<double>(sampled.size()) * sonar_.rows() * sonar_.cols();
    figures.unexplained /= std::max(returns, 1e-300);
    return figures;
  };
  FitPassFigures before;
  for (std::size_t s = 0; s < sample.size(); ++s) {
    const cv::Mat image = asDouble(sample[s]);
    score(unit_returns[s] * view.gain + background_image, image, before, nullptr);
    returns += cv::norm(image, background_image, cv::NORM_L1);
    progress.report("fit", ++done, work);
  }
  unit_returns.clear();
  summary.before = finish(before);

  std::vector<std::size_t> order(frames.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937 shuffle(1);
  std::size_t step = 0;
  for (int pass = 0; pass < params_.passes; ++pass) {
    std::shuffle(order.begin(), order.end(), shuffle);
    FitPassFigures during;  // the figures as the steps go; not reported
    for (std::size_t first = 0; first < order.size(); first += per_step) {
      ModelGradient gradient(grid.voxelCount(), view.profile.knotsDb().size(), background.size());
      ModelSettings some_beams = settings;
      some_beams.beam_stride = kStepBeamStride;
      some_beams.beam_offset = static_cast<int>(step % kStepBeamStride);
      const ForwardModel step_model(sonar_, some_beams, pool_);
      const std::size_t last = std::min(order.size(), first + per_step);
      for (std::size_t k = first; k < last; ++k) {
        look(step_model, frames[order[k]], during, &gradient);
      }
      const double share = 1.0 - (1.0 - kFinalLearningRateShare) * static_cast<double>(step) /
                                     static_cast<double>(std::max<std::size_t>(1, total_steps - 1));
      ++step;
      logit_steps.step(grid.logits(), gradient.logits, fit.in_band, kLogitLearningRate * share,
                       kMinLogit, kMaxLogit);
      view_fit.step(view, gradient,
                    static_cast<double>(last - first) * sonar_.rows() * sonar_.cols(), share);
      for (std::size_t i = 0; i < gradient.reflectance.size(); ++i) {
        gradient.reflectance[i] *= grid.reflectance()[i];  // d / d log(rho)
      }
      reflectance_steps.step(log_reflectance, gradient.reflectance, fit.in_band,
                             kReflectanceLearningRate * share, std::log(kMinReflectance),
                             std::log(kMaxReflectance));
      for (std::size_t i = 0; i < log_reflectance.size(); ++i) {
        if (fit.in_band[i] != 0) {
          grid.reflectance()[i] = std::exp(log_reflectance[i]);
        }
      }
    }
  }
  FitPassFigures after;
  for (const std::size_t k : sampled) {
    look(model, frames[k], after, nullptr);
  }
  summary.after = finish(after);
  summary.fitted_profile = view.profile;
  summary.gain = view.gain;  // with the level the profile's shape gave it
  summary.fitted_background = mean(view.background);
  return summary;
}

}  // namespace sonarcarve
