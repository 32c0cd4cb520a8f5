// The speckle likelihood of a frame under the forward model. Fully developed speckle makes a
// pixel's intensity exponential about its mean I (Rayleigh amplitude), so the negative log
// likelihood of an observed frame is, up to a constant,
//   NLL = sum over pixels of  log I + I_obs / I,
// with d NLL / d I = 1 / I - I_obs / I^2 (zero at I = I_obs). The predicted mean must be
// positive everywhere: a background B(k) > 0 keeps it so (model/forward_model.h).
#pragma once

#include <opencv2/core.hpp>

namespace sonarcarve {

/// The NLL of `observed` (CV_32F or CV_64F) given the predicted mean (CV_64F, same size); if
/// `gradient` is set it receives d NLL / d predicted (CV_64F). Throws Error if the sizes differ
/// or a predicted value is not positive.
double speckleNll(const cv::Mat& predicted, const cv::Mat& observed, cv::Mat* gradient = nullptr);

/// The least squares sum (predicted - observed)^2 and, if set, its gradient 2 (predicted -
/// observed), same types as speckleNll.
double squaredError(const cv::Mat& predicted, const cv::Mat& observed, cv::Mat* gradient = nullptr);

}  // namespace sonarcarve
