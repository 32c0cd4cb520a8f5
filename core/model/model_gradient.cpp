#include "model/model_gradient.h"

namespace sonarcarve {
namespace {

void addInto(std::vector<double>& to, const std::vector<double>& from) {
  for (std::size_t i = 0; i < to.size(); ++i) {
    to[i] += from[i];
  }
}

}  // namespace

ModelGradient::ModelGradient(std::size_t voxels, std::size_t knots, std::size_t bins)
    : logits(voxels, 0.0), reflectance(voxels, 0.0), knots_db(knots, 0.0), background(bins, 0.0) {}

void ModelGradient::add(const ModelGradient& other) {
  addInto(logits, other.logits);
  addInto(reflectance, other.reflectance);
  addInto(knots_db, other.knots_db);
  addInto(background, other.background);
  gain += other.gain;
  twist += other.twist;
}

Eigen::Isometry3d applyTwist(const Eigen::Isometry3d& T_world_sonar, const Twist& xi) {
  const Eigen::Vector3d v = xi.head<3>();
  const Eigen::Vector3d omega = xi.tail<3>();
  const double angle = omega.norm();
  // The exponential map of SE(3): rotation exp(omega), translation V(omega) v.
  const Eigen::Matrix3d W = Eigen::Matrix3d{
      {0, -omega.z(), omega.y()}, {omega.z(), 0, -omega.x()}, {-omega.y(), omega.x(), 0}};
  Eigen::Matrix3d V = Eigen::Matrix3d::Identity() + 0.5 * W;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity() + W;
  if (angle > 1e-9) {
    const double a2 = angle * angle;
    R = Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
    V = Eigen::Matrix3d::Identity() + (1.0 - std::cos(angle)) / a2 * W +
        (angle - std::sin(angle)) / (a2 * angle) * W * W;
  }
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.linear() = R;
  step.translation() = V * v;
  return T_world_sonar * step;
}

}  // namespace sonarcarve
