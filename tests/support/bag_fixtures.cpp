#include "support/bag_fixtures.h"

#include <cmath>

#include "common/angles.h"

namespace sonarcarve::test {

Frame MemorySource::load(std::size_t index) const {
  Frame frame{times_.at(index), sonar_.id(), cv::Mat(sonar_.rows(), sonar_.cols(), CV_32F)};
  for (int r = 0; r < sonar_.rows(); ++r) {
    for (int c = 0; c < sonar_.cols(); ++c) {
      frame.image.at<float>(r, c) = value_(index, r, c);
    }
  }
  return frame;
}

SonarModel smallBagSonar() {
  std::vector<double> centres;
  for (int j = 0; j < 24; ++j) {
    const double u = -1.0 + 2.0 * (j + 0.5) / 24.0;
    centres.push_back(std::asin(u * std::sin(degToRad(30))));
  }
  return SonarModel("small", RangeBins{0.5, 0.05, 40}, BearingTable::fromCentres(centres),
                    degToRad(12));
}

Mission memoryMission(std::size_t frames, MemorySource::Value value) {
  const SonarModel sonar = smallBagSonar();
  std::vector<double> times;
  for (std::size_t k = 0; k < frames; ++k) {
    times.push_back(2.0 + 0.5 * static_cast<double>(k));
  }
  std::vector<NavSample> samples;
  for (int k = 0; k <= 20; ++k) {
    NavSample s;
    s.time_s = 1.0 + 0.25 * k;
    s.position_m = Eigen::Vector3d(0.1 * k, 0.05 * k, 3.0 + 0.02 * k);
    s.q_world_vehicle = quaternionFromRollPitchYaw({0.01 * k, -0.02 * k, 0.3 + 0.05 * k});
    samples.push_back(s);
  }
  Mounting mounting;
  mounting.translation_m = Eigen::Vector3d(0.3, -0.05, 0.1);
  mounting.rpy = {degToRad(2.0), degToRad(-20.0), degToRad(5.0)};
  Mission mission{"memory",
                  "memory",
                  sonar,
                  mounting,
                  NavTrack(samples),
                  {},
                  "",
                  "",
                  std::make_shared<MemorySource>(sonar, times, std::move(value)),
                  {},
                  {}};
  for (std::size_t k = 0; k < frames; ++k) {
    mission.frames.push_back({times[k], sonar.id(), "frame", 0});
  }
  return mission;
}

float countsPattern(std::size_t frame, int row, int col) {
  return static_cast<float>(
      (frame * 7919 + static_cast<std::size_t>(row) * 257 + static_cast<std::size_t>(col) * 31) %
      65536);
}

}  // namespace sonarcarve::test
