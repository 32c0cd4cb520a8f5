#include "denoise/noise_model.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "common/input_limits.h"
#include "common/number_text.h"
#include "io/files/atomic_file.h"
#include "io/files/input_file.h"
#include "io/files/yaml_block_keys.h"

namespace sonarcarve {

NoiseModel::NoiseModel(cv::Mat mean, cv::Mat stddev, cv::Mat rayleigh_sigma,
                       const SonarModel& sonar, int frames, int smoothing)
    : mean_(std::move(mean)),
      stddev_(std::move(stddev)),
      rayleigh_sigma_(std::move(rayleigh_sigma)),
      range_min_m_(sonar.range().min_m),
      range_resolution_m_(sonar.range().resolution_m),
      bearings_rad_(sonar.bearings().centres()),
      vertical_aperture_rad_(sonar.verticalAperture()),
      intensity_scale_(sonar.intensityScale()),
      frames_(frames),
      smoothing_(smoothing) {
  if (const auto problem = smoothingProblem(smoothing)) {
    throw Error("noise model", "smoothing", *problem);
  }
  checkGeometry(sonar, "noise model");
}

std::optional<std::string> smoothingProblem(int size) {
  if (size >= 1 && size <= kMaxSmoothingWindow && size % 2 != 0) {
    return std::nullopt;
  }
  return "expected an odd whole number of pixels, from 1 to " +
         std::to_string(kMaxSmoothingWindow) + ", got " + std::to_string(size);
}

cv::Mat smoothFrame(const cv::Mat& image, int size) {
  if (size <= 1) {
    return image;
  }
  cv::Mat out;
  cv::blur(image, out, cv::Size(size, size), cv::Point(-1, -1), cv::BORDER_REPLICATE);
  return out;
}

NoiseModel NoiseModel::learn(const Mission& mission, Progress& progress,
                             std::vector<FrameProblem>* skipped, int smoothing) {
  const int rows = mission.sonar.rows();
  const int cols = mission.sonar.cols();
  cv::Mat sum(rows, cols, CV_64F, cv::Scalar(0.0));
  cv::Mat sum_sq(rows, cols, CV_64F, cv::Scalar(0.0));
  int n = 0;
  for (std::size_t i = 0; i < mission.frames.size(); ++i) {
    if (progress.cancelled()) {
      throw Cancelled();
    }
    Frame frame;
    try {
      frame = loadFrame(mission, i);
    } catch (const Error& e) {
      if (skipped != nullptr) {
        skipped->push_back({i, e.what()});
      }
      continue;
    }
    cv::Mat f64;
    smoothFrame(frame.image, smoothing).convertTo(f64, CV_64F);
    sum += f64;
    sum_sq += f64.mul(f64);
    ++n;
    progress.report("noise model", i + 1, mission.frames.size());
  }
  if (n < 2) {
    throw Error(mission.folder.string(), "", "a noise model needs at least 2 readable frames");
  }
  cv::Mat mean = sum / n;
  cv::Mat second = sum_sq / n;
  cv::Mat variance = (second - mean.mul(mean)) * (static_cast<double>(n) / (n - 1));
  cv::Mat stddev;
  cv::sqrt(cv::max(variance, 0.0), stddev);
  cv::Mat sigma;
  cv::sqrt(second / 2.0, sigma);
  cv::Mat mean32, stddev32, sigma32;
  mean.convertTo(mean32, CV_32F);
  stddev.convertTo(stddev32, CV_32F);
  sigma.convertTo(sigma32, CV_32F);
  return NoiseModel(std::move(mean32), std::move(stddev32), std::move(sigma32), mission.sonar, n,
                    smoothing);
}

void NoiseModel::checkGeometry(const SonarModel& sonar, const std::string& what) const {
  const auto mismatch = [&](const std::string& detail) {
    throw Error(what, "noise model",
                "learned for another sonar geometry (" + detail +
                    "): learn a noise model from empty-water frames of this sonar");
  };
  if (mean_.rows != sonar.rows() || mean_.cols != sonar.cols()) {
    mismatch(std::to_string(mean_.rows) + " x " + std::to_string(mean_.cols) +
             " pixels, this sonar has " + std::to_string(sonar.rows()) + " x " +
             std::to_string(sonar.cols()));
  }
  if (std::abs(range_min_m_ - sonar.range().min_m) > 1e-6 ||
      std::abs(range_resolution_m_ - sonar.range().resolution_m) > 1e-9) {
    mismatch("range bins differ");
  }
  for (int j = 0; j < sonar.cols(); ++j) {
    if (std::abs(bearings_rad_[static_cast<std::size_t>(j)] - sonar.bearings().centre(j)) > 1e-6) {
      mismatch("bearing table differs at beam " + std::to_string(j));
    }
  }
  // Statistics of power read on one scale say nothing of frames read on another.
  if (!(intensity_scale_ == sonar.intensityScale())) {
    throw Error(what, "noise model",
                "learned on another intensity scale (its frames' was " +
                    intensity_scale_.describe() + ", this sonar's is " +
                    sonar.intensityScale().describe() +
                    "): learn a noise model from empty-water frames of this sonar");
  }
}

void NoiseModel::save(const std::filesystem::path& path) const {
  cv::FileStorage fs(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  fs << "format"
     << "sonarcarve-noise-model"
     << "version" << 1 << "frames" << frames_ << "smoothing" << smoothing_;
  fs << "rows" << mean_.rows << "cols" << mean_.cols << "range_min_m" << range_min_m_
     << "range_resolution_m" << range_resolution_m_ << "vertical_aperture_rad"
     << vertical_aperture_rad_ << "bearings_rad" << cv::Mat(bearings_rad_).t();
  fs << "intensity_full_scale_db" << intensity_scale_.fullScaleDb() << "intensity_full_scale_count"
     << intensity_scale_.fullScaleCount();
  if (intensity_scale_.gammaExponent() != 0.0) {
    fs << "intensity_gamma" << intensity_scale_.gammaExponent();
  }
  fs << "mean" << mean_ << "stddev" << stddev_ << "rayleigh_sigma" << rayleigh_sigma_;
  writeFileAtomically(path, fs.releaseAndGetString());
}

namespace {

// What OpenCV says went wrong, without its version, source file and error code.
std::string openCvReason(const cv::Exception& e) {
  std::string text = e.what();
  const auto code = text.find("error: (");
  if (code != std::string::npos) {
    const auto end = text.find(") ", code);
    if (end != std::string::npos) {
      text = text.substr(end + 2);
    }
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
    text.pop_back();
  }
  return text;
}

// A matrix of statistics must hold finite numbers of at least `least` (a deviation is never
// negative): a NaN mean or a negative deviation would test every pixel against nonsense.
void requireStatistics(const std::string& file, const std::string& key, const cv::Mat& values,
                       float least) {
  for (int r = 0; r < values.rows; ++r) {
    const auto* row = values.ptr<float>(r);
    for (int c = 0; c < values.cols; ++c) {
      if (!std::isfinite(row[c]) || row[c] < least) {
        const std::string what = least == 0.0F ? "finite numbers >= 0" : "finite numbers";
        throw Error(file, key + ", row " + std::to_string(r) + " column " + std::to_string(c),
                    shortestNumber(row[c]) + ": expected " + what + " (the " + key +
                        " of the empty-water frames' pixels)");
      }
    }
  }
}

}  // namespace

NoiseModel NoiseModel::load(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text =
      readInputFile(path, "a noise model (sonarcarve-cli noise-model)", kMaxNoiseModelFileBytes);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw Error(file, "", "cannot read the noise model (empty or not YAML)");
  }
  requireUniqueBlockKeys(text, file);  // OpenCV's reader keeps the last of two
  NoiseModel model;
  try {
    cv::FileStorage fs(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    if (!fs.isOpened()) {
      throw Error(file, "", "cannot read the noise model (empty or not YAML)");
    }
    if (static_cast<std::string>(fs["format"]) != "sonarcarve-noise-model") {
      throw Error(file, "format", "expected 'sonarcarve-noise-model'");
    }
    if (static_cast<int>(fs["version"]) != 1) {
      throw Error(file, "version", "unknown noise model version: this build reads 1");
    }
    fs["frames"] >> model.frames_;
    if (!fs["smoothing"].empty()) {
      fs["smoothing"] >> model.smoothing_;
      if (const auto problem = smoothingProblem(model.smoothing_)) {
        throw Error(file, "smoothing",
                    *problem + " (a detector smooths by an odd window: learn the model again)");
      }
    }
    fs["range_min_m"] >> model.range_min_m_;
    fs["range_resolution_m"] >> model.range_resolution_m_;
    fs["vertical_aperture_rad"] >> model.vertical_aperture_rad_;
    // Absent (models written before intensity scales) or 0: linear.
    const auto number = [&](const char* key) {
      return fs[key].empty() ? 0.0 : static_cast<double>(fs[key]);
    };
    const double full_scale_db = number("intensity_full_scale_db");
    const double gamma = number("intensity_gamma");
    if (full_scale_db != 0.0 && gamma != 0.0) {
      throw Error(file, "intensity_gamma",
                  "expected either intensity_full_scale_db (decibel) or intensity_gamma, not both");
    }
    if (full_scale_db != 0.0 || gamma != 0.0) {
      if (fs["intensity_full_scale_count"].empty()) {
        throw Error(file, "intensity_full_scale_count",
                    "missing: expected the full scale of the intensity's decibels or gamma");
      }
      const double full_scale_count = number("intensity_full_scale_count");
      try {
        model.intensity_scale_ = full_scale_db != 0.0
                                     ? IntensityScale::decibel(full_scale_db, full_scale_count)
                                     : IntensityScale::gamma(gamma, full_scale_count);
      } catch (const Error& e) {
        throw Error(file, "intensity_" + e.place(), e.message());
      }
    }
    cv::Mat bearings;
    fs["bearings_rad"] >> bearings;
    fs["mean"] >> model.mean_;
    fs["stddev"] >> model.stddev_;
    fs["rayleigh_sigma"] >> model.rayleigh_sigma_;
    if (bearings.empty() || model.mean_.empty() || model.stddev_.empty() ||
        model.rayleigh_sigma_.empty()) {
      throw Error(file, "",
                  "incomplete noise model: expected bearings_rad, mean, stddev and "
                  "rayleigh_sigma");
    }
    bearings.reshape(1, 1).convertTo(bearings, CV_64F);
    model.bearings_rad_.assign(bearings.begin<double>(), bearings.end<double>());
    for (cv::Mat* m : {&model.mean_, &model.stddev_, &model.rayleigh_sigma_}) {
      if (m->size() != model.mean_.size() || m->type() != CV_32F) {
        throw Error(file, "", "noise model matrices must be CV_32F and of one size");
      }
    }
    if (static_cast<int>(model.bearings_rad_.size()) != model.mean_.cols) {
      throw Error(file, "bearings_rad", "expected one bearing per column");
    }
    requireStatistics(file, "mean", model.mean_, -std::numeric_limits<float>::infinity());
    requireStatistics(file, "stddev", model.stddev_, 0.0F);
    requireStatistics(file, "rayleigh_sigma", model.rayleigh_sigma_, 0.0F);
  } catch (const Error&) {
    throw;  // already names the file and the place
  } catch (const cv::Exception& e) {
    throw Error(file, "",
                "corrupt noise model (expected the YAML that sonarcarve-cli noise-model "
                "writes): " +
                    openCvReason(e));
  } catch (const std::exception& e) {
    // OpenCV's reader throws standard exceptions too (std::length_error on a huge count).
    throw Error(file, "",
                std::string("corrupt noise model (expected the YAML that sonarcarve-cli "
                            "noise-model writes): ") +
                    e.what());
  }
  return model;
}

}  // namespace sonarcarve
