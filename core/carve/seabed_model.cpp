#include "carve/seabed_model.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "common/angles.h"
#include "common/quantile.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {

SeabedPlane SeabedPlane::sloped(const Eigen::Vector3d& at, double depth_m, double slope_north,
                                double slope_east) {
  // z = depth + sn (x - ax) + se (y - ay)  <=>  (sn, se, -1) . p = sn ax + se ay - depth
  const Eigen::Vector3d n(slope_north, slope_east, -1.0);
  const double norm = n.norm();
  return {n / norm, (slope_north * at.x() + slope_east * at.y() - depth_m) / norm};
}

double SeabedPlane::depthAt(double north, double east) const {
  return (normal.x() * north + normal.y() * east - offset) / -normal.z();
}

double seabedRange(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                   const Eigen::Vector3d& direction_sonar) {
  const Eigen::Vector3d d = T_world_sonar.linear() * direction_sonar;
  const double towards = plane.normal.dot(d);  // < 0: the ray goes down into the seabed
  const double height = plane.normal.dot(T_world_sonar.translation()) - plane.offset;
  if (!(towards < -1e-9) || !(height > 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  return height / -towards;
}

namespace {

// The unit ray of a beam at an elevation (up positive) in the sonar frame (x forward, y
// starboard, z down).
Eigen::Vector3d rayDirection(double elevation_rad, double bearing_rad) {
  return {std::cos(elevation_rad) * std::cos(bearing_rad),
          std::cos(elevation_rad) * std::sin(bearing_rad), -std::sin(elevation_rad)};
}

// Runs fn(i) for i in [0, count), on `pool` where given.
void forEachBeam(ThreadPool* pool, std::size_t count, const std::function<void(std::size_t)>& fn) {
  if (pool == nullptr) {
    for (std::size_t i = 0; i < count; ++i) {
      fn(i);
    }
    return;
  }
  pool->parallelFor(count, 8, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      fn(i);
    }
  });
}

// The rays of some of a frame's beams, in the world, cut into elevation intervals over the
// beam's traced pattern (to the second null): each interval's two ends and its centre, and
// its weight (power x solid angle, cos(incidence) still to come).
struct BeamRays {
  std::vector<int> beams;
  int intervals = 0;
  std::vector<Eigen::Vector3d> ends;     // per beam intervals + 1
  std::vector<Eigen::Vector3d> centres;  // per beam intervals
  std::vector<double> weights;           // per interval
};

BeamRays beamRays(const SonarModel& sonar, const Eigen::Matrix3d& R, int beam_stride, double step,
                  ThreadPool* pool) {
  BeamRays rays;
  const SincSquaredBeam beam(sonar.verticalAperture());
  const double reach = beam.null(2);
  rays.intervals = static_cast<int>(std::ceil(2.0 * reach / step));
  step = 2.0 * reach / rays.intervals;
  for (int k = 0; k < rays.intervals; ++k) {
    const double el = -reach + (k + 0.5) * step;
    rays.weights.push_back(beam.power(el) * std::cos(el) * step);
  }
  for (int b = 0; b < sonar.cols(); b += beam_stride) {
    rays.beams.push_back(b);
  }
  const auto n = static_cast<std::size_t>(rays.intervals);
  rays.ends.resize(rays.beams.size() * (n + 1));
  rays.centres.resize(rays.beams.size() * n);
  forEachBeam(pool, rays.beams.size(), [&](std::size_t i) {
    const double bearing = sonar.bearings().centre(rays.beams[i]);
    const auto direction = [&](double el) -> Eigen::Vector3d {
      return R * rayDirection(el, bearing);
    };
    for (std::size_t k = 0; k <= n; ++k) {
      rays.ends[i * (n + 1) + k] = direction(-reach + static_cast<double>(k) * step);
    }
    for (std::size_t k = 0; k < n; ++k) {
      rays.centres[i * n + k] = direction(-reach + (static_cast<double>(k) + 0.5) * step);
    }
  });
  return rays;
}

double heightOver(const SeabedPlane& plane, const Eigen::Vector3d& sonar_position) {
  return plane.normal.dot(sonar_position) - plane.offset;
}

// Adds beam i of `rays` seen over `plane` from `height` to `column` (one value per range
// bin): each interval's weight times cos(incidence) spread evenly over the ranges between its
// ends, as a surface spreads its return between two rays.
void accumulateBeam(std::vector<float>& column, const BeamRays& rays, std::size_t i,
                    const SeabedPlane& plane, double height, const RangeBins& bins) {
  const int rows = static_cast<int>(column.size());
  const Eigen::Vector3d* ends = rays.ends.data() + i * (rays.intervals + 1);
  const Eigen::Vector3d* centres = rays.centres.data() + i * rays.intervals;
  const double inv_res = 1.0 / bins.resolution_m;
  double ta = plane.normal.dot(ends[0]);
  for (int k = 0; k < rays.intervals; ++k) {
    const double tb = plane.normal.dot(ends[k + 1]);
    const double tc = plane.normal.dot(centres[k]);
    const double t_start = ta;
    ta = tb;
    if (!(tc < -1e-9)) {
      continue;  // the interval's centre does not go down to the seabed
    }
    const double weight = rays.weights[static_cast<std::size_t>(k)] * -tc;
    const double rc = height / -tc;
    const double r0 = t_start < -1e-9 ? height / -t_start : rc;
    const double r1 = tb < -1e-9 ? height / -tb : rc;
    double lo = (std::min(r0, r1) - bins.min_m) * inv_res;
    double hi = (std::max(r0, r1) - bins.min_m) * inv_res;
    if (hi < 0.0 || lo >= rows) {
      continue;
    }
    if (hi - lo < 1e-6) {
      column[static_cast<std::size_t>(std::clamp(static_cast<int>(lo), 0, rows - 1))] +=
          static_cast<float>(weight);
      continue;
    }
    const double density = weight / (hi - lo);
    lo = std::max(lo, 0.0);
    hi = std::min(hi, static_cast<double>(rows));
    for (int b = static_cast<int>(lo); b < hi; ++b) {
      const double overlap = std::min(hi, b + 1.0) - std::max(lo, static_cast<double>(b));
      column[static_cast<std::size_t>(b)] += static_cast<float>(density * overlap);
    }
  }
}

cv::Mat predictedImage(const BeamRays& rays, const SeabedPlane& plane,
                       const Eigen::Vector3d& position, const SonarModel& sonar, ThreadPool* pool) {
  cv::Mat image = cv::Mat::zeros(sonar.rows(), sonar.cols(), CV_32F);
  const double height = heightOver(plane, position);
  if (!(height > 0.0)) {
    return image;
  }
  forEachBeam(pool, rays.beams.size(), [&](std::size_t i) {
    std::vector<float> column(static_cast<std::size_t>(sonar.rows()), 0.0f);
    accumulateBeam(column, rays, i, plane, height, sonar.range());
    for (int r = 0; r < sonar.rows(); ++r) {
      image.at<float>(r, rays.beams[i]) = column[static_cast<std::size_t>(r)];
    }
  });
  return image;
}

constexpr double kPredictionStep_rad = 0.2 * std::numbers::pi / 180.0;
constexpr double kFitStep_rad = 0.2 * std::numbers::pi / 180.0;
constexpr int kFitBeamStride = 4;
constexpr int kRefits = 2;
constexpr double kMaxDepthStep_m = 0.02;
constexpr double kMaxSlopeStep = 0.002;  // 0.11 degree
constexpr double kOutlierFactor = 1.5;

}  // namespace

