#include "carve/pose_refiner.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

// A move must lower the mean cost by this share of the robust scale squared: weaker gradients
// (along a direction the frame barely observes) do not move it.
constexpr double kMinGain = 0.002;
// Beams whose predicted and measured leading edges disagree by more than the robust scale (or
// where only one of them has a return) cost the scale squared: the frame agrees with the map
// in at least this share of its beams, or it gives no measurement.
constexpr double kMinAgreement = 0.5;
// Behind a detector only returns clear of the background give edges, and at the right pose a
// frame agrees with the map in nearly all of them (0.94 to 0.99 of its beams on the noisy riser
// without drift); frames that agree less see structure the map holds badly (the top of a
// structure that few frames see, a detector's blobs), and at 0.5 they pulled the noisy riser's
// track 9 cm away without any drift (docs/navigation.md).
constexpr double kMinAgreementBehindDetector = 0.9;
// The voxels kept for a frame: in front of what the map predicts at the start pose by no more
// than this many robust scales (and the farthest move of the search), within this margin
// beyond the carved elevation.
constexpr double kKeepBehindScales = 4.0;
constexpr double kElevationMargin_rad = degToRad(3.0);
constexpr double kBearingMargin_rad = degToRad(5.0);
// A leading edge's range is known to the range resolution (a uniform error over the bin,
// sigma = resolution / sqrt(12)), the map's edge to the voxel the same way: one effective
// beam's residual has this standard deviation in units of those.
constexpr double kResidualSigmaPerBin = 0.5;
// The axes searched: north, east, down and yaw. Roll and pitch turn the fan about the sonar
// itself, which keeps every range and, near the axis, every bearing: a frame barely observes
// them, and carving barely depends on them (an arc keeps its range and bearing), so they stay
// where the navigation put them.
constexpr std::array<int, 3> kSearchedAxes = {0, 1, 5};
constexpr int kMoves = 2 * static_cast<int>(kSearchedAxes.size());

