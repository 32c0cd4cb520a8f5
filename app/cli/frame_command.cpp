// `sonarcarve-cli frame MISSION --index N --polar P.png --fan F.png`: pictures of one frame.
#include <iomanip>
#include <iostream>

#include "cli/commands.h"
#include "cli/param_flags.h"
#include "cli/source_flags.h"
#include "common/error.h"
#include "denoise/detector.h"
#include "io/files/atomic_file.h"
#include "io/files/output_folder.h"
#include "io/files/png_codec.h"
#include "io/mission/mission.h"
#include "sonar/fan_image.h"

namespace sonarcarve::cli {
namespace {

void writePng(const cv::Mat& picture, const std::string& path) {
  writeFileAtomically(path, encodePng(picture, path));
}

}  // namespace

void addFrameCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("frame", "Draw one frame of a mission as PNG pictures");
  struct Options {
    std::string mission, polar, fan, noise_model, detected;
    int smoothing = DetectorParams::kDefaultSmoothing;
    double z = DetectorParams::kDefaultZ;
    std::size_t index = 0;
    float low = -1.0f, high = -1.0f;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("mission", o->mission, "Mission folder, or a recording read in place")
      ->required();
  auto source = std::make_shared<SourceFlags>();
  addSourceFlags(*cmd, *source);
  cmd->add_option("--index", o->index, "Frame index (0-based)")
      ->capture_default_str()
      // "-1" would otherwise read as 2^64 - 1.
      ->check(CLI::Validator(
          [](const std::string& text) {
            return !text.empty() && text.front() == '-'
                       ? "expected a frame index of 0 or more, got " + text
                       : std::string();
          },
          "INDEX >= 0"));
  cmd->add_option("--polar", o->polar, "Write the polar image here (PNG)");
  cmd->add_option("--fan", o->fan, "Write the fan in true geometry here (PNG)");
  cmd->add_option("--noise-model", o->noise_model, "Noise model for --detected");
  cmd->add_option("--detected", o->detected,
                  "Write the polar image after the Z-test (PNG, same intensity window)");
  cmd->add_option("--z", o->z, "Z-test threshold for --detected")
      ->capture_default_str()
      ->check(schemaCheck("detector.z"));
  cmd->add_option("--smoothing", o->smoothing, "Detector's box filter for --detected")
      ->capture_default_str()
      ->check(schemaCheck("detector.smoothing"));
  cmd->add_option("--low", o->low, "Intensity shown black (default: 1st percentile)");
  cmd->add_option("--high", o->high, "Intensity shown white (default: 99.5th percentile)");
  cmd->callback([o, source, &exit_code] {
    std::vector<std::unique_ptr<OutputFolderLock>> holds;  // the pictures' targets, checked first
    for (const std::string* picture : {&o->polar, &o->fan, &o->detected}) {
      if (!picture->empty()) {
        holds.push_back(holdOutputFile(*picture));
      }
    }
    const Mission mission = openMission(o->mission, openOptionsFrom(*source));
    if (o->index >= mission.frames.size()) {
      throw Error(o->mission, "frame " + std::to_string(o->index),
                  "no such frame: the mission has " + std::to_string(mission.frames.size()));
    }
    const Frame frame = loadFrame(mission, o->index);
    // Drawn in the sonar's own counts (what --low and --high are in), not in power.
    const IntensityScale& scale = mission.sonar.intensityScale();
    const cv::Mat counts = scale.powerToCounts(frame.image);
    DisplayWindow window = DisplayWindow::fromPercentiles(counts);
    if (o->low >= 0.0f) {
      window.low = o->low;
    }
    if (o->high >= 0.0f) {
      window.high = o->high;
    }
    if (!o->polar.empty()) {
      writePng(polarPicture(counts, window), o->polar);
    }
    if (!o->fan.empty()) {
      writePng(fanPicture(counts, mission.sonar, window), o->fan);
    }
    if (!o->detected.empty()) {
      DetectorParams params;
      params.mode = DetectorMode::ZTest;
      params.z = o->z;
      params.smoothing = o->smoothing;
      const Detector detector(params,
                              std::make_shared<const NoiseModel>(NoiseModel::load(o->noise_model)),
                              mission.sonar);
      writePng(polarPicture(scale.powerToCounts(detector.apply(frame.image)), window), o->detected);
    }
    std::cout << "frame " << o->index << " at t = " << std::fixed << std::setprecision(3)
              << frame.time_s << " s, intensity window " << std::defaultfloat << window.low
              << " .. " << window.high << " counts (" << scale.describe() << ")\n";
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
