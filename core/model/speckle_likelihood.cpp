#include "model/speckle_likelihood.h"

#include <cmath>

#include "common/error.h"

namespace sonarcarve {
namespace {

// Sums loss(I, I_obs) over the pixels and writes d loss / d I into `gradient` if set.
template <typename Loss>
double pixelLoss(const cv::Mat& predicted, const cv::Mat& observed, cv::Mat* gradient, Loss loss) {
  if (predicted.type() != CV_64F || predicted.size() != observed.size()) {
    throw Error("model likelihood", "frame", "expected a CV_64F prediction of the frame's size");
  }
  cv::Mat obs;
  observed.convertTo(obs, CV_64F);
  if (gradient != nullptr) {
    gradient->create(predicted.size(), CV_64F);
  }
  double total = 0.0;
  for (int row = 0; row < predicted.rows; ++row) {
    const auto* p = predicted.ptr<double>(row);
    const auto* o = obs.ptr<double>(row);
    auto* g = gradient != nullptr ? gradient->ptr<double>(row) : nullptr;
    for (int col = 0; col < predicted.cols; ++col) {
      double d = 0.0;
      total += loss(p[col], o[col], d);
      if (g != nullptr) {
        g[col] = d;
      }
    }
  }
  return total;
}

}  // namespace

double speckleNll(const cv::Mat& predicted, const cv::Mat& observed, cv::Mat* gradient) {
  return pixelLoss(predicted, observed, gradient, [](double i, double obs, double& d) {
    if (!(i > 0.0)) {
      throw Error("model likelihood", "prediction",
                  "the speckle likelihood needs a positive predicted mean (add a background)");
    }
    d = 1.0 / i - obs / (i * i);
    return std::log(i) + obs / i;
  });
}

double squaredError(const cv::Mat& predicted, const cv::Mat& observed, cv::Mat* gradient) {
  return pixelLoss(predicted, observed, gradient, [](double i, double obs, double& d) {
    d = 2.0 * (i - obs);
    return (i - obs) * (i - obs);
  });
}

}  // namespace sonarcarve
