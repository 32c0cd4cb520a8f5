#include "pipeline/beam_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/angles.h"
#include "common/quantile.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

// Points read: enough for a median over thousands of pairs, bounded whatever the map.
constexpr std::size_t kMostPoints = 4000;
// A point's return near the axis, where the declared power is within 1 dB of the axis's.
constexpr double kNearAxisShare = 0.5;
// A pair counts when the declared beam's prediction stands this far over the background.
constexpr double kStandsOut = 3.0;

struct View {
  double elevation_rad = 0.0;
  double value = 0.0;  // the pixel's return over the background
  double floor = 0.0;  // the background's spread there
};

}  // namespace

BeamTailCheck checkBeamTails(const std::vector<Eigen::Vector3f>& points_world,
                             const std::vector<PosedFrame>& frames,
                             const std::function<std::optional<cv::Mat>(std::size_t)>& excess,
                             const SonarModel& sonar, const cv::Mat& floor) {
  const SincSquaredBeam declared(sonar.verticalAperture());
  const double half = 0.5 * sonar.verticalAperture();
  BeamTailCheck check;
  check.band_lo_rad = 1.1 * half;
  check.band_hi_rad = 0.85 * declared.null(1);
  const double dark = sonar.intensityScale().darkPower();
  const std::size_t step = std::max<std::size_t>(1, points_world.size() / kMostPoints);
  std::vector<std::vector<View>> views((points_world.size() + step - 1) / step);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::optional<cv::Mat> image = excess(f);
    if (!image) {
      continue;
    }
    const Eigen::Isometry3d T_sonar_world = frames[f].T_world_sonar.inverse();
    for (std::size_t p = 0, k = 0; p < points_world.size(); p += step, ++k) {
      const Polar polar = polarFromPoint(T_sonar_world * points_world[p].cast<double>());
      const std::optional<int> bin = sonar.range().binOf(polar.range_m);
      const std::optional<int> beam = sonar.bearings().beamOf(polar.bearing_rad);
      if (!bin || !beam || std::abs(polar.elevation_rad) > check.band_hi_rad) {
        continue;
      }
      const double spread =
          floor.empty() ? dark : std::max<double>(dark, floor.at<float>(*bin, *beam));
      views[k].push_back({polar.elevation_rad, image->at<float>(*bin, *beam), spread});
    }
  }
  std::vector<double> ratios;
  for (const std::vector<View>& seen : views) {
    double reflect = 0.0;  // the point's return on the axis, from views near it
    for (const View& v : seen) {
      if (std::abs(v.elevation_rad) <= kNearAxisShare * half) {
        reflect = std::max(reflect, v.value / declared.power(v.elevation_rad));
      }
    }
    if (!(reflect > 0.0)) {
      continue;
    }
    ++check.points;
    for (const View& v : seen) {
      const double elevation = std::abs(v.elevation_rad);
      const double predicted = reflect * declared.power(v.elevation_rad);
      if (elevation >= check.band_lo_rad && elevation <= check.band_hi_rad &&
          predicted >= kStandsOut * v.floor) {
        ratios.push_back(std::max(0.0, v.value) / predicted);
      }
    }
  }
  check.samples = ratios.size();
  if (!ratios.empty()) {
    check.tail_ratio = quantile(ratios, kTailQuantile);
  }
  check.tails_present =
      check.samples < kBeamCheckMinSamples || check.tail_ratio >= kMissingTailRatio;
  return check;
}

RunChoice beamTailChoice(const BeamTailCheck& check) {
  char detail[320];
  std::snprintf(detail, sizeof detail,
                "between %.1f and %.1f degrees off the axis, %zu views of %zu points of a first "
                "surface carved inside the aperture measured %.1f dB of the declared beam's "
                "prediction (upper quartile; missing tails: under %.0f dB over at least %zu views)",
                radToDeg(check.band_lo_rad), radToDeg(check.band_hi_rad), check.samples,
                check.points, 10.0 * std::log10(std::max(check.tail_ratio, 1e-12)),
                10.0 * std::log10(kMissingTailRatio), kBeamCheckMinSamples);
  RunChoice choice;
  choice.name = "elevation beam";
  choice.detail = detail;
  if (check.samples < kBeamCheckMinSamples) {
    choice.value = "as declared";
    choice.reason = "too few returns past the aperture to check the declared beam";
  } else if (check.tails_present) {
    choice.value = "as declared";
    choice.reason = "the frames show the returns the declared beam puts past its aperture";
  } else {
    choice.value = "carved inside the aperture";
    choice.reason = "the frames lack the returns the declared beam puts past its aperture";
    choice.action = "check the sonar's beam pattern (beam_pattern: clipped in mission.yaml)";
    choice.warning = true;
  }
  return choice;
}

}  // namespace sonarcarve
