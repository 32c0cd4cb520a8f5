// Adam (Kingma and Ba 2015) over the band voxels of one parameter array of the fit: a step
// per voxel scaled by the running root mean square of its gradient, so that logits and
// reflectances move at the learning rate whatever the frames' intensity scale. The epsilon is
// relative (a small share of the typical voxel's gradient), so that voxels whose gradient is
// only a trace (hidden behind an opaque surface) barely move.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace sonarcarve {

class AdamState {
 public:
  explicit AdamState(std::size_t size) : m_(size, 0.0f), v_(size, 0.0f) {}

  /// One step of `x` (band voxels only, `in_band` non-zero) down the gradient `g`, clamped to
  /// [lo, hi].
  void step(std::vector<float>& x, const std::vector<double>& g,
            const std::vector<std::uint8_t>& in_band, double learning_rate, double lo, double hi);
  /// The same for a small dense vector (every element moves).
  void step(std::vector<double>& x, const std::vector<double>& g, double learning_rate, double lo,
            double hi);

 private:
  template <typename T>
  void update(std::vector<T>& x, const std::vector<double>& g,
              const std::vector<std::uint8_t>* in_band, double learning_rate, double lo, double hi);
  std::vector<float> m_, v_;
  int t_ = 0;
};

}  // namespace sonarcarve
