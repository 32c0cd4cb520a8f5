#include "sim/noise.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "common/error.h"
#include "io/yaml_fields.h"

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
  std::mt19937_64 rng(spec_.seed * 0x9E3779B97F4A7C15ULL + frame_index);
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

}  // namespace sonarcarve
