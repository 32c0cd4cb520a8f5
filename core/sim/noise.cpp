#include "sim/noise.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "common/error.h"
#include "io/files/yaml_fields.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {

NoiseSpec NoiseSpec::none() {
  NoiseSpec spec;
  spec.enabled = false;
  return spec;
}

NoiseSpec NoiseSpec::coherent() {
  NoiseSpec spec;
  spec.combination = NoiseCombination::Coherent;
  return spec;
}

NoiseSpec NoiseSpec::fromYamlFile(const std::string& path) {
  const YamlFields fields(path);
  const YAML::Node root = fields.load();
  NoiseSpec spec;
  const auto read = [&](const char* key, double& value, bool positive) {
    if (root[key]) {
      value = positive ? fields.positive(root[key], key) : fields.number(root[key], key);
      if (value < 0.0) {
        fields.fail(root[key], key, "expected a number >= 0");
      }
    }
  };
  read("background_mean", spec.background_mean, false);
  read("near_range_boost", spec.near_range_boost, false);
  read("near_range_scale_m", spec.near_range_scale_m, true);
  read("edge_boost", spec.edge_boost, false);
  read("speckle_looks", spec.speckle_looks, true);
  if (root["seed"]) {
    spec.seed = static_cast<std::uint64_t>(fields.positiveInt(root["seed"], "seed"));
  }
  if (root["enabled"]) {
    spec.enabled = root["enabled"].as<bool>();
  }
  if (root["combination"]) {
    const auto combination =
        enumFromString<NoiseCombination>(fields.text(root["combination"], "combination"));
    if (!combination) {
      fields.fail(root["combination"], "combination", "expected added or coherent");
    }
    spec.combination = *combination;
  }
  return spec;
}

std::string NoiseSpec::toYaml() const {
  std::ostringstream out;
  out << "enabled: " << (enabled ? "true" : "false") << "\n"
      << "background_mean: " << shortestNumber(background_mean) << "\n"
      << "near_range_boost: " << shortestNumber(near_range_boost) << "\n"
      << "near_range_scale_m: " << shortestNumber(near_range_scale_m) << "\n"
      << "edge_boost: " << shortestNumber(edge_boost) << "\n"
      << "speckle_looks: " << shortestNumber(speckle_looks) << "\n"
      << "combination: " << toString(combination) << "\n"
      << "seed: " << seed << "\n";
  return out.str();
}

double backgroundMean(const NoiseSpec& spec, const SonarModel& sonar, int row, int col) {
  const double range = sonar.range().centre(row);
  const double half_fov = 0.5 * sonar.bearings().fieldOfView();
  const double u = sonar.bearings().centre(col) / half_fov;  // -1..1 across the fan
  return spec.background_mean *
         (1.0 + spec.near_range_boost * std::exp(-range / spec.near_range_scale_m)) *
         (1.0 + spec.edge_boost * u * u);
}

namespace {

// Speckle of more looks than this, or of a fraction of a look, is drawn white.
constexpr double kMostCorrelatedLooks = 16.0;

// The amplitude weights of beams `width` wide and `spacing` apart, each the pattern's mean
// over a beam's interval, to the second null (as the simulator traces the power pattern),
// scaled so that their squares sum to 1: white fields filtered by them keep their variance.
std::vector<float> amplitudeTaps(double width, double spacing, int max_half) {
  const std::vector<double> taps = meansOverBeams(SincSquaredBeam(width), spacing, max_half, true);
  double squares = 0.0;
  for (const double t : taps) {
    squares += t * t;
  }
  std::vector<float> out;
  for (const double t : taps) {
    out.push_back(static_cast<float>(t / std::sqrt(squares)));
  }
  return out;
}

// One row of a complex Gaussian field (real and imaginary parts N(0, 1) in each pixel),
// correlated across bearing by `taps`.
class FieldRow {
 public:
  FieldRow(const std::vector<float>& taps, int cols)
      : taps_(taps), half_(static_cast<int>(taps.size() / 2)), cols_(cols) {}

  void draw(std::mt19937_64& rng, std::vector<float>& re, std::vector<float>& im) {
    const auto padded = static_cast<std::size_t>(cols_ + 2 * half_);
    white_re_.resize(padded);
    white_im_.resize(padded);
    for (std::size_t i = 0; i < padded; ++i) {
      white_re_[i] = normal_(rng);
      white_im_[i] = normal_(rng);
    }
    filter(white_re_, re);
    filter(white_im_, im);
  }

 private:
  void filter(const std::vector<float>& white, std::vector<float>& out) const {
    out.assign(static_cast<std::size_t>(cols_), 0.0f);
    for (int d = 0; d <= 2 * half_; ++d) {
      const float w = taps_[static_cast<std::size_t>(d)];
      const float* __restrict in = white.data() + d;
      float* __restrict o = out.data();
      for (int c = 0; c < cols_; ++c) {
        o[c] += w * in[c];
      }
    }
  }

  const std::vector<float>& taps_;
  int half_;
  int cols_;
  std::normal_distribution<float> normal_{0.0f, 1.0f};
  std::vector<float> white_re_, white_im_;
};

}  // namespace

void addNoise(cv::Mat& image, const NoiseSpec& spec, const SonarModel& sonar,
              std::uint64_t frame_index) {
  if (spec.enabled) {
    FrameNoise(spec, sonar).add(image, frame_index);
  }
}

