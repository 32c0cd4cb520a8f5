#include "carve/pose_refiner.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "common/error.h"

namespace sonarcarve {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Range bins after dark water that count as a return's leading edge: a surface's response
// spans about a bin or two (the range resolution and the voxel).
constexpr int kLeadingEdgeBins = 2;
// Range bins of dark water just before a leading edge: certainly empty, since the surface
// that returns begins behind them.
constexpr int kWaterBins = 3;
// What a change of one expected step from the carried correction costs each voxel: a tenth
// of a hundredth of what a voxel gains by moving from dark water onto an edge (-1 to 1).
constexpr double kTrackPriorWeight = 0.01;
// A move must raise the mean score by this much (a voxel in a hundred from dark water onto an
// edge): weaker gradients (along a direction the frame barely observes) do not move it.
constexpr double kMinGainPerVoxel = 0.01;
// The mean score a frame must reach to be aligned.
constexpr double kMinAgreement = 0.1;
// Margins inside the view of the voxels scored.
constexpr double kElevationMargin_rad = degToRad(2.0);
constexpr double kBearingMargin_rad = degToRad(5.0);

Eigen::Matrix3d rotationAboutSonarAxes(const Eigen::Vector3d& roll_pitch_yaw) {
  return (Eigen::AngleAxisd(roll_pitch_yaw.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(roll_pitch_yaw.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll_pitch_yaw.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// A correction from the search's vector (translation, then rotation), and back.
PoseCorrection correctionOf(const Vector6d& x) {
  PoseCorrection c;
  c.translation_world_m = x.head<3>();
  c.rotation_sonar_rad = x.tail<3>();
  return c;
}

Vector6d vectorOf(const PoseCorrection& c) {
  Vector6d x;
  x << c.translation_world_m, c.rotation_sonar_rad;
  return x;
}

}  // namespace

Eigen::Isometry3d PoseCorrection::applied(const Eigen::Isometry3d& T_world_sonar_prior) const {
  Eigen::Isometry3d T = T_world_sonar_prior;
  T.linear() = T_world_sonar_prior.linear() * rotationAboutSonarAxes(rotation_sonar_rad);
  T.translation() += translation_world_m;
  return T;
}

PoseRefiner::PoseRefiner(const VoxelMap& map, const SonarModel& sonar, const CarveParams& carve,
                         PoseRefinementParams params, ThreadPool& pool)
    : map_(map), geometry_(sonar, carve), carve_(carve), params_(params), pool_(pool) {
  if (!map_.hasCounts()) {
    throw Error("pose refinement", "map", "expected a map that keeps its voxels' view counts");
  }
  if (!(params_.max_translation_m >= 0.0) || !(params_.max_rotation_rad >= 0.0)) {
    throw Error("parameters", "pose_refinement", "expected a search window >= 0");
  }
}

cv::Mat PoseRefiner::edgeField(const cv::Mat& image) const {
  // Rows are range bins (near to far), columns beams.
  cv::Mat field(image.size(), CV_32F, cv::Scalar(0.0f));
  const auto threshold = static_cast<float>(carve_.intensity_threshold);
  for (int c = 0; c < image.cols; ++c) {
    bool was_lit = true;  // the window's near edge is no surface
    for (int r = 0; r < image.rows; ++r) {
      const bool lit = image.at<float>(r, c) > threshold;
      if (lit && !was_lit) {
        for (int k = std::max(0, r - kWaterBins); k < r; ++k) {
          field.at<float>(k, c) = -1.0f;
        }
        for (int k = r; k < std::min(image.rows, r + kLeadingEdgeBins); ++k) {
          if (image.at<float>(k, c) > threshold) {
            field.at<float>(k, c) = 1.0f;
          }
        }
      }
      was_lit = lit;
    }
  }
  // Over a range bin: a voxel half a bin off its edge keeps part of its score.
  cv::GaussianBlur(field, field, cv::Size(1, 5), 0.0, 1.0, cv::BORDER_REPLICATE);
  return field;
}

std::vector<Eigen::Vector3f> PoseRefiner::settledVoxels(
    const Eigen::Isometry3d& T_world_sonar, const Eigen::Isometry3d& T_world_frame) const {
  std::vector<Eigen::Vector3f> voxels;
  Eigen::Vector3i lo, hi;
  if (!map_.blockSpan(
          geometry_.frustumBounds(T_world_sonar, 0.5 * geometry_.sonar().verticalAperture()), lo,
          hi)) {
    return voxels;
  }
  // Voxels well inside the view: inside +-aperture/2 less a margin and away from the fan's
  // edges, so that the moves of the search do not take them out of the image.
  const Eigen::Isometry3f T_sonar_world = T_world_sonar.inverse().cast<float>();
  const Eigen::Isometry3f T_frame_world = T_world_frame.inverse().cast<float>();
  const double half = 0.5 * geometry_.sonar().verticalAperture() - kElevationMargin_rad;
  const auto sin2 = static_cast<float>(std::pow(std::sin(std::max(half, 0.0)), 2));
  const float rmin2 = geometry_.rangeMinSq();
  const float rmax2 = geometry_.rangeMaxSq();
  const BearingTable& bearings = geometry_.sonar().bearings();
  const auto left = static_cast<float>(bearings.centre(0) + kBearingMargin_rad);
  const auto right = static_cast<float>(bearings.centre(bearings.count() - 1) - kBearingMargin_rad);
  const auto settled = static_cast<std::uint8_t>(
      std::clamp(params_.settled_views, 1, static_cast<int>(VoxelMap::kViewCountMask)));
  constexpr std::uint8_t kBothSides = VoxelMap::kSeenAbove | VoxelMap::kSeenBelow;
  for (int bz = lo.z(); bz <= hi.z(); ++bz) {
    for (int by = lo.y(); by <= hi.y(); ++by) {
      for (int bx = lo.x(); bx <= hi.x(); ++bx) {
        const std::size_t b = map_.blockIndex({bx, by, bz});
        const float* values = map_.values(b);
        if (values == nullptr) {
          continue;
        }
        const std::uint8_t* views = map_.views(b);
        for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
          if ((views[i] & kBothSides) != kBothSides ||
              (views[i] & VoxelMap::kViewCountMask) < settled ||
              !(values[i] > 0.0f && values[i] < VoxelMap::kUnknown)) {
            continue;
          }
          const Eigen::Vector3f w = map_.voxelCentre(map_.voxelIndex(b, i)).cast<float>();
          const Eigen::Vector3f p = T_sonar_world * w;
          const float r2 = p.squaredNorm();
          const float bearing = std::atan2(p.y(), p.x());
          if (r2 < rmin2 || r2 >= rmax2 || p.z() * p.z() > r2 * sin2 || bearing < left ||
              bearing > right) {
            continue;
          }
          voxels.push_back(T_frame_world * w);
        }
      }
    }
  }
  if (voxels.size() > params_.max_voxels) {
    const double stride = static_cast<double>(voxels.size()) / params_.max_voxels;
    std::vector<Eigen::Vector3f> thinned;
    thinned.reserve(params_.max_voxels);
    for (std::size_t k = 0; k < params_.max_voxels; ++k) {
      thinned.push_back(voxels[static_cast<std::size_t>(k * stride)]);
    }
    voxels.swap(thinned);
  }
  return voxels;
}

double PoseRefiner::score(const cv::Mat& field, const std::vector<Eigen::Vector3f>& q_sonar,
                          const Eigen::Isometry3d& T_world_sonar_prior, const Vector6d& x) const {
  // q is a voxel in the prior's sonar frame; in the candidate's: R_d^T (q - R_prior^T t_d).
  const Eigen::Vector3f d = (T_world_sonar_prior.linear().transpose() * x.head<3>()).cast<float>();
  const Eigen::Matrix3f M = rotationAboutSonarAxes(x.tail<3>()).transpose().cast<float>();
  const float bin_min = geometry_.binMin();
  const float inv_res = geometry_.binInvResolution();
  double sum = 0.0;
  for (const Eigen::Vector3f& q : q_sonar) {
    // The same voxels whatever the candidate: one that the move takes out of the image
    // counts as dark water.
    const Eigen::Vector3f p = M * (q - d);
    const int beam = geometry_.beamOf(fastAtan2(p.y(), p.x()));
    const int row = static_cast<int>((p.norm() - bin_min) * inv_res);
    sum += beam < 0 || row < 0 || row >= field.rows ? -1.0f : field.at<float>(row, beam);
  }
  return sum;
}

double PoseRefiner::scoreOf(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar_prior,
                            const PoseCorrection& correction) const {
  const std::vector<Eigen::Vector3f> q = settledVoxels(T_world_sonar_prior, T_world_sonar_prior);
  return q.empty() ? 0.0
                   : score(edgeField(image), q, T_world_sonar_prior, vectorOf(correction)) /
                         static_cast<double>(q.size());
}

Vector6d PoseRefiner::clamped(Vector6d x) const {
  for (int a = 0; a < 3; ++a) {
    x[a] = std::clamp(x[a], -params_.max_translation_m, params_.max_translation_m);
    x[a + 3] = std::clamp(x[a + 3], -params_.max_rotation_rad, params_.max_rotation_rad);
  }
  return x;
}

PoseCorrection PoseRefiner::refine(const cv::Mat& image,
                                   const Eigen::Isometry3d& T_world_sonar_prior) {
  const SonarModel& sonar = geometry_.sonar();
  if (image.type() != CV_32F || image.rows != sonar.rows() || image.cols != sonar.cols()) {
    throw Error("pose refinement", "frame", "image does not match the sonar model");
  }
  carried_ = clamped(carried_);
  PoseCorrection result = correctionOf(carried_);
  const std::vector<Eigen::Vector3f> q =
      settledVoxels(result.applied(T_world_sonar_prior), T_world_sonar_prior);
  result.voxels = q.size();
  if (q.size() < params_.min_settled_voxels) {
    return result;
  }
  const cv::Mat field = edgeField(image);
  // Steps from two voxels to half a voxel; rotations by the same arc at the voxels' range.
  double mean_range = 0.0;
  for (const Eigen::Vector3f& p : q) {
    mean_range += p.norm();
  }
  mean_range = std::max(mean_range / static_cast<double>(q.size()), 0.5);
  const double voxel = map_.voxelSize();

  // The prior along the track: a change from the carried correction costs every voxel
  // kTrackPriorWeight per (change / expected change per frame)^2, so that a direction the
  // frame cannot observe (along a vertical pipe) stays where the track put it.
  const double n = static_cast<double>(q.size());
  const double min_gain = kMinGainPerVoxel * n;
  const auto objective = [&](const Vector6d& x) {
    double change = 0.0;
    for (int a = 0; a < 6; ++a) {
      const double sigma = a < 3 ? params_.step_sigma_m : params_.step_sigma_rad;
      change += sigma > 0.0 ? std::pow((x[a] - carried_[a]) / sigma, 2) : 0.0;
    }
    return score(field, q, T_world_sonar_prior, x) - n * kTrackPriorWeight * change;
  };
  Candidate best{carried_, objective(carried_)};
  const double score_start = best.score;
  std::vector<Candidate> moves(12);
  for (const double step : {2.0 * voxel, voxel, 0.5 * voxel}) {
    const double turn = step / mean_range;
    for (int iteration = 0; iteration < 10; ++iteration) {
      for (int k = 0; k < 12; ++k) {
        Vector6d x = best.x;
        const int axis = k / 2;
        x[axis] += (k % 2 == 0 ? 1.0 : -1.0) * (axis < 3 ? step : turn);
        moves[static_cast<std::size_t>(k)].x = clamped(x);
      }
      pool_.parallelFor(moves.size(), 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
          moves[k].score = objective(moves[k].x);
        }
      });
      const auto top =
          std::max_element(moves.begin(), moves.end(),
                           [](const auto& a, const auto& b) { return a.score < b.score; });
      if (!(top->score > best.score + min_gain)) {
        break;
      }
      best = *top;
    }
  }
  result.score_before = score_start / n;
  result.score_after = score(field, q, T_world_sonar_prior, best.x) / n;
  // Where the settled voxels do not meet the frame's edges at the end, there is nothing to
  // align to: the frame keeps the carried correction.
  if (result.score_after < kMinAgreement) {
    return result;
  }
  carried_ = best.x;
  result.translation_world_m = best.x.head<3>();
  result.rotation_sonar_rad = best.x.tail<3>();
  result.aligned = true;
  return result;
}

}  // namespace sonarcarve
