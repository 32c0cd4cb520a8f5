#include "pipeline/frame_stage.h"

#include <algorithm>

namespace sonarcarve {

std::vector<std::size_t> selectFrames(std::size_t count, const FrameSelection& selection) {
  const std::size_t last =
      selection.last < 0 ? count : std::min(count, static_cast<std::size_t>(selection.last));
  std::vector<std::size_t> frames;
  for (std::size_t i = selection.first; i < last; i += selection.stride) {
    frames.push_back(i);
  }
  return frames;
}

std::vector<PosedFrame> placeFrames(const Mission& mission, const FrameSelection& selection,
                                    const std::function<void(const FrameProblem&)>& skip) {
  const Eigen::Isometry3d T_vehicle_sonar = mission.mounting.T_vehicle_sonar();
  std::vector<PosedFrame> posed;
  for (std::size_t i : selectFrames(mission.frames.size(), selection)) {
    const double t = mission.frames[i].time_s;
    if (!mission.nav.covers(t)) {
      skip({i, "frame " + std::to_string(i) + " at t = " + std::to_string(t) +
                   " s lies outside the navigation track"});
      continue;
    }
    posed.push_back({i, mission.nav.T_world_sonar(t, T_vehicle_sonar)});
  }
  return posed;
}

DenoisedFrames::DenoisedFrames(const Mission& mission, const SonarModel& sonar,
                               const DetectorParams& detector, const std::string& noise_model)
    : mission_(mission) {
  std::shared_ptr<const NoiseModel> model;
  if (!noise_model.empty()) {
    model = std::make_shared<const NoiseModel>(NoiseModel::load(noise_model));
  }
  detector_ = std::make_shared<const Detector>(detector, model, sonar);
}

Frame DenoisedFrames::load(std::size_t index) const {
  Frame frame = loadFrame(mission_, index);
  frame.image = detector_->apply(frame.image);
  return frame;
}

bool DenoisedFrames::probabilities() const {
  return detector_->params().mode == "probability";
}

}  // namespace sonarcarve
