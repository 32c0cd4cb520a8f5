#include "pipeline/frame_stage.h"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "common/error.h"
#include "denoise/mission_noise_model.h"
#include "sonar/beam_width_estimate.h"

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

namespace {

/// Frames the check of a detector `none` reads: enough for `auto`'s background test, whose
/// pixels are medians over frames.
constexpr std::size_t kSpeckleCheckFrames = 8;

/// What an analyst who turned the detector off should know: said when the frames carry a
/// background (speckle), which carving without a detector keeps as structure; empty otherwise.
std::string speckleLeftIn(const Mission& mission, const std::vector<std::size_t>& indices,
                          int smoothing, Progress& progress) {
  RenamedProgress checking(progress, "speckle check");
  MissionNoiseStats stats;
  try {
    learnNoiseFromMission(mission, indices, smoothing, checking, &stats, kSpeckleCheckFrames);
  } catch (const Error&) {
    return "";  // too few frames to tell
  }
  if (!stats.has_background()) {
    return "";
  }
  return "; warning: " + std::to_string(stats.frames_used) +
         " frames checked carry background noise (speckle), which carving without a detector "
         "keeps as structure: use the detector auto (the default), or give an empty-water "
         "noise model (--noise-model)";
}

}  // namespace

NoiseChoice chooseNoiseModel(const Mission& mission, const std::vector<PosedFrame>& frames,
                             const DetectorParams& detector, const std::string& given_path,
                             std::shared_ptr<const NoiseModel> given, Progress& progress) {
  NoiseChoice choice;
  RunChoice& said = choice.choice;
  said.name = "denoising";
  if (given) {
    choice.model = std::move(given);
    choice.detector = detector.resolved(true);
    said.value = std::string(toString(choice.detector.mode)) + " with the noise model given";
    said.reason = "background noise removed with the empty-water noise model you gave";
    said.detail = "noise model " + given_path;
    return choice;
  }
  choice.detector = detector.resolved(false);
  const std::vector<std::size_t> indices = indicesOf(frames);
  if (detector.mode == DetectorMode::None) {
    const std::string speckle = speckleLeftIn(mission, indices, detector.smoothing, progress);
    said.value = "off";
    said.detail = "no denoising (detector none)" + speckle;
    said.warning = !speckle.empty();
    said.reason = said.warning ? "the frames carry background noise, which carving keeps as "
                                 "structure without a detector"
                               : "the parameters turn the detector off";
    if (said.warning) {
      said.action = "use the detector auto (the default), or give an empty-water noise model";
    }
    return choice;
  }
  if (detector.mode != DetectorMode::Auto) {
    said.value = std::string(toString(detector.mode));
    said.reason = "the detector the parameters ask for, with no noise model";
    said.detail = "detector " + std::string(toString(detector.mode)) + ", no noise model";
    return choice;
  }
  MissionNoiseStats stats;
  std::optional<NoiseModel> learned;
  try {
    learned = learnNoiseFromMission(mission, indices, detector.smoothing, progress, &stats);
  } catch (const Error& e) {
    said.value = "off";
    said.reason = "no noise model was given and none could be learned from the frames";
    said.detail = "no denoising: " + std::string(e.message());
    said.action = "give an empty-water noise model (--noise-model), or check the frames";
    said.warning = true;
    return choice;
  }
  if (!stats.has_background()) {
    said.value = "off";
    said.reason = "the frames carry no background noise";
    said.detail = "no denoising: the frames carry no background noise (noise-free)";
    return choice;
  }
  choice.model = std::make_shared<const NoiseModel>(std::move(*learned));
  choice.detector = detector.resolved(true);
  char structure[32];
  std::snprintf(structure, sizeof structure, "%.1f", 100.0 * stats.structure_fraction);
  said.value = std::string(toString(choice.detector.mode)) + " with a noise model learned";
  said.reason = "background noise learned from the mission's own frames and removed";
  said.detail = "noise model learned from " + std::to_string(stats.frames_used) +
                " of the mission's own frames (no empty-water model given; " + structure +
                " % of pixels held structure in most frames" +
                (stats.full_row_bins > 0 ? "; " + std::to_string(stats.full_row_bins) +
                                               " range bins held a return across the fan, a "
                                               "seabed, scaled out"
                                         : std::string()) +
                ")";
  said.action = "an empty-water recording's noise model (--noise-model) denoises best";
  return choice;
}

