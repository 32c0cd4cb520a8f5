// HoloOcean / NeuSIS datasets opened in place (docs/formats.md, "HoloOcean / NeuSIS datasets"):
// a folder with Config.json (the HoloOcean scenario) and Data/*.pkl (one pickle a frame, a dict
// holding the ImagingSonar image and the PoseSensor matrix). Every pickle is decoded once when
// the folder is opened, for its pose; a frame whose pickle cannot be read is left out and
// reported. The pose is the sonar's (the PoseSensor in the sonar's socket, as NeuSIS uses it),
// so the mounting is the identity unless --mounting says otherwise. The pickles hold no time:
// frame k is at k / Hz (the sonar's Hz in Config.json, else its ticks_per_sec, else 1 Hz).
#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "common/number_text.h"
#include "io/frame_source.h"
#include "io/holoocean/holoocean_config.h"
#include "io/holoocean/holoocean_frame_file.h"
#include "io/holoocean/holoocean_frames.h"
#include "io/import.h"
#include "io/pickle/pickle_reader.h"

namespace sonarcarve {
namespace {

bool looksLikeHoloOceanDataset(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec) &&
         std::filesystem::is_regular_file(path / kHoloOceanConfigFile, ec) &&
         std::filesystem::is_directory(path / kHoloOceanDataFolder, ec);
}

class HoloOceanSource final : public FrameSource {
 public:
  HoloOceanSource(std::vector<std::filesystem::path> files, std::string image_key, int rows,
                  int cols, std::string sonar_id)
      : files_(std::move(files)),
        image_key_(std::move(image_key)),
        rows_(rows),
        cols_(cols),
        sonar_id_(std::move(sonar_id)) {}

  std::string kind() const override { return "HoloOcean / NeuSIS dataset"; }
  std::size_t size() const override { return files_.size(); }
  Frame load(std::size_t index) const override {
    const std::filesystem::path& file = files_.at(index);
    const pickle::ValuePtr state = pickle::readPickleFile(file);
    Frame frame;
    frame.sonar_id = sonar_id_;
    frame.image = holoOceanImage(*state, image_key_, rows_, cols_, file.string());
    return frame;
  }

 private:
  std::vector<std::filesystem::path> files_;
  std::string image_key_;
  int rows_, cols_;
  std::string sonar_id_;
};

struct UsableFrame {
  std::filesystem::path file;
  Eigen::Isometry3d pose;
};

// Each frame's pose (and the images' size), leaving out and reporting frames that fail.
std::vector<UsableFrame> usableFrames(const std::vector<std::filesystem::path>& files,
                                      const HoloOceanSonarConfig& config, int& rows, int& cols,
                                      std::vector<std::string>& warnings) {
  std::vector<UsableFrame> frames;
  for (const std::filesystem::path& file : files) {
    try {
      const pickle::ValuePtr state = pickle::readPickleFile(file);
      const auto [r, c] = holoOceanImageSize(*state, config.image_key, file.string());
      if (rows == 0) {
        rows = config.range_bins.value_or(r);
        cols = config.azimuth_bins.value_or(c);
      }
      if (r != rows || c != cols) {
        throw Error(file.string(), "key " + config.image_key,
                    "an image of " + std::to_string(r) + " x " + std::to_string(c) + ": expected " +
                        std::to_string(rows) + " x " + std::to_string(cols) +
                        " (RangeBins x AzimuthBins)");
      }
      const Eigen::Matrix4d T = holoOceanPose(*state, config.pose_key, file.string());
      frames.push_back({file, nedPoseFromHoloOcean(T)});
    } catch (const Error& e) {
      warnings.push_back(std::string(e.what()) + " (frame skipped)");
    }
  }
  return frames;
}

NavTrack poseTrack(const std::vector<UsableFrame>& frames, double period_s) {
  std::vector<NavSample> samples;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    NavSample s;
    s.time_s = static_cast<double>(k) * period_s;
    s.position_m = frames[k].pose.translation();
    s.q_world_vehicle = Eigen::Quaterniond(frames[k].pose.linear()).normalized();
    samples.push_back(s);
  }
  if (samples.size() == 1) {  // a track spans a time: one pose held for a period
    samples.push_back(samples.front());
    samples.back().time_s += period_s;
  }
  return NavTrack(std::move(samples));
}

Mission openHoloOceanDataset(const std::filesystem::path& path, const OpenOptions& options) {
  const HoloOceanSonarConfig config = readHoloOceanConfig(path / kHoloOceanConfigFile);
  const std::filesystem::path data = path / kHoloOceanDataFolder;
  const std::vector<std::filesystem::path> files = holoOceanFrameFiles(data);
  if (files.empty()) {
    throw Error(data.string(), "",
                "no .pkl file: expected one pickle a frame (NeuSIS layout: Config.json and "
                "Data/*.pkl)");
  }
  std::vector<std::string> warnings = config.warnings;
  int rows = 0, cols = 0;
  const std::vector<UsableFrame> frames = usableFrames(files, config, rows, cols, warnings);
  if (frames.empty()) {
    throw Error(data.string(), "",
                "none of its " + std::to_string(files.size()) +
                    " .pkl files could be read: " + warnings.back());
  }
  const double res = (config.range_max_m - config.range_min_m) / rows;
  const double aperture_deg = options.vertical_aperture_deg.value_or(config.elevation_deg);
  const SonarModel sonar =
      SonarModel("holoocean", RangeBins{config.range_min_m, res, rows},
                 BearingTable::uniform(degToRad(config.azimuth_deg), cols), degToRad(aperture_deg))
          .withElevationBeam(ElevationBeam::Clipped);
  const double rate =
      config.frame_rate_hz > 0.0 && config.frame_rate_hz <= 1e6 ? config.frame_rate_hz : 1.0;
  std::vector<double> times;
  std::vector<std::filesystem::path> used;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    times.push_back(static_cast<double>(k) / rate + options.time_offset_s);
    used.push_back(frames[k].file);
  }
  Mission mission = recordingMission(path, sonar, times, [&](std::size_t k) {
    return std::string(kHoloOceanDataFolder) + "/" + used[k].filename().string();
  });
  mission.warnings = warnings;
  if (config.frame_rate_hz <= 0.0) {
    mission.warnings.push_back(
        "Config.json gives no Hz or ticks_per_sec: frames are taken 1 s apart (the pickles "
        "hold no time)");
  }
  mission.nav = poseTrack(frames, 1.0 / rate);
  if (options.time_offset_s != 0.0) {
    mission.nav = NavTrack([&] {
      std::vector<NavSample> samples = mission.nav.samples();
      for (NavSample& s : samples) {
        s.time_s += options.time_offset_s;
      }
      return samples;
    }());
  }
  mission.nav_file = "Data/*.pkl (" + config.pose_key + ": the sonar's pose)";
  mission.contents.push_back("HoloOcean / NeuSIS dataset: " + std::to_string(frames.size()) +
                             " of " + std::to_string(files.size()) + " frames, images " +
                             std::to_string(rows) + " x " + std::to_string(cols) + " (" +
                             config.image_key + "), poses " + config.pose_key +
                             " (HoloOcean's x forward, y left, z up taken as north, west, up)");
  applyNavigationAndMounting(mission, options);
  mission.source =
      std::make_shared<const HoloOceanSource>(used, config.image_key, rows, cols, sonar.id());
  return mission;
}

[[maybe_unused]] const bool registered =
    registerFrameSourceReader({"holoocean", looksLikeHoloOceanDataset, openHoloOceanDataset});

}  // namespace
}  // namespace sonarcarve
