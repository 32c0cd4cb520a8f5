#include "carve/track_smoother.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>

#include "common/error.h"

namespace sonarcarve {
namespace {

// The map's offset is free; a whisper of a prior keeps the system regular along a direction
// that no frame observes (it then stays at zero).
constexpr double kOffsetRegularisation = 1e-6;

}  // namespace

std::vector<Vector6d> smoothCorrectionTrack(const std::vector<PoseMeasurement>& measurements,
                                            const PoseRefinementParams& params) {
  const std::size_t n = measurements.size();
  if (n == 0) {
    return {};
  }
  if (!(params.step_sigma_m > 0.0) || !(params.step_sigma_rad > 0.0)) {
    throw Error("parameters", "pose_refinement", "expected a navigation drift per frame > 0");
  }
  Vector6d step_information;
  step_information << Eigen::Vector3d::Constant(1.0 / (params.step_sigma_m * params.step_sigma_m)),
      Eigen::Vector3d::Constant(1.0 / (params.step_sigma_rad * params.step_sigma_rad));
  const Matrix6d Q_inv = step_information.asDiagonal();

  // Unknowns: c_0 .. c_{n-1}, then b; six each.
  const auto unknowns = static_cast<Eigen::Index>(6 * (n + 1));
  const Eigen::Index offset = unknowns - 6;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  const auto add = [&](Eigen::Index row, Eigen::Index col, const Matrix6d& block) {
    for (int r = 0; r < 6; ++r) {
      for (int c = 0; c < 6; ++c) {
        if (block(r, c) != 0.0) {
          entries.emplace_back(row + r, col + c, block(r, c));
        }
      }
    }
  };
  add(0, 0, Q_inv);  // the walk starts from the navigation
  for (std::size_t i = 0; i < n; ++i) {
    const auto at = static_cast<Eigen::Index>(6 * i);
    if (i > 0) {
      add(at, at, Q_inv);
      add(at - 6, at - 6, Q_inv);
      add(at, at - 6, -Q_inv);
      add(at - 6, at, -Q_inv);
    }
    const PoseMeasurement& m = measurements[i];
    if (!m.correction.aligned) {
      continue;
    }
    const Matrix6d& H = m.information;
    const Vector6d Hm = H * m.correction.vector();
    add(at, at, H);
    add(at, offset, H);
    add(offset, at, H);
    add(offset, offset, H);
    rhs.segment<6>(at) += Hm;
    rhs.segment<6>(offset) += Hm;
  }
  add(offset, offset, kOffsetRegularisation * Q_inv);
  Eigen::SparseMatrix<double> A(unknowns, unknowns);
  A.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) {
    throw Error("pose refinement", "track", "the correction track's system is singular");
  }
  const Eigen::VectorXd x = solver.solve(rhs);
  std::vector<Vector6d> track(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vector6d c = x.segment<6>(static_cast<Eigen::Index>(6 * i));
    for (int a = 0; a < 3; ++a) {
      c[a] = std::clamp(c[a], -params.max_translation_m, params.max_translation_m);
      c[a + 3] = std::clamp(c[a + 3], -params.max_rotation_rad, params.max_rotation_rad);
    }
    track[i] = c;
  }
  return track;
}

}  // namespace sonarcarve
