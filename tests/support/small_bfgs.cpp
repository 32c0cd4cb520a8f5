#include "support/small_bfgs.h"

#include <cmath>

namespace sonarcarve::test {

BfgsResult minimiseBfgs(const Objective& f, Eigen::VectorXd x0, const Eigen::VectorXd& scale,
                        int iterations, double stop_value) {
  const Eigen::Index n = x0.size();
  Eigen::VectorXd g(n);
  BfgsResult result{std::move(x0), 0.0, 0};
  result.value = f(result.x, g);
  const Eigen::VectorXd scaled = g.cwiseProduct(scale);
  Eigen::MatrixXd H = scale.cwiseAbs2().asDiagonal();
  H /= std::max(scaled.norm(), 1e-300);
  for (int it = 0; it < iterations && result.value > stop_value; ++it) {
    Eigen::VectorXd direction = -H * g;
    if (g.dot(direction) >= 0.0) {  // not a descent: restart from the scaled gradient
      H = scale.cwiseAbs2().asDiagonal();
      H /= std::max(g.cwiseProduct(scale).norm(), 1e-300);
      direction = -H * g;
    }
    double step = 1.0;
    Eigen::VectorXd x_new;
    Eigen::VectorXd g_new(n);
    double value_new = 0.0;
    bool accepted = false;
    for (int tries = 0; tries < 30; ++tries, step *= 0.5) {
      x_new = result.x + step * direction;
      value_new = f(x_new, g_new);
      if (std::isfinite(value_new) && value_new <= result.value + 1e-4 * step * g.dot(direction)) {
        accepted = true;
        break;
      }
    }
    result.iterations = it + 1;
    if (!accepted) {
      break;
    }
    const Eigen::VectorXd s = x_new - result.x;
    const Eigen::VectorXd y = g_new - g;
    const double sy = s.dot(y);
    if (sy > 1e-300) {
      const double rho = 1.0 / sy;
      const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
      H = (I - rho * s * y.transpose()) * H * (I - rho * y * s.transpose()) +
          rho * s * s.transpose();
    }
    result.x = x_new;
    result.value = value_new;
    g = g_new;
  }
  return result;
}

}  // namespace sonarcarve::test
