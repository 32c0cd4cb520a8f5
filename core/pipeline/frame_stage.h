// The pipeline's first stages: which frames take part and where the sonar was for each
// (read), and the noise removal every frame goes through before carving (denoise).
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <vector>

#include "carve/seabed_model.h"
#include "common/progress.h"
#include "denoise/detector.h"
#include "io/mission/mission.h"
#include "pipeline/run_choice.h"
#include "sonar/bearing_deblur.h"

namespace sonarcarve {

/// Frames used: [first, last) every `stride`-th; last < 0 means to the end.
struct FrameSelection {
  std::size_t first = 0;
  long last = -1;
  std::size_t stride = 1;
};

struct PosedFrame {
  std::size_t index = 0;  ///< in the mission
  Eigen::Isometry3d T_world_sonar = Eigen::Isometry3d::Identity();
};

/// Indices of the frames a selection takes from a mission of `count` frames.
std::vector<std::size_t> selectFrames(std::size_t count, const FrameSelection& selection);

/// The selected frames with their sonar poses. Frames outside the navigation's time span
/// cannot be placed: each is passed to `skip` with the reason and left out.
std::vector<PosedFrame> placeFrames(const Mission& mission, const FrameSelection& selection,
                                    const std::function<void(const FrameProblem&)>& skip);

/// The noise model the denoise stage uses, and why (the run's choice "denoising").
struct NoiseChoice {
  std::shared_ptr<const NoiseModel> model;  ///< null: none
  DetectorParams detector;                  ///< `auto` made concrete
  RunChoice choice;
};

/// Chooses the noise model: the file `noise_model` when given; for the `auto` detector
/// without one, a model learned from the placed frames themselves
/// (denoise/mission_noise_model.h), or no denoising when the frames carry no background at
/// all (noise-free simulations). `given` is the model read from the file `given_path`, or
/// null when none was given. With the detector `none` the reason warns when a few frames show
/// a background (speckle), which the run then carves as structure.
NoiseChoice chooseNoiseModel(const Mission& mission, const std::vector<PosedFrame>& frames,
                             const DetectorParams& detector, const std::string& given_path,
                             std::shared_ptr<const NoiseModel> given, Progress& progress);

/// The sonar whose beams' blur across bearing is taken out of the frames, and why.
class DenoisedFrames;

struct BeamWidthChoice {
  enum class Source { Declared, ReadFromFrames, NotFound, NoFrameRead };
  SonarModel sonar;
  Source source = Source::Declared;
  std::string reason;  ///< empty when the sonar declares its width (or an analyst gave one)
};

/// The run's choice "bearing deblur": whether the frames' blur across bearing is taken out,
/// with the beams' width `beams` gives, as `frames` does it.
RunChoice bearingDeblurChoice(const BeamWidthChoice& beams, const DenoisedFrames& frames);

/// Frames read for the beams' width.
inline constexpr std::size_t kBeamWidthFrames = 24;

/// `sonar` as it is when it declares its beams' width; otherwise with the width read from up
/// to kBeamWidthFrames of the frames `indices`, evenly spread (sonar/beam_width_estimate.h),
/// when one can be read. Frames that cannot be read are passed over (the carving stage reports
/// them). Throws Cancelled.
BeamWidthChoice chooseBeamWidth(const Mission& mission, const SonarModel& sonar,
                                const std::vector<std::size_t>& indices, Progress& progress);

/// The mission's indices of placed frames.
std::vector<std::size_t> indicesOf(const std::vector<PosedFrame>& frames);

/// What carving reads of a raw frame (power): the detector's output with the beams' blur
/// across bearing taken out.
cv::Mat denoiseFrame(const Detector& detector, const BearingDeblur& deblur, const cv::Mat& image);

/// Reads a frame of the mission, removes its noise and, where the sonar's beams are wider
/// than their spacing, their blur across bearing (sonar/bearing_deblur.h). Thread safe.
class DenoisedFrames {
 public:
  /// Builds the detector; throws Error naming the parameter on a problem.
  DenoisedFrames(const Mission& mission, const SonarModel& sonar, const NoiseChoice& noise);
  /// Throws Error naming the frame's file if it cannot be read. With `before`, where a
  /// Z-test ran, fills it with the frame before the detector less the noise's mean and the
  /// background's standard deviation (for seabed-aware carving); left empty otherwise.
  Frame load(std::size_t index, BeforeDetection* before = nullptr) const;
  const Detector& detector() const { return *detector_; }
  /// Whether and how the frames' blur across bearing is taken out, in words.
  std::string bearingDeblur() const;
  /// Whether the frames' blur across bearing is taken out at all.
  bool deblurs() const { return deblur_.active(); }

 private:
  const Mission& mission_;
  std::shared_ptr<const Detector> detector_;
  std::shared_ptr<const NoiseModel> model_;
  // Whether a dark pixel means no return (no detector ran).
  bool exactDark() const { return darkPixelsAreExact(detector_->params()); }
  cv::Mat background_sigma_;  // ztest: the detector's, per pixel before its box filter
  BearingDeblur deblur_;      // beams wider than their spacing: their blur taken out
};

}  // namespace sonarcarve