FrameNoise::FrameNoise(const NoiseSpec& spec, const SonarModel& sonar) : spec_(spec) {
  if (!spec_.enabled) {
    return;
  }
  // Rayleigh with mean m has scale sigma = m / sqrt(pi / 2).
  const double to_sigma = 1.0 / std::sqrt(std::numbers::pi / 2.0);
  background_sigma_.create(sonar.rows(), sonar.cols(), CV_64F);
  for (int r = 0; r < sonar.rows(); ++r) {
    auto* row = background_sigma_.ptr<double>(r);
    for (int c = 0; c < sonar.cols(); ++c) {
      row[c] = backgroundMean(spec_, sonar, r, c) * to_sigma;
    }
  }
  const double spacing = sonar.bearings().medianSpacing();
  if (sonar.horizontalBeamWidth() > 0.0 && spacing > 0.0) {  // a single beam has no neighbours
    field_taps_ = amplitudeTaps(sonar.horizontalBeamWidth(), spacing, sonar.cols() - 1);
  }
}

void FrameNoise::add(cv::Mat& image, std::uint64_t frame_index) const {
  if (!spec_.enabled) {
    return;
  }
  if (image.size() != background_sigma_.size() || image.type() != CV_32F) {
    throw Error("noise", "frame " + std::to_string(frame_index),
                "expected a float image of the sonar's " + std::to_string(background_sigma_.rows) +
                    " range bins x " + std::to_string(background_sigma_.cols) + " beams");
  }
  if (field_taps_.empty()) {
    addWhite(image, frame_index);
  } else {
    addAcrossBeams(image, frame_index);
  }
}

std::mt19937_64 FrameNoise::frameRandom(std::uint64_t frame_index) const {
  return std::mt19937_64(spec_.seed * 0x9E3779B97F4A7C15ULL + frame_index);
}

void FrameNoise::addWhite(cv::Mat& image, std::uint64_t frame_index) const {
  std::mt19937_64 rng = frameRandom(frame_index);
  std::gamma_distribution<float> speckle(static_cast<float>(spec_.speckle_looks),
                                         static_cast<float>(1.0 / spec_.speckle_looks));
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const bool coherent = spec_.combination == NoiseCombination::Coherent;
  for (int r = 0; r < image.rows; ++r) {
    float* row = image.ptr<float>(r);
    const double* sigma = background_sigma_.ptr<double>(r);
    for (int c = 0; c < image.cols; ++c) {
      const double background = sigma[c] * std::sqrt(-2.0 * std::log(1.0 - uniform(rng)));
      const double signal = row[c] > 0.0f ? static_cast<double>(row[c] * speckle(rng)) : 0.0;
      double value = signal + background;
      if (coherent && signal > 0.0) {
        // The background is the envelope of a complex Gaussian: its phase against the
        // return's is uniform.
        const double phase = 2.0 * std::numbers::pi * uniform(rng);
        value = std::hypot(signal + background * std::cos(phase), background * std::sin(phase));
      }
      row[c] = std::clamp(static_cast<float>(value), 0.0f, 65535.0f);
    }
  }
}

void FrameNoise::addAcrossBeams(cv::Mat& image, std::uint64_t frame_index) const {
  std::mt19937_64 rng = frameRandom(frame_index);
  const double whole = std::floor(spec_.speckle_looks);
  const bool correlated_speckle = whole >= 1.0 && whole <= kMostCorrelatedLooks;
  const int looks = correlated_speckle ? static_cast<int>(whole) : 0;
  const double fraction = spec_.speckle_looks - looks;
  // The fraction of a look left, drawn white (the whole speckle where it is not correlated).
  const bool white_rest = fraction > 1e-9;
  std::gamma_distribution<float> rest(static_cast<float>(white_rest ? fraction : 1.0), 1.0f);
  const float to_mean = 1.0f / static_cast<float>(spec_.speckle_looks);
  const bool coherent = spec_.combination == NoiseCombination::Coherent;
  FieldRow field(field_taps_, image.cols);
  std::vector<float> bg_re, bg_im, sp_re, sp_im;
  std::vector<float> speckle(static_cast<std::size_t>(image.cols));
  for (int r = 0; r < image.rows; ++r) {
    float* row = image.ptr<float>(r);
    const double* sigma = background_sigma_.ptr<double>(r);
    field.draw(rng, bg_re, bg_im);
    const bool lit = std::any_of(row, row + image.cols, [](float v) { return v > 0.0f; });
    if (lit) {
      // Gamma(looks, 1 / looks): the mean of `looks` unit exponentials, |z|^2 / 2 each.
      std::fill(speckle.begin(), speckle.end(), 0.0f);
      for (int l = 0; l < looks; ++l) {
        field.draw(rng, sp_re, sp_im);
        for (int c = 0; c < image.cols; ++c) {
          const auto i = static_cast<std::size_t>(c);
          speckle[i] += 0.5f * (sp_re[i] * sp_re[i] + sp_im[i] * sp_im[i]);
        }
      }
      if (white_rest) {
        for (float& s : speckle) {
          s += rest(rng);
        }
      }
    }
    for (int c = 0; c < image.cols; ++c) {
      const auto i = static_cast<std::size_t>(c);
      // The background's field: a Rayleigh amplitude of scale sigma, its phase uniform.
      const double re = sigma[c] * bg_re[i];
      const double im = sigma[c] * bg_im[i];
      const double signal =
          row[c] > 0.0f ? static_cast<double>(row[c] * speckle[i] * to_mean) : 0.0;
      const double value =
          coherent && signal > 0.0 ? std::hypot(signal + re, im) : signal + std::hypot(re, im);
      row[c] = std::clamp(static_cast<float>(value), 0.0f, 65535.0f);
    }
  }
}

}  // namespace sonarcarve
