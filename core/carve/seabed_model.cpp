#include "carve/seabed_model.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "carve/internal/seabed_rays.h"
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
  return SeabedSurface{plane}.rayRange(T_world_sonar.translation(),
                                       T_world_sonar.linear() * direction_sonar);
}

namespace seabed_internal {

Eigen::Vector3d rayDirection(double elevation_rad, double bearing_rad) {
  return {std::cos(elevation_rad) * std::cos(bearing_rad),
          std::cos(elevation_rad) * std::sin(bearing_rad), -std::sin(elevation_rad)};
}

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

void depositInterval(std::vector<float>& column, double r0, double r1, double weight,
                     const RangeBins& bins) {
  const int rows = static_cast<int>(column.size());
  const double inv_res = 1.0 / bins.resolution_m;
  double lo = (std::min(r0, r1) - bins.min_m) * inv_res;
  double hi = (std::max(r0, r1) - bins.min_m) * inv_res;
  if (hi < 0.0 || lo >= rows) {
    return;
  }
  if (hi - lo < 1e-6) {
    column[static_cast<std::size_t>(std::clamp(static_cast<int>(lo), 0, rows - 1))] +=
        static_cast<float>(weight);
    return;
  }
  const double density = weight / (hi - lo);
  lo = std::max(lo, 0.0);
  hi = std::min(hi, static_cast<double>(rows));
  for (int b = static_cast<int>(lo); b < hi; ++b) {
    const double overlap = std::min(hi, b + 1.0) - std::max(lo, static_cast<double>(b));
    column[static_cast<std::size_t>(b)] += static_cast<float>(density * overlap);
  }
}

std::vector<SurfaceInterval> surfaceIntervals(const BeamRays& rays, std::size_t i,
                                              const SeabedSurface& surface,
                                              const Eigen::Vector3d& position,
                                              const std::vector<double>& end_ranges) {
  const Eigen::Vector3d* centres = rays.centres.data() + i * rays.intervals;
  std::vector<SurfaceInterval> out;
  out.reserve(static_cast<std::size_t>(rays.intervals));
  for (std::size_t k = 0; k < static_cast<std::size_t>(rays.intervals); ++k) {
    const double rc = surface.rayRange(position, centres[k]);
    if (!std::isfinite(rc)) {
      continue;
    }
    const Eigen::Vector3d c = position + rc * centres[k];
    const double tc = surface.upNormal(c).dot(centres[k]);
    if (!(tc < -1e-9)) {
      continue;  // the relief faces away from the ray
    }
    SurfaceInterval iv;
    iv.k = k;
    iv.own0 = std::isfinite(end_ranges[k]);
    iv.own1 = std::isfinite(end_ranges[k + 1]);
    iv.r0 = iv.own0 ? end_ranges[k] : rc;
    iv.r1 = iv.own1 ? end_ranges[k + 1] : rc;
    iv.weight = rays.weights[k] * -tc;
    iv.centre_hit = c;
    out.push_back(iv);
  }
  return out;
}

void accumulateOnSurface(std::vector<float>& column, const BeamRays& rays, std::size_t i,
                         const SeabedSurface& surface, const Eigen::Vector3d& position,
                         const RangeBins& bins) {
  const Eigen::Vector3d* ends = rays.ends.data() + i * (rays.intervals + 1);
  std::vector<double> end_ranges(static_cast<std::size_t>(rays.intervals) + 1);
  for (std::size_t k = 0; k < end_ranges.size(); ++k) {
    end_ranges[k] = surface.rayRange(position, ends[k]);
  }
  for (const SurfaceInterval& iv : surfaceIntervals(rays, i, surface, position, end_ranges)) {
    depositInterval(column, iv.r0, iv.r1, iv.weight, bins);
  }
}

}  // namespace seabed_internal