cv::Mat predictSeabedImage(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                           const SonarModel& sonar, ThreadPool* pool) {
  const BeamRays rays = beamRays(sonar, T_world_sonar.linear(), 1, kPredictionStep_rad, pool);
  return predictedImage(rays, plane, T_world_sonar.translation(), sonar, pool);
}

namespace {

// The frame's pixels on the fit's beams (rows x beams).
cv::Mat fitPixels(const cv::Mat& pixels, const BeamRays& rays) {
  cv::Mat out(pixels.rows, static_cast<int>(rays.beams.size()), CV_32F);
  for (int r = 0; r < pixels.rows; ++r) {
    for (std::size_t i = 0; i < rays.beams.size(); ++i) {
      out.at<float>(r, static_cast<int>(i)) = pixels.at<float>(r, rays.beams[i]);
    }
  }
  return out;
}

// Normalised correlation of `data` (rows x fit beams) with a plane's predicted image.
double correlation(const cv::Mat& data, const BeamRays& rays, const SeabedPlane& plane,
                   const Eigen::Vector3d& position, const RangeBins& bins, ThreadPool* pool) {
  const double height = heightOver(plane, position);
  if (!(height > 0.0)) {
    return 0.0;
  }
  // Per beam: the sums of pixel x prediction, prediction^2 and pixel^2 over the pixels fitted.
  std::vector<std::array<double, 3>> sums(rays.beams.size());
  forEachBeam(pool, rays.beams.size(), [&](std::size_t i) {
    std::vector<float> column(static_cast<std::size_t>(data.rows), 0.0f);
    accumulateBeam(column, rays, i, plane, height, bins);
    std::array<double, 3> s{0.0, 0.0, 0.0};
    for (int r = 0; r < data.rows; ++r) {
      const double e = column[static_cast<std::size_t>(r)];
      const double v = data.at<float>(r, static_cast<int>(i));
      if (v < 0.0) {
        continue;  // left out of the fit
      }
      s[0] += v * e;
      s[1] += e * e;
      s[2] += v * v;
    }
    sums[i] = s;
  });
  double ie = 0.0, ee = 0.0, ii = 0.0;
  for (const auto& s : sums) {
    ie += s[0];
    ee += s[1];
    ii += s[2];
  }
  if (!(ee > 0.0) || !(ii > 0.0)) {
    return 0.0;
  }
  return ie / std::sqrt(ee * ii);
}

struct FitParams {
  double depth, sn, se;
};

// Pattern search from `best`: depth in metres, slopes (dimensionless) from the given steps.
double patternSearch(FitParams& best, double depth_step, double slope_step,
                     const std::function<double(const FitParams&)>& score) {
  double best_score = score(best);
  while (depth_step > 0.002) {
    bool moved = false;
    for (int axis = 0; axis < 3; ++axis) {
      for (const double sign : {-1.0, 1.0}) {
        FitParams p = best;
        (axis == 0   ? p.depth
         : axis == 1 ? p.sn
                     : p.se) += sign * (axis == 0 ? depth_step : slope_step);
        const double s = score(p);
        if (s > best_score) {
          best_score = s;
          best = p;
          moved = true;
        }
      }
    }
    if (!moved) {
      depth_step *= 0.5;
      slope_step *= 0.5;
    }
  }
  return best_score;
}

// The median of lit pixels over the prediction where it is at least `floor` of its peak.
double medianRatio(const cv::Mat& pixels, const cv::Mat& predicted, double floor) {
  double peak = 0.0;
  cv::minMaxLoc(predicted, nullptr, &peak);
  std::vector<float> ratios;
  for (int r = 0; r < pixels.rows; ++r) {
    for (int c = 0; c < pixels.cols; ++c) {
      const float e = predicted.at<float>(r, c);
      if (e > 0.0f && e >= floor * peak && pixels.at<float>(r, c) > 0.0f) {
        ratios.push_back(pixels.at<float>(r, c) / e);
      }
    }
  }
  if (ratios.empty()) {
    return 0.0;
  }
  const auto mid = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
  std::nth_element(ratios.begin(), mid, ratios.end());
  return *mid;
}

}  // namespace

