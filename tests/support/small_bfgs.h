// A small BFGS minimiser for the tests that recover a few parameters (a beam profile's knots,
// a pose) from frames through the forward model's gradient: dense inverse Hessian, backtracking
// line search on the Armijo condition.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>

namespace sonarcarve::test {

/// Value of the objective at x; fills `gradient`.
using Objective = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)>;

struct BfgsResult {
  Eigen::VectorXd x;
  double value = 0.0;
  int iterations = 0;
};

/// Minimises from `x0` for at most `iterations` steps, or until the value falls below
/// `stop_value`. `scale`: the size of a sensible first step in each coordinate (the initial
/// inverse Hessian is diag(scale^2) / |g|).
BfgsResult minimiseBfgs(const Objective& f, Eigen::VectorXd x0, const Eigen::VectorXd& scale,
                        int iterations,
                        double stop_value = -std::numeric_limits<double>::infinity());

}  // namespace sonarcarve::test