std::vector<std::size_t> indicesOf(const std::vector<PosedFrame>& frames) {
  std::vector<std::size_t> indices;
  for (const PosedFrame& f : frames) {
    indices.push_back(f.index);
  }
  return indices;
}

BeamWidthChoice chooseBeamWidth(const Mission& mission, const SonarModel& sonar,
                                const std::vector<std::size_t>& indices, Progress& progress) {
  using Source = BeamWidthChoice::Source;
  if (sonar.horizontalBeamWidth() > 0.0) {
    return {sonar, Source::Declared, ""};
  }
  const std::size_t count = std::min(indices.size(), kBeamWidthFrames);
  BearingSpectrum spectrum(sonar.cols());
  std::size_t read = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (progress.cancelled()) {
      throw Cancelled();
    }
    try {
      spectrum.add(loadFrame(mission, indices[k * indices.size() / count]).image);
      ++read;
    } catch (const Error&) {
      // a frame that cannot be read is reported where carving reads it
    }
    progress.report("beam width", k + 1, count);
  }
  if (indices.empty()) {
    return {sonar, Source::NoFrameRead,
            "the mission gives no horizontal beam width, and no frame is placed in the "
            "navigation to read one from"};
  }
  if (read == 0) {
    return {sonar, Source::NoFrameRead,
            "the mission gives no horizontal beam width, and no frame could be read for "
            "one"};
  }
  const BeamWidthEstimate estimate = estimateBeamWidth(spectrum, sonar.bearings());
  const std::string frames =
      " from " + std::to_string(read) + (read == 1 ? " frame: " : " frames: ");
  if (!(estimate.width_rad > 0.0)) {
    return {
        sonar, Source::NotFound,
        "the mission gives no horizontal beam width, and none was read" + frames + estimate.reason};
  }
  return {sonar.withHorizontalBeamWidth(estimate.width_rad), Source::ReadFromFrames,
          "width read" + frames + estimate.reason};
}

RunChoice bearingDeblurChoice(const BeamWidthChoice& beams, const DenoisedFrames& frames) {
  using Source = BeamWidthChoice::Source;
  RunChoice choice;
  choice.name = "bearing deblur";
  choice.value = frames.deblurs() ? "on" : "off";
  if (beams.sonar.horizontalBeamWidth() > 0.0) {
    choice.detail = frames.bearingDeblur() + (beams.reason.empty() ? "" : "; " + beams.reason);
    const std::string width = beams.source == Source::ReadFromFrames
                                  ? "their width read from the frames"
                                  : "the width the sonar or the parameters give";
    choice.reason = frames.deblurs()
                        ? "the beams' blur across bearing taken out, with " + width
                        : "the beams are too narrow to blur across bearing (" + width + ")";
    return choice;
  }
  choice.detail = "off: " + beams.reason;
  if (beams.source == Source::NotFound) {
    choice.reason = "the frames show no blur across bearing to take out";
  } else {
    choice.reason = "the beams' width is unknown and no frame could be read for it";
  }
  choice.action =
      "give the sonar's horizontal beam width (horizontal_beam_width_deg) if its beams are "
      "wider than their spacing";
  return choice;
}

cv::Mat denoiseFrame(const Detector& detector, const BearingDeblur& deblur, const cv::Mat& image) {
  return deblur.apply(detector.apply(image), darkPixelsAreExact(detector.params()));
}

DenoisedFrames::DenoisedFrames(const Mission& mission, const SonarModel& sonar,
                               const NoiseChoice& noise)
    : mission_(mission),
      detector_(std::make_shared<const Detector>(noise.detector, noise.model, sonar)),
      model_(noise.model),
      background_sigma_(detector_->backgroundSigma()),
      deblur_(sonar) {}

Frame DenoisedFrames::load(std::size_t index, BeforeDetection* before) const {
  Frame frame = loadFrame(mission_, index);
  if (before != nullptr && !background_sigma_.empty()) {
    before->excess = frame.image - model_->mean();  // both CV_32F (sonar/frame.h)
    before->sigma = background_sigma_;
  }
  frame.image = denoiseFrame(*detector_, deblur_, frame.image);
  return frame;
}

std::string DenoisedFrames::bearingDeblur() const {
  return deblur_.describe(exactDark());
}

}  // namespace sonarcarve