Eigen::Matrix3d rotationAboutSonarAxes(const Eigen::Vector3d& roll_pitch_yaw) {
  return (Eigen::AngleAxisd(roll_pitch_yaw.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(roll_pitch_yaw.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll_pitch_yaw.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

Eigen::Isometry3d PoseCorrection::applied(const Eigen::Isometry3d& T_world_sonar_prior) const {
  Eigen::Isometry3d T = T_world_sonar_prior;
  T.linear() = T_world_sonar_prior.linear() * rotationAboutSonarAxes(rotation_sonar_rad);
  T.translation() += translation_world_m;
  return T;
}

Vector6d PoseCorrection::vector() const {
  Vector6d x;
  x << translation_world_m, rotation_sonar_rad;
  return x;
}

PoseCorrection PoseCorrection::of(const Vector6d& x) {
  PoseCorrection c;
  c.translation_world_m = x.head<3>();
  c.rotation_sonar_rad = x.tail<3>();
  return c;
}

PoseRefiner::PoseRefiner(const VoxelMap& map, const SonarModel& sonar, const CarveParams& carve,
                         PoseRefinementParams params, ThreadPool& pool)
    : geometry_(sonar, carve),
      carve_(carve),
      params_(params),
      pool_(pool),
      voxel_size_m_(map.voxelSize()) {
  if (!(params_.max_translation_m >= 0.0) || !(params_.max_rotation_rad >= 0.0)) {
    throw Error("parameters", "pose_refinement", "expected a search window >= 0");
  }
  map.forEachOccupiedOnShell([&](const Eigen::Vector3i& v, float value) {
    shell_.push_back(map.voxelCentre(v).cast<float>());
    shell_values_.push_back(value);
  });
  // The beam's power over |sin(elevation)| up to the end of its first side lobe: a voxel
  // lights a pixel where its on-axis value times the power there exceeds the keep level.
  // Carving by the seed paper's rule (a clipped beam) sees +-aperture/2 alike, nothing beyond.
  const SincSquaredBeam beam(sonar.verticalAperture());
  const bool beam_aware = carvesMainLobe(sonar, carve);
  max_sin_elevation_ = static_cast<float>(
      std::sin(beam_aware ? std::min(beam.null(2), 1.5) : 0.5 * sonar.verticalAperture()));
  power_.resize(kPowerTable);
  for (std::size_t i = 0; i < kPowerTable; ++i) {
    const double sine = (static_cast<double>(i) + 0.5) / kPowerTable * max_sin_elevation_;
    power_[i] = beam_aware ? static_cast<float>(beam.power(std::asin(sine))) : 1.0f;
  }
}

std::vector<float> PoseRefiner::leadingEdges(const cv::Mat& image,
                                             const EdgeWidening& widening) const {
  // Rows are range bins (near to far), columns beams: the near edge of the first lit bin. Behind
  // a detector, only one that begins a return (two of its first three bins lit: a lone speckle
  // the detector let through is not a surface); without one every lit pixel is a return.
  std::vector<float> edges(static_cast<std::size_t>(image.cols), kNoReturn);
  const float bin_min = geometry_.binMin();
  const auto resolution = static_cast<float>(geometry_.sonar().range().resolution_m);
  const auto r_min = static_cast<float>(geometry_.rangeMin());
  // Beams near the fan's edges are left out, as their voxels are (voxelsInView).
  const BearingTable& bearings = geometry_.sonar().bearings();
  const double left = bearings.centre(0) + kBearingMargin_rad;
  const double right = bearings.centre(bearings.count() - 1) - kBearingMargin_rad;
  const bool exact = carve_.dark_pixels == CarveParams::DarkPixels::Exact;
  const float lit_level = litLevel();
  const auto lit = [&](int r, int c) {
    return r < image.rows &&
           image.at<float>(r, c) > (edge_level_.empty() ? lit_level : edge_level_.at<float>(r, c));
  };
  for (int c = 0; c < image.cols; ++c) {
    if (bearings.centre(c) < left || bearings.centre(c) > right) {
      continue;
    }
    for (int r = 0; r < image.rows; ++r) {
      const float range = bin_min + resolution * static_cast<float>(r);
      if (range >= r_min && lit(r, c) && (exact || lit(r + 1, c) || lit(r + 2, c))) {
        edges[static_cast<std::size_t>(c)] = range;
        break;
      }
    }
  }
  if (widening.bins <= 0 && widening.beams <= 0) {
    return edges;
  }
  // The edges of the frame with its returns widened as the map's frames were: the nearest
  // edge within `beams` either side, `bins` nearer.
  std::vector<float> widened(edges.size(), kNoReturn);
  const int n = static_cast<int>(edges.size());
  const float nearer = resolution * static_cast<float>(std::max(widening.bins, 0));
  for (int c = 0; c < n; ++c) {
    if (bearings.centre(c) < left || bearings.centre(c) > right) {
      continue;
    }
    float edge = kNoReturn;
    for (int k = std::max(0, c - widening.beams); k <= std::min(n - 1, c + widening.beams); ++k) {
      edge = std::min(edge, edges[static_cast<std::size_t>(k)]);
    }
    widened[static_cast<std::size_t>(c)] = edge < kNoReturn ? std::max(edge - nearer, r_min) : edge;
  }
  return widened;
}

std::vector<Eigen::Vector4f> PoseRefiner::voxelsInView(const Eigen::Isometry3d& T_world_sonar,
                                                       const Eigen::Isometry3d& T_world_frame,
                                                       double keep_behind_m) const {
  // Voxels inside the carved lobe (and a margin beyond it: a move may bring them in), away
  // from the fan's edges, and no deeper than `keep_behind_m` behind the nearest voxel of their
  // beam: only the nearest voxel of a beam predicts its leading edge.
  const Eigen::Isometry3f T_sonar_world = T_world_sonar.inverse().cast<float>();
  const Eigen::Isometry3f T_frame_world = T_world_frame.inverse().cast<float>();
  const double half = std::min(std::asin(max_sin_elevation_) + kElevationMargin_rad, 1.5);
  const auto sin2 = static_cast<float>(std::pow(std::sin(half), 2));
  const float rmin2 = geometry_.rangeMinSq();
  const float rmax2 = geometry_.rangeMaxSq();
  const BearingTable& bearings = geometry_.sonar().bearings();
  const auto left = static_cast<float>(bearings.centre(0) + kBearingMargin_rad);
  const auto right = static_cast<float>(bearings.centre(bearings.count() - 1) - kBearingMargin_rad);
  std::vector<Eigen::Vector4f> in_view;
  std::vector<float> nearest(static_cast<std::size_t>(bearings.count()), kNoReturn);
  std::vector<int> beam_of;
  for (std::size_t k = 0; k < shell_.size(); ++k) {
    const Eigen::Vector3f& w = shell_[k];
    const Eigen::Vector3f p = T_sonar_world * w;
    const float r2 = p.squaredNorm();
    if (r2 < rmin2 || r2 >= rmax2 || p.z() * p.z() > r2 * sin2) {
      continue;
    }
    const float bearing = fastAtan2(p.y(), p.x());
    if (bearing < left || bearing > right) {
      continue;
    }
    const int beam = geometry_.beamOf(bearing);
    if (beam < 0) {
      continue;
    }
    const float r = std::sqrt(r2);
    float& near = nearest[static_cast<std::size_t>(beam)];
    near = std::min(near, r);
    in_view.emplace_back(w.x(), w.y(), w.z(), shell_values_[k]);
    beam_of.push_back(beam);
  }
  std::vector<Eigen::Vector4f> voxels;
  for (std::size_t k = 0; k < in_view.size(); ++k) {
    const Eigen::Vector3f w = in_view[k].head<3>();
    if ((T_sonar_world * w).norm() <=
        nearest[static_cast<std::size_t>(beam_of[k])] + keep_behind_m) {
      const Eigen::Vector3f q = T_frame_world * w;
      voxels.emplace_back(q.x(), q.y(), q.z(), in_view[k].w());
    }
  }
  if (voxels.size() > params_.max_voxels) {
    // Evenly thinned: neighbouring voxels predict the same edges.
    const double stride = static_cast<double>(voxels.size()) / params_.max_voxels;
    std::vector<Eigen::Vector4f> thinned;
    thinned.reserve(params_.max_voxels);
    for (std::size_t k = 0; k < params_.max_voxels; ++k) {
      thinned.push_back(voxels[static_cast<std::size_t>(k * stride)]);
    }
    voxels.swap(thinned);
  }
  return voxels;
}

double PoseRefiner::cost(const std::vector<float>& measured,
                         const std::vector<Eigen::Vector4f>& q_sonar,
                         const Eigen::Isometry3d& T_world_sonar_nav, const Vector6d& x,
                         double scale_m) const {
  // q is a voxel in the navigation's sonar frame; in the candidate's: R_d^T (q - R_nav^T t_d).
  const Eigen::Vector3f d = (T_world_sonar_nav.linear().transpose() * x.head<3>()).cast<float>();
  const Eigen::Matrix3f M = rotationAboutSonarAxes(x.tail<3>()).transpose().cast<float>();
  const auto half_voxel = static_cast<float>(0.5 * voxel_size_m_);
  const float lit = litLevel();
  const float table_scale = static_cast<float>(kPowerTable) / max_sin_elevation_;
  const float bin_min = geometry_.binMin();
  const float inv_resolution = geometry_.binInvResolution();
  std::vector<float> predicted(measured.size(), kNoReturn);
  for (const Eigen::Vector4f& q : q_sonar) {
    const Eigen::Vector3f p = M * (q.head<3>() - d);
    const float r = p.norm();
    const auto i = static_cast<std::size_t>(std::abs(p.z()) / r * table_scale);
    if (i >= kPowerTable || !(q.w() * power_[i] > lit)) {
      continue;  // outside the beam, or too faint there to light the pixel
    }
    // The voxel's width across the beams it covers.
    const float bearing = fastAtan2(p.y(), p.x());
    const float half_width = half_voxel / r;
    const int first = geometry_.beamOf(bearing - half_width);
    const int last = geometry_.beamOf(bearing + half_width);
    if (first < 0 || last < 0) {
      continue;
    }
    if (!edge_level_.empty()) {
      const int row = static_cast<int>((r - bin_min) * inv_resolution);
      if (row < 0 || row >= edge_level_.rows ||
          !(q.w() * power_[i] > edge_level_.at<float>(row, (first + last) / 2))) {
        continue;  // too faint to stand clear of the background
      }
    }
    for (int b = first; b <= last; ++b) {
      float& edge = predicted[static_cast<std::size_t>(b)];
      edge = std::min(edge, r - half_voxel);
    }
  }
  const double cap = scale_m * scale_m;
  double sum = 0.0;
  for (std::size_t b = 0; b < measured.size(); ++b) {
    const bool seen = measured[b] < kNoReturn;
    const bool expected = predicted[b] < kNoReturn;
    if (seen && expected) {
      const double e = static_cast<double>(predicted[b]) - measured[b];
      sum += std::min(e * e, cap);
    } else if (seen != expected) {
      sum += cap;
    }
  }
  return sum;
}

Vector6d PoseRefiner::clamped(Vector6d x) const {
  for (int a = 0; a < 3; ++a) {
    x[a] = std::clamp(x[a], -params_.max_translation_m, params_.max_translation_m);
    x[a + 3] = std::clamp(x[a + 3], -params_.max_rotation_rad, params_.max_rotation_rad);
  }
  return x;
}

double PoseRefiner::meanCostOf(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar_nav,
                               const PoseCorrection& correction, double scale_m) const {
  const std::vector<Eigen::Vector4f> q =
      voxelsInView(correction.applied(T_world_sonar_nav), T_world_sonar_nav, keepBehind(scale_m));
  const std::vector<float> measured = leadingEdges(image, {});
  return cost(measured, q, T_world_sonar_nav, correction.vector(), scale_m) /
         static_cast<double>(measured.size());
}

double PoseRefiner::keepBehind(double scale_m) const {
  return kKeepBehindScales * scale_m;
}

float PoseRefiner::litLevel() const {
  // What carving keeps: above the threshold and, beam-aware, above the keep level.
  return static_cast<float>(
      std::max(carve_.intensity_threshold,
               carvesMainLobe(geometry_.sonar(), carve_) ? carve_.keep_level : 0.0));
}

void PoseRefiner::keepVoxelsSeenBy(const std::vector<Eigen::Isometry3d>& T_world_sonar) {
  std::vector<std::uint32_t> views(shell_.size(), 0);
  const float sin2 = geometry_.sinHalfApertureSq();
  const float rmin2 = geometry_.rangeMinSq();
  const float rmax2 = geometry_.rangeMaxSq();
  pool_.parallelFor(shell_.size(), 4096, [&](std::size_t begin, std::size_t end) {
    for (const Eigen::Isometry3d& T : T_world_sonar) {
      const Eigen::Isometry3f T_sonar_world = T.inverse().cast<float>();
      for (std::size_t k = begin; k < end; ++k) {
        const Eigen::Vector3f p = T_sonar_world * shell_[k];
        const float r2 = p.squaredNorm();
        if (r2 >= rmin2 && r2 < rmax2 && p.z() * p.z() <= r2 * sin2 &&
            geometry_.beamOf(fastAtan2(p.y(), p.x())) >= 0) {
          ++views[k];
        }
      }
    }
  });
  std::size_t kept = 0;
  for (std::size_t k = 0; k < shell_.size(); ++k) {
    if (views[k] >= params_.min_views) {
      shell_[kept] = shell_[k];
      shell_values_[kept] = shell_values_[k];
      ++kept;
    }
  }
  shell_.resize(kept);
  shell_values_.resize(kept);
}

void PoseRefiner::setEdgeLevel(cv::Mat level) {
  const SonarModel& sonar = geometry_.sonar();
  if (!level.empty() &&
      (level.type() != CV_32F || level.rows != sonar.rows() || level.cols != sonar.cols())) {
    throw Error("pose refinement", "edge level", "does not match the sonar model");
  }
  // Never under the carving's own level: held once here, looked up per pixel.
  edge_level_ =
      level.empty() ? cv::Mat() : cv::Mat(cv::max(level, static_cast<double>(litLevel())));
}

PoseMeasurement PoseRefiner::measure(const cv::Mat& image,
                                     const Eigen::Isometry3d& T_world_sonar_nav,
                                     const Vector6d& start, double scale_m,
                                     const EdgeWidening& widening) const {
  const SonarModel& sonar = geometry_.sonar();
  if (image.type() != CV_32F || image.rows != sonar.rows() || image.cols != sonar.cols()) {
    throw Error("pose refinement", "frame", "image does not match the sonar model");
  }
  PoseMeasurement m;
  const Vector6d x0 = clamped(start);
  m.correction = PoseCorrection::of(x0);
  const std::vector<Eigen::Vector4f> q =
      voxelsInView(m.correction.applied(T_world_sonar_nav), T_world_sonar_nav, keepBehind(scale_m));
  m.correction.voxels = q.size();
  if (q.size() < params_.min_voxels) {
    return m;
  }
  const std::vector<float> measured = leadingEdges(image, widening);
  const double cap = scale_m * scale_m;
  const auto objective = [&](const Vector6d& x) {
    return cost(measured, q, T_world_sonar_nav, x, scale_m);
  };
  double mean_range = 0.0;
  for (const Eigen::Vector4f& p : q) {
    mean_range += p.head<3>().norm();
  }
  mean_range = std::max(mean_range / static_cast<double>(q.size()), 0.5);
  const auto stepOf = [&](int axis, double step) { return axis < 3 ? step : step / mean_range; };
  // The cost is counted per beam with a measured return.
  const auto beams = static_cast<std::size_t>(
      std::count_if(measured.begin(), measured.end(), [](float e) { return e < kNoReturn; }));
  if (beams == 0) {
    return m;
  }
  const double n = static_cast<double>(beams);
  const double min_gain = kMinGain * cap * n;

  Vector6d best = x0;
  double best_cost = objective(x0);
  std::vector<double> costs(kMoves);
  std::vector<Vector6d> moves(kMoves);
  std::vector<double> steps;
  for (double step = scale_m; step > 0.6 * voxel_size_m_; step *= 0.5) {
    steps.push_back(step);
  }
  steps.push_back(0.5 * voxel_size_m_);
  for (const double step : steps) {
    for (int iteration = 0; iteration < 12; ++iteration) {
      for (int k = 0; k < kMoves; ++k) {
        Vector6d x = best;
        const int axis = kSearchedAxes[static_cast<std::size_t>(k / 2)];
        x[axis] += (k % 2 == 0 ? 1.0 : -1.0) * stepOf(axis, step);
        moves[static_cast<std::size_t>(k)] = clamped(x);
      }
      pool_.parallelFor(moves.size(), 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
          costs[k] = objective(moves[k]);
        }
      });
      const auto top = std::min_element(costs.begin(), costs.end());
      if (!(*top < best_cost - min_gain)) {
        break;
      }
      best_cost = *top;
      best = moves[static_cast<std::size_t>(top - costs.begin())];
    }
  }
  m.correction = PoseCorrection::of(best);
  m.correction.voxels = q.size();
  m.correction.score_before = 1.0 - objective(Vector6d::Zero()) / (cap * n);
  m.correction.score_after = 1.0 - best_cost / (cap * n);
  if (m.correction.score_after <
      (edge_level_.empty() ? kMinAgreement : kMinAgreementBehindDetector)) {
    return m;
  }
  // The information: the mean cost per beam is sum(e^2)/n near the peak; as one effective
  // beam whose residual has sigma = kResidualSigmaPerBin range bins, information =
  // Hessian(mean cost) / (2 sigma^2). Central differences one voxel apart (rotations: its arc
  // at the mean range).
  Vector6d h;
  for (int a = 0; a < 6; ++a) {
    h[a] = stepOf(a, voxel_size_m_);
  }
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < kSearchedAxes.size(); ++i) {
    for (std::size_t j = i; j < kSearchedAxes.size(); ++j) {
      pairs.emplace_back(kSearchedAxes[i], kSearchedAxes[j]);
    }
  }
  std::vector<double> second(pairs.size());
  pool_.parallelFor(pairs.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const auto [a, b] = pairs[k];
      const auto at = [&](double sa, double sb) {
        Vector6d x = best;
        x[a] += sa * h[a];
        x[b] += sb * h[b];
        return objective(x);
      };
      second[k] = a == b ? (at(0.5, 0.5) - 2.0 * best_cost + at(-0.5, -0.5)) / (h[a] * h[a])
                         : (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4.0 * h[a] * h[b]);
    }
  });
  const double sigma = kResidualSigmaPerBin * sonar.range().resolution_m;
  Matrix6d H = Matrix6d::Zero();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    H(a, b) = H(b, a) = second[k] / (n * 2.0 * sigma * sigma);
  }
  // Only the directions in which the cost rises away from the minimum more sharply than one
  // expected step of the navigation's drift carry information: the frame measures them better
  // than the track's prior knows them. Weaker ones (along the valley where a shift across the
  // beams and a turn move a structure's image alike) are left to the track. Compared in
  // metres: rotations as their arcs at the voxels' mean range.
  Vector6d arc = Vector6d::Ones();
  arc.tail<3>().setConstant(mean_range);
  const Matrix6d H_m = arc.cwiseInverse().asDiagonal() * H * arc.cwiseInverse().asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(H_m);
  const double step_information = 1.0 / (params_.step_sigma_m * params_.step_sigma_m);
  Vector6d values = eigen.eigenvalues();
  for (int i = 0; i < 6; ++i) {
    values[i] = values[i] > step_information ? values[i] : 0.0;
  }
  m.information = arc.asDiagonal() *
                  (eigen.eigenvectors() * values.asDiagonal() * eigen.eigenvectors().transpose()) *
                  arc.asDiagonal();
  m.correction.aligned = true;
  return m;
}

}  // namespace sonarcarve