SeabedFit fitSeabed(const cv::Mat& pixels, const Eigen::Isometry3d& T_world_sonar,
                    const SonarModel& sonar, const SeabedFit* prior, ThreadPool* pool) {
  const BeamRays rays = beamRays(sonar, T_world_sonar.linear(), kFitBeamStride, kFitStep_rad, pool);
  const cv::Mat raw = fitPixels(pixels, rays);
  // Without a prior, a first search runs on pixels clipped at their 90th percentile, so that
  // bright structure does not pull the plane; then (from a prior, at once) the unclipped
  // pixels less those the plane does not explain.
  cv::Mat data = raw.clone();
  std::vector<float> lit;
  for (int r = 0; r < raw.rows; ++r) {
    for (int c = 0; c < raw.cols; ++c) {
      if (raw.at<float>(r, c) > 0.0f) {
        lit.push_back(raw.at<float>(r, c));
      }
    }
  }
  if (lit.empty()) {
    return {};
  }
  const float clip = quantile(lit, 0.9);
  cv::min(data, clip, data);

  const Eigen::Vector3d at = T_world_sonar.translation();
  const auto plane = [&](const FitParams& p) {
    return SeabedPlane::sloped(at, p.depth, p.sn, p.se);
  };
  const auto score = [&](const FitParams& p) {
    return correlation(data, rays, plane(p), at, sonar.range(), pool);
  };
  FitParams best{at.z() + 1.0, 0.0, 0.0};
  // From a prior, the plane moves at most kMaxDepthStep_m and kMaxSlopeStep a frame: the
  // seabed is one surface, and what pulls a fit further is structure coming into view.
  FitParams start = best;
  bool bounded = false;
  if (prior != nullptr && prior->correlation > 0.0) {
    const SeabedPlane& pq = prior->plane;
    best = {pq.depthAt(at.x(), at.y()), pq.normal.x() / -pq.normal.z(),
            pq.normal.y() / -pq.normal.z()};
    start = best;
    bounded = true;
  } else {
    // A scan of level planes with a coarse ray set (every 16th beam, 0.5 degree intervals).
    const BeamRays coarse =
        beamRays(sonar, T_world_sonar.linear(), 4 * kFitBeamStride, 2.5 * kFitStep_rad, pool);
    cv::Mat coarse_data;
    cv::min(fitPixels(pixels, coarse), clip, coarse_data);
    double best_score = 0.0;
    for (double h = 0.3; h < sonar.range().maxRange(); h += 0.1) {
      const FitParams p{at.z() + h, 0.0, 0.0};
      const double s = correlation(coarse_data, coarse, plane(p), at, sonar.range(), pool);
      if (s > best_score) {
        best_score = s;
        best = p;
      }
    }
    if (best_score < 0.5 * SeabedTracker::kMinCorrelation) {
      return {plane(best), best_score};
    }
    patternSearch(best, 0.04, 0.02, score);
  }
  // Then twice on the unclipped pixels, leaving out those the last plane does not explain:
  // structure (over kOutlierFactor times its prediction) and acoustic shadows (under a
  // kOutlierFactor-th of it), give or take two counts of rounding. Without the shadows a box
  // on the seabed pulled the plane 4 cm up as it came nearer; with them, under 1 cm.
  double fit = 0.0;
  for (int round = 0; round < kRefits; ++round) {
    const cv::Mat predicted = predictedImage(rays, plane(best), at, sonar, pool);
    const double scale = medianRatio(pixels, predicted, 0.0);
    for (int r = 0; r < raw.rows; ++r) {
      for (std::size_t i = 0; i < rays.beams.size(); ++i) {
        const double v = raw.at<float>(r, static_cast<int>(i));
        const double e = scale * predicted.at<float>(r, rays.beams[i]);
        const bool outlier = v > kOutlierFactor * e + 2.0 || v < e / kOutlierFactor - 2.0;
        data.at<float>(r, static_cast<int>(i)) = outlier ? -1.0f : static_cast<float>(v);
      }
    }
    fit = patternSearch(best, 0.01, 0.002, [&](const FitParams& p) {
      if (bounded && (std::abs(p.depth - start.depth) > kMaxDepthStep_m ||
                      std::abs(p.sn - start.sn) > kMaxSlopeStep ||
                      std::abs(p.se - start.se) > kMaxSlopeStep)) {
        return -1.0;
      }
      return score(p);
    });
  }
  return {plane(best), fit};
}

