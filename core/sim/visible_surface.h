// VisibleSurface: the set of scene surface points the sonar actually saw, thinned to one point
// per cell of `cell_m` (1 cm by default): what a perfect reconstruction could recover, used to
// measure completeness on the visible surface only.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <mutex>
#include <span>
#include <unordered_map>
#include <vector>

namespace sonarcarve {

class VisibleSurface {
 public:
  explicit VisibleSurface(double cell_m = 0.01) : cell_m_(cell_m) {}
  /// Keeps each of `p_world` whose cell holds no point yet. Thread safe: the renderer's threads
  /// add their batches at once; a batch is thinned before the shared set is locked.
  void add(std::span<const Eigen::Vector3f> p_world);
  /// Not while add() runs.
  std::size_t size() const { return points_.size(); }
  const std::vector<Eigen::Vector3f>& points() const { return points_; }

 private:
  std::uint64_t cellOf(const Eigen::Vector3f& p_world) const;

  double cell_m_;
  std::mutex mutex_;
  std::unordered_map<std::uint64_t, std::uint32_t> cells_;
  std::vector<Eigen::Vector3f> points_;
};

}  // namespace sonarcarve