namespace {

using namespace seabed_internal;

double heightOver(const SeabedPlane& plane, const Eigen::Vector3d& sonar_position) {
  return plane.normal.dot(sonar_position) - plane.offset;
}

// Adds beam i of `rays` seen over `plane` from `height` to `column` (one value per range
// bin): each interval's weight times cos(incidence) spread evenly over the ranges between its
// ends, as a surface spreads its return between two rays.
void accumulateBeam(std::vector<float>& column, const BeamRays& rays, std::size_t i,
                    const SeabedPlane& plane, double height, const RangeBins& bins) {
  const Eigen::Vector3d* ends = rays.ends.data() + i * (rays.intervals + 1);
  const Eigen::Vector3d* centres = rays.centres.data() + i * rays.intervals;
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
    depositInterval(column, r0, r1, weight, bins);
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
constexpr float kNoiseClip = 3.0f;
constexpr std::size_t kSectors = 8;
constexpr int kStructureBox = 5;
constexpr double kSureStructure = 5.0;

}  // namespace

cv::Mat predictSeabedImage(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                           const SonarModel& sonar, ThreadPool* pool) {
  const BeamRays rays = beamRays(sonar, T_world_sonar.linear(), 1, kPredictionStep_rad, pool);
  return predictedImage(rays, plane, T_world_sonar.translation(), sonar, pool);
}

cv::Mat predictSeabedImage(const SeabedSurface& surface, const Eigen::Isometry3d& T_world_sonar,
                           const SonarModel& sonar, ThreadPool* pool) {
  if (surface.field == nullptr) {
    return predictSeabedImage(surface.plane, T_world_sonar, sonar, pool);
  }
  const BeamRays rays = beamRays(sonar, T_world_sonar.linear(), 1, kPredictionStep_rad, pool);
  cv::Mat image = cv::Mat::zeros(sonar.rows(), sonar.cols(), CV_32F);
  forEachBeam(pool, rays.beams.size(), [&](std::size_t i) {
    std::vector<float> column(static_cast<std::size_t>(sonar.rows()), 0.0f);
    accumulateOnSurface(column, rays, i, surface, T_world_sonar.translation(), sonar.range());
    for (int r = 0; r < sonar.rows(); ++r) {
      image.at<float>(r, rays.beams[i]) = column[static_cast<std::size_t>(r)];
    }
  });
  return image;
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

// Sums over the fitted pixels of one beam or of a frame (NaN in the data: left out), each
// pixel weighted by `weights` where given (1 / the background's variance), else by 1:
// w v e, w e e and w v v for pixel v and prediction e.
struct FitSums {
  double ve = 0.0, ee = 0.0, vv = 0.0;
  FitSums& operator+=(const FitSums& o) {
    ve += o.ve;
    ee += o.ee;
    vv += o.vv;
    return *this;
  }
};

// Per beam of `rays`, the sums of `data` (rows x fit beams) against a plane's predicted image;
// empty if the sonar is not over the plane.
std::vector<FitSums> beamSums(const cv::Mat& data, const cv::Mat& weights, const BeamRays& rays,
                              const SeabedPlane& plane, const Eigen::Vector3d& position,
                              const RangeBins& bins, ThreadPool* pool) {
  const double height = heightOver(plane, position);
  if (!(height > 0.0)) {
    return {};
  }
  std::vector<FitSums> sums(rays.beams.size());
  forEachBeam(pool, rays.beams.size(), [&](std::size_t i) {
    std::vector<float> column(static_cast<std::size_t>(data.rows), 0.0f);
    accumulateBeam(column, rays, i, plane, height, bins);
    FitSums s;
    for (int r = 0; r < data.rows; ++r) {
      const double e = column[static_cast<std::size_t>(r)];
      const double v = data.at<float>(r, static_cast<int>(i));
      if (std::isnan(v)) {
        continue;  // left out of the fit
      }
      const double w = weights.empty() ? 1.0 : weights.at<float>(r, static_cast<int>(i));
      s.ve += w * v * e;
      s.ee += w * e * e;
      s.vv += w * v * v;
    }
    sums[i] = s;
  });
  return sums;
}

FitSums frameSums(const std::vector<FitSums>& beams) {
  FitSums total;
  for (const auto& s : beams) {
    total += s;
  }
  return total;
}

// Normalised correlation of `data` (rows x fit beams) with a plane's predicted image.
double correlation(const cv::Mat& data, const BeamRays& rays, const SeabedPlane& plane,
                   const Eigen::Vector3d& position, const RangeBins& bins, ThreadPool* pool) {
  const FitSums s = frameSums(beamSums(data, {}, rays, plane, position, bins, pool));
  if (!(s.ee > 0.0) || !(s.vv > 0.0)) {
    return 0.0;
  }
  return s.ve / std::sqrt(s.ee * s.vv);
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

// 1 / sigma^2 per pixel (sigma floored at one count).
cv::Mat inverseVariance(const cv::Mat& sigma) {
  cv::Mat floored = cv::max(sigma, 1.0f);
  cv::Mat weights;
  cv::divide(1.0, floored.mul(floored), weights, CV_32F);
  return weights;
}

// Behind a detector, the sums over cells of the fan: kSectors runs of its beams, each cut in
// two along range where the plane's prediction has half its energy (the near and the far
// seabed). `data` and `weights` are rows x fit beams, `predicted` the full image.
std::vector<FitSums> cellSums(const cv::Mat& data, const cv::Mat& weights, const BeamRays& rays,
                              const cv::Mat& predicted) {
  const std::size_t per = (rays.beams.size() + kSectors - 1) / kSectors;
  std::vector<FitSums> cells(2 * ((rays.beams.size() + per - 1) / per));
  for (std::size_t i = 0; i < rays.beams.size(); ++i) {
    const int c = static_cast<int>(i);
    double energy = 0.0;
    for (int r = 0; r < data.rows; ++r) {
      const double e = predicted.at<float>(r, rays.beams[i]);
      energy += e * e;
    }
    double before = 0.0;
    for (int r = 0; r < data.rows; ++r) {
      const double e = predicted.at<float>(r, rays.beams[i]);
      before += e * e;
      const double v = data.at<float>(r, c);
      if (std::isnan(v) || !(e > 0.0)) {
        continue;
      }
      const double w = weights.at<float>(r, c);
      FitSums& cell = cells[2 * (i / per) + (before > 0.5 * energy ? 1 : 0)];
      cell.ve += w * v * e;
      cell.ee += w * e * e;
    }
  }
  return cells;
}

// Behind a detector: whether a plane's amplitude, fitted over each cell on its own, agrees
// with the whole fan's where the cell measures it (its standard error under half the
// amplitude): within three standard errors and half the amplitude (Lambert's law is only an
// approximation of a seabed's scattering) in three cells of four, and at least four cells
// measure it. A seabed spans the fan and its range; structure that a plane happens to cross
// (the top of a template a metre over the seabed) lights some cells only.
bool spansTheFan(const std::vector<FitSums>& cells) {
  const FitSums total = frameSums(cells);
  if (!(total.ee > 0.0) || !(total.ve > 0.0)) {
    return false;
  }
  const double amplitude = total.ve / total.ee;
  int measured = 0, agreeing = 0;
  for (const FitSums& s : cells) {
    if (!(s.ee > 0.0)) {
      continue;
    }
    const double error = 1.0 / std::sqrt(s.ee);
    if (error >= 0.5 * amplitude) {
      continue;
    }
    ++measured;
    agreeing += std::abs(s.ve / s.ee - amplitude) <= 3.0 * error + 0.5 * amplitude ? 1 : 0;
  }
  return measured >= 4 && 4 * agreeing >= 3 * measured;
}

// What the two fits share: the plane's parameters searched from a prior (moving at most
// kMaxDepthStep_m and kMaxSlopeStep a frame: the seabed is one surface, and what pulls a fit
// further is structure coming into view), or without one from a scan of level planes on a
// coarse ray set (every 16th beam, 0.5 degree intervals) and a free search; then kRefits
// rounds, each choosing the pixels to fit for the plane found so far and searching again.
struct PlaneSearch {
  const SonarModel& sonar;
  Eigen::Isometry3d T_world_sonar;
  ThreadPool* pool;
  /// The score of a plane on the fit's current pixels.
  std::function<double(const SeabedPlane&)> score;
  /// For the scan: the score on the coarse rays, their pixels prepared once.
  std::function<std::function<double(const SeabedPlane&)>(const BeamRays&)> coarse_scorer;
  /// Chooses the pixels to fit for the plane found so far and its predicted image.
  std::function<void(const SeabedPlane&, const cv::Mat& predicted)> choose_pixels;
  /// Without a prior, a scan whose best score is under this ends the search: no seabed.
  double least_scan_score = 0.0;
};

SeabedPlane planeAt(const Eigen::Vector3d& at, const FitParams& p) {
  return SeabedPlane::sloped(at, p.depth, p.sn, p.se);
}

// The plane found and its score, or with `found` false the scan's best when it found no
// seabed.
struct PlaneFound {
  SeabedPlane plane;
  double score = 0.0;
  bool found = false;
};

PlaneFound searchPlane(const PlaneSearch& search, const BeamRays& rays, const SeabedFit* prior) {
  const Eigen::Vector3d at = search.T_world_sonar.translation();
  FitParams best{at.z() + 1.0, 0.0, 0.0};
  FitParams start = best;
  bool bounded = false;
  if (prior != nullptr && prior->explains) {
    const SeabedPlane& pq = prior->plane;
    best = {pq.depthAt(at.x(), at.y()), pq.normal.x() / -pq.normal.z(),
            pq.normal.y() / -pq.normal.z()};
    start = best;
    bounded = true;
  } else {
    const BeamRays coarse = beamRays(search.sonar, search.T_world_sonar.linear(),
                                     4 * kFitBeamStride, 2.5 * kFitStep_rad, search.pool);
    const auto coarse_score = search.coarse_scorer(coarse);
    double best_score = 0.0;
    for (double h = 0.3; h < search.sonar.range().maxRange(); h += 0.1) {
      const FitParams p{at.z() + h, 0.0, 0.0};
      const double s = coarse_score(planeAt(at, p));
      if (s > best_score) {
        best_score = s;
        best = p;
      }
    }
    if (best_score < search.least_scan_score) {
      return {planeAt(at, best), best_score, false};
    }
    patternSearch(best, 0.04, 0.02,
                  [&](const FitParams& p) { return search.score(planeAt(at, p)); });
  }
  double score = 0.0;
  for (int round = 0; round < kRefits; ++round) {
    search.choose_pixels(planeAt(at, best),
                         predictedImage(rays, planeAt(at, best), at, search.sonar, search.pool));
    score = patternSearch(best, 0.01, 0.002, [&](const FitParams& p) {
      if (bounded && (std::abs(p.depth - start.depth) > kMaxDepthStep_m ||
                      std::abs(p.sn - start.sn) > kMaxSlopeStep ||
                      std::abs(p.se - start.se) > kMaxSlopeStep)) {
        return -1.0;
      }
      return search.score(planeAt(at, p));
    });
  }
  return {planeAt(at, best), score, true};
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
  PlaneSearch search{
      sonar, T_world_sonar, pool, nullptr, nullptr, nullptr, 0.5 * SeabedTracker::kMinCorrelation};
  search.score = [&](const SeabedPlane& plane) {
    return correlation(data, rays, plane, at, sonar.range(), pool);
  };
  search.coarse_scorer = [&](const BeamRays& coarse) {
    cv::Mat coarse_data;
    cv::min(fitPixels(pixels, coarse), clip, coarse_data);
    return [&, coarse_data](const SeabedPlane& plane) {
      return correlation(coarse_data, coarse, plane, at, sonar.range(), pool);
    };
  };
  // The refits run on the unclipped pixels, leaving out those the last plane does not
  // explain: structure (over kOutlierFactor times its prediction) and acoustic shadows (under
  // a kOutlierFactor-th of it), give or take two counts of rounding. Without the shadows a box
  // on the seabed pulled the plane 4 cm up as it came nearer; with them, under 1 cm.
  search.choose_pixels = [&](const SeabedPlane&, const cv::Mat& predicted) {
    const double scale = medianRatio(pixels, predicted, 0.0);
    for (int r = 0; r < raw.rows; ++r) {
      for (std::size_t i = 0; i < rays.beams.size(); ++i) {
        const double v = raw.at<float>(r, static_cast<int>(i));
        const double e = scale * predicted.at<float>(r, rays.beams[i]);
        const bool outlier = v > kOutlierFactor * e + 2.0 || v < e / kOutlierFactor - 2.0;
        data.at<float>(r, static_cast<int>(i)) =
            outlier ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(v);
      }
    }
  };
  const PlaneFound found = searchPlane(search, rays, prior);
  return {found.plane, found.score, 0.0,
          found.found && found.score >= SeabedTracker::kMinCorrelation};
}

SeabedFit fitSeabedInNoise(const BeforeDetection& frame, const Eigen::Isometry3d& T_world_sonar,
                           const SonarModel& sonar, const SeabedFit* prior, ThreadPool* pool) {
  const BeamRays rays = beamRays(sonar, T_world_sonar.linear(), kFitBeamStride, kFitStep_rad, pool);
  const cv::Mat raw = fitPixels(frame.excess, rays);
  const cv::Mat fit_sigma = fitPixels(frame.sigma, rays);
  const cv::Mat weights = inverseVariance(fit_sigma);
  cv::Mat data;
  cv::min(raw, kNoiseClip * fit_sigma, data);
  // Structure is told from the seabed on the frame averaged over kStructureBox pixels, where
  // the background's deviation is that many times smaller: clipping alone let the manifold's
  // bright template tilt the plane by half a degree.
  cv::Mat averaged;
  cv::blur(frame.excess, averaged, cv::Size(kStructureBox, kStructureBox));
  const cv::Mat fit_averaged = fitPixels(averaged, rays);
  const Eigen::Vector3d at = T_world_sonar.translation();
  // The matched filter's signal to noise: the weighted projection on the prediction over
  // its noise.
  const auto significance = [&](const cv::Mat& d, const cv::Mat& w, const BeamRays& r,
                                const SeabedPlane& plane) {
    const FitSums s = frameSums(beamSums(d, w, r, plane, at, sonar.range(), pool));
    return s.ee > 0.0 ? s.ve / std::sqrt(s.ee) : 0.0;
  };
  PlaneSearch search{
      sonar, T_world_sonar, pool, nullptr, nullptr, nullptr, 0.5 * SeabedTracker::kMinSignificance};
  search.score = [&](const SeabedPlane& plane) { return significance(data, weights, rays, plane); };
  search.coarse_scorer = [&](const BeamRays& coarse) {
    const cv::Mat coarse_sigma = fitPixels(frame.sigma, coarse);
    const cv::Mat coarse_weights = inverseVariance(coarse_sigma);
    cv::Mat coarse_data;
    cv::min(fitPixels(frame.excess, coarse), kNoiseClip * coarse_sigma, coarse_data);
    return [&, coarse_data, coarse_weights](const SeabedPlane& plane) {
      return significance(coarse_data, coarse_weights, coarse, plane);
    };
  };
  search.choose_pixels = [&](const SeabedPlane& plane, const cv::Mat& predicted) {
    const FitSums s = frameSums(beamSums(data, weights, rays, plane, at, sonar.range(), pool));
    const double amplitude = s.ee > 0.0 ? s.ve / s.ee : 0.0;
    forEachBeam(pool, rays.beams.size(), [&](std::size_t i) {
      const int c = static_cast<int>(i);
      bool shadowed = false;
      for (int r = 0; r < raw.rows; ++r) {
        const float sigma = fit_sigma.at<float>(r, c);
        const double e = amplitude * predicted.at<float>(r, rays.beams[i]);
        const double over = fit_averaged.at<float>(r, c) - kOutlierFactor * e;
        const bool structure = over > kNoiseClip * sigma / kStructureBox;
        // Past the first sure return of structure along the beam, its shadow may hide the
        // seabed, and no pixel says where: a shadow under a weak seabed's return is not told
        // from the noise.
        shadowed = shadowed || over > kSureStructure * sigma / kStructureBox;
        data.at<float>(r, c) = structure || shadowed
                                   ? std::numeric_limits<float>::quiet_NaN()
                                   : std::min(raw.at<float>(r, c), kNoiseClip * sigma);
      }
    });
  };
  const PlaneFound found = searchPlane(search, rays, prior);
  SeabedFit fit{found.plane, 0.0, found.score, false};
  fit.explains =
      found.found && fit.significance >= SeabedTracker::kMinSignificance &&
      spansTheFan(cellSums(data, weights, rays, predictedImage(rays, fit.plane, at, sonar, pool)));
  return fit;
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

SeabedBands seabedBands(const SeabedSurface& surface, const Eigen::Isometry3d& T_world_sonar,
                        const SonarModel& sonar, int bins, double half, double step,
                        double voxel_size, double doubt_m) {
  const auto rays = static_cast<std::size_t>(sonar.cols()) * static_cast<std::size_t>(bins);
  SeabedBands out{std::vector<float>(rays, std::numeric_limits<float>::infinity()),
                  std::vector<float>(rays, std::numeric_limits<float>::infinity()),
                  std::vector<float>(rays, std::numeric_limits<float>::infinity())};
  const Eigen::Matrix3d& R = T_world_sonar.linear();
  const Eigen::Vector3d& position = T_world_sonar.translation();
  const Eigen::Vector3d plane_up = R.transpose() * surface.plane.normal;  // sonar frame
  for (int b = 0; b < sonar.cols(); ++b) {
    const double bearing = sonar.bearings().centre(b);
    for (int k = 0; k < bins; ++k) {
      const double el = -half + (k + 0.5) * step;
      const Eigen::Vector3d dir = rayDirection(el, bearing);
      const double range = surface.rayRange(position, R * dir);
      if (!std::isfinite(range)) {
        continue;
      }
      const Eigen::Vector3d up =
          surface.field == nullptr
              ? plane_up
              : Eigen::Vector3d(R.transpose() * surface.upNormal(position + range * (R * dir)));
      // A voxel's centre lies within its half diagonal of the seabed where the ray meets it,
      // which along a ray at grazing incidence spans more range (sine of the grazing angle,
      // floored at 0.1: 5.7 degrees).
      const double sine = std::max(0.1, -up.dot(dir));
      const double reach = std::sqrt(3.0) * voxel_size / sine;
      const auto i = static_cast<std::size_t>(b) * static_cast<std::size_t>(bins) +
                     static_cast<std::size_t>(k);
      out.from[i] = static_cast<float>(range - reach);
      out.to[i] = static_cast<float>(range + reach);
      out.doubt_from[i] = static_cast<float>(range - reach - doubt_m / sine);
    }
  }
  return out;
}

SeabedBands seabedBands(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                        const SonarModel& sonar, int bins, double half, double step,
                        double voxel_size, double doubt_m) {
  return seabedBands(SeabedSurface{plane}, T_world_sonar, sonar, bins, half, step, voxel_size,
                     doubt_m);
}

std::optional<SeabedPlane> SeabedTracker::track(const cv::Mat& pixels,
                                                const Eigen::Isometry3d& T_world_sonar,
                                                const SonarModel& sonar, ThreadPool* pool,
                                                const BeforeDetection* before) {
  if (!last_ && since_scan_ > 0) {
    since_scan_ = (since_scan_ + 1) % kScanEvery;
    return std::nullopt;
  }
  const SeabedFit* prior = last_ ? &*last_ : nullptr;
  const bool noisy = behindDetector(before);
  const SeabedFit fit = noisy ? fitSeabedInNoise(*before, T_world_sonar, sonar, prior, pool)
                              : fitSeabed(pixels, T_world_sonar, sonar, prior, pool);
  if (!fit.explains) {
    // Behind a detector a frame of weak seabed (structure over it, its shadow) is expected:
    // the last plane stays the prior for up to kScanEvery frames, where a fresh scan could
    // lock onto structure.
    if (noisy && last_ && ++misses_ <= kScanEvery) {
      return std::nullopt;
    }
    last_.reset();
    misses_ = 0;
    since_scan_ = 1;
    return std::nullopt;
  }
  misses_ = 0;
  last_ = fit;
  ++found_;
  return fit.plane;
}

}  // namespace sonarcarve