cv::Mat explainSeabed(const cv::Mat& pixels, const cv::Mat& predicted, int slack_bins,
                      double headroom) {
  const double scale = medianRatio(pixels, predicted, 0.1);
  if (!(scale > 0.0)) {
    return pixels.clone();
  }
  cv::Mat spread;
  cv::dilate(predicted, spread, cv::Mat::ones(2 * slack_bins + 1, 1, CV_8U));
  cv::Mat explained;
  cv::min(pixels, spread * (headroom * scale), explained);
  return pixels - explained;
}

SeabedBands seabedBands(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                        const SonarModel& sonar, int bins, double half, double step,
                        double voxel_size) {
  const auto rays = static_cast<std::size_t>(sonar.cols()) * static_cast<std::size_t>(bins);
  SeabedBands out{std::vector<float>(rays, std::numeric_limits<float>::infinity()),
                  std::vector<float>(rays, std::numeric_limits<float>::infinity())};
  const Eigen::Vector3d up = T_world_sonar.linear().transpose() * plane.normal;  // sonar frame
  for (int b = 0; b < sonar.cols(); ++b) {
    const double bearing = sonar.bearings().centre(b);
    for (int k = 0; k < bins; ++k) {
      const double el = -half + (k + 0.5) * step;
      const Eigen::Vector3d dir = rayDirection(el, bearing);
      const double range = seabedRange(plane, T_world_sonar, dir);
      if (!std::isfinite(range)) {
        continue;
      }
      // A voxel's centre lies within its half diagonal of the plane where the ray meets it,
      // which along a ray at grazing incidence spans more range (sine of the grazing angle,
      // floored at 0.1: 5.7 degrees).
      const double reach = std::sqrt(3.0) * voxel_size / std::max(0.1, -up.dot(dir));
      const auto i = static_cast<std::size_t>(b) * static_cast<std::size_t>(bins) +
                     static_cast<std::size_t>(k);
      out.from[i] = static_cast<float>(range - reach);
      out.to[i] = static_cast<float>(range + reach);
    }
  }
  return out;
}

std::optional<SeabedPlane> SeabedTracker::track(const cv::Mat& pixels,
                                                const Eigen::Isometry3d& T_world_sonar,
                                                const SonarModel& sonar, ThreadPool* pool) {
  if (!last_ && since_scan_ > 0) {
    since_scan_ = (since_scan_ + 1) % kScanEvery;
    return std::nullopt;
  }
  const SeabedFit fit = fitSeabed(pixels, T_world_sonar, sonar, last_ ? &*last_ : nullptr, pool);
  if (fit.correlation < kMinCorrelation) {
    last_.reset();
    since_scan_ = 1;
    return std::nullopt;
  }
  last_ = fit;
  ++found_;
  return fit.plane;
}

}  // namespace sonarcarve
