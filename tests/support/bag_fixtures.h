// Missions in memory for the ROS 2 bag tests: a small sonar with a non-uniform bearing table,
// frames of known values, a moving and turning vehicle and a tilted mounting, so that a bag
// written by io/rosbag/bag_writer.h and read back can be compared sample for sample.
#pragma once

#include <functional>
#include <vector>

#include "io/frame_source.h"

namespace sonarcarve::test {

/// Frames from a function of (frame, row, column), of `sonar`.
class MemorySource final : public FrameSource {
 public:
  using Value = std::function<float(std::size_t frame, int row, int col)>;
  MemorySource(SonarModel sonar, std::vector<double> times, Value value)
      : sonar_(std::move(sonar)), times_(std::move(times)), value_(std::move(value)) {}
  std::string kind() const override { return "memory"; }
  std::size_t size() const override { return times_.size(); }
  Frame load(std::size_t index) const override;

 private:
  SonarModel sonar_;
  std::vector<double> times_;
  Value value_;
};

/// 40 range bins of 5 cm from 0.5 m, 24 beams over +-30 deg spaced as the Oculus' (finer at
/// the centre), 12 deg aperture.
SonarModel smallBagSonar();

/// `frames` frames 0.5 s apart from t = 2 s, valued by `value`; a vehicle moving north-east,
/// sinking and turning; the sonar 0.3 m forward and pitched 20 degrees down.
Mission memoryMission(std::size_t frames, MemorySource::Value value);

/// Whole counts 0..65535, different in every pixel and frame.
float countsPattern(std::size_t frame, int row, int col);

}  // namespace sonarcarve::test
