// A HoloOcean scenario's Config.json as NeuSIS publishes it beside its Data/*.pkl frames
// (docs/formats.md, "HoloOcean / NeuSIS datasets"): the first agent's ImagingSonar sensor and
// its configuration (RangeMin, RangeMax in metres; Azimuth, Elevation in degrees; RangeBins,
// AzimuthBins), and the names under which the frames' pickles hold the sonar image and the
// PoseSensor matrix (each sensor's sensor_name, else its sensor_type).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sonarcarve {

inline constexpr const char* kHoloOceanConfigFile = "Config.json";
inline constexpr const char* kHoloOceanDataFolder = "Data";

struct HoloOceanSonarConfig {
  double range_min_m = 0.0;
  double range_max_m = 0.0;
  double azimuth_deg = 0.0;
  double elevation_deg = 0.0;
  std::optional<int> range_bins;    ///< absent: HoloOcean derived it (the images' rows)
  std::optional<int> azimuth_bins;  ///< absent: the images' columns
  double frame_rate_hz = 0.0;       ///< the sensor's Hz, else ticks_per_sec; 0: unknown
  std::string image_key = "ImagingSonar";
  std::string pose_key = "PoseSensor";
  std::vector<std::string> warnings;
};

/// Reads `path` (Config.json). Throws Error naming the file and the key (as a JSON path:
/// agents[0].sensors[1].configuration.RangeMax) and what was expected.
HoloOceanSonarConfig readHoloOceanConfig(const std::filesystem::path& path);

}  // namespace sonarcarve
