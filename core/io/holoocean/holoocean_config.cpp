#include "io/holoocean/holoocean_config.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/input_limits.h"
#include "common/number_text.h"
#include "io/files/input_file.h"

namespace sonarcarve {
namespace {

using nlohmann::json;

// Reads keys of one JSON object, naming each by its path in errors.
class ConfigKeys {
 public:
  ConfigKeys(const std::filesystem::path& file, const json& object, std::string place)
      : file_(file.string()), object_(object), place_(std::move(place)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw Error(file_, "key " + place_ + (key.empty() ? "" : "." + key), what);
  }

  const json* find(const std::string& key) const {
    const auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }

  double number(const std::string& key, const std::string& expected) const {
    const json* v = find(key);
    if (v == nullptr) {
      fail(key, "missing: expected " + expected);
    }
    if (!v->is_number() || !std::isfinite(v->get<double>())) {
      fail(key, std::string("is ") + v->type_name() + " " + v->dump() + ": expected " + expected);
    }
    return v->get<double>();
  }

  std::optional<int> count(const std::string& key, int max) const {
    const json* v = find(key);
    if (v == nullptr) {
      return std::nullopt;
    }
    if (!v->is_number_integer() || v->get<std::int64_t>() < 1 || v->get<std::int64_t>() > max) {
      fail(key, std::string("is ") + v->type_name() + " " + v->dump() +
                    ": expected a whole number from 1 to " + std::to_string(max));
    }
    return static_cast<int>(v->get<std::int64_t>());
  }

  std::string text(const std::string& key, const std::string& fallback) const {
    const json* v = find(key);
    if (v == nullptr) {
      return fallback;
    }
    if (!v->is_string()) {
      fail(key, std::string("is ") + v->type_name() + ": expected a string");
    }
    return v->get<std::string>();
  }

 private:
  std::string file_;
  const json& object_;
  std::string place_;
};

json parseConfig(const std::filesystem::path& path) {
  const std::string text = readInputFile(path, "HoloOcean Config.json", kMaxYamlFileBytes);
  try {
    return json::parse(withoutByteOrderMark(text));
  } catch (const json::parse_error& e) {
    throw Error(path.string(), bytePlace(e.byte), std::string("not JSON: ") + e.what());
  }
}

const json& member(const std::filesystem::path& path, const json& parent, const std::string& key,
                   const std::string& place, bool array) {
  const auto it = parent.find(key);
  const std::string where = place.empty() ? key : place + "." + key;
  if (it == parent.end()) {
    throw Error(path.string(), "key " + where,
                std::string("missing: expected ") + (array ? "a list" : "an object"));
  }
  if (array ? !it->is_array() : !it->is_object()) {
    throw Error(
        path.string(), "key " + where,
        std::string("is ") + it->type_name() + ": expected " + (array ? "a list" : "an object"));
  }
  return *it;
}

void readSonar(const std::filesystem::path& path, const json& sensor, const std::string& place,
               HoloOceanSonarConfig& config) {
  const json& c = member(path, sensor, "configuration", place, false);
  const ConfigKeys keys(path, c, place + ".configuration");
  config.range_min_m = keys.number("RangeMin", "a range in metres");
  config.range_max_m = keys.number("RangeMax", "a range in metres");
  config.azimuth_deg = keys.number("Azimuth", "the field of view in degrees");
  config.elevation_deg = keys.number("Elevation", "the vertical aperture in degrees");
  config.range_bins = keys.count("RangeBins", kMaxRangeBins);
  config.azimuth_bins = keys.count("AzimuthBins", kMaxBeams);
  if (!(config.range_min_m >= 0.0)) {
    keys.fail("RangeMin", "is " + shortestNumber(config.range_min_m) + ": expected >= 0 m");
  }
  if (!(config.range_max_m > config.range_min_m) || config.range_max_m > 1e4) {
    keys.fail("RangeMax", "is " + shortestNumber(config.range_max_m) +
                              ": expected more than RangeMin and at most 10 km");
  }
  if (!(config.azimuth_deg > 0.0 && config.azimuth_deg <= 360.0)) {
    keys.fail("Azimuth",
              "is " + shortestNumber(config.azimuth_deg) + ": expected degrees in (0, 360]");
  }
  if (!(config.elevation_deg > 0.0 && config.elevation_deg < 180.0)) {
    keys.fail("Elevation",
              "is " + shortestNumber(config.elevation_deg) + ": expected degrees in (0, 180)");
  }
}

}  // namespace

HoloOceanSonarConfig readHoloOceanConfig(const std::filesystem::path& path) {
  const json root = parseConfig(path);
  if (!root.is_object()) {
    throw Error(path.string(), "",
                std::string("is a JSON ") + root.type_name() +
                    ": expected an object (a HoloOcean scenario)");
  }
  const json& agents = member(path, root, "agents", "", true);
  HoloOceanSonarConfig config;
  for (std::size_t a = 0; a < agents.size(); ++a) {
    const std::string agent_place = "agents[" + std::to_string(a) + "]";
    if (!agents[a].is_object()) {
      continue;
    }
    const json& sensors = member(path, agents[a], "sensors", agent_place, true);
    std::optional<std::size_t> sonar, pose;
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      if (!sensors[s].is_object()) {
        continue;
      }
      const ConfigKeys keys(path, sensors[s], agent_place + ".sensors[" + std::to_string(s) + "]");
      const std::string type = keys.text("sensor_type", "");
      if (type == "ImagingSonar" && !sonar) {
        sonar = s;
        config.image_key = keys.text("sensor_name", type);
        const json* hz = keys.find("Hz");
        config.frame_rate_hz = hz != nullptr && hz->is_number() ? hz->get<double>() : 0.0;
      } else if (type == "ImagingSonar") {
        config.warnings.push_back(path.string() + ": more than one ImagingSonar: the first (" +
                                  config.image_key + ") is read");
      } else if (type == "PoseSensor" && !pose) {
        pose = s;
        config.pose_key = keys.text("sensor_name", type);
      }
    }
    if (!sonar) {
      continue;
    }
    const std::string place = agent_place + ".sensors[" + std::to_string(*sonar) + "]";
    readSonar(path, sensors[*sonar], place, config);
    if (pose) {
      const ConfigKeys sonar_keys(path, sensors[*sonar], place);
      const ConfigKeys pose_keys(path, sensors[*pose],
                                 agent_place + ".sensors[" + std::to_string(*pose) + "]");
      if (sonar_keys.text("socket", "") != pose_keys.text("socket", "")) {
        config.warnings.push_back(
            path.string() + ": the PoseSensor sits in socket '" + pose_keys.text("socket", "") +
            "', the ImagingSonar in '" + sonar_keys.text("socket", "") +
            "': its pose is taken as the sonar's (give the offset with --mounting if they differ)");
      }
    }
    if (config.frame_rate_hz <= 0.0) {
      const json* ticks = root.contains("ticks_per_sec") ? &root["ticks_per_sec"] : nullptr;
      config.frame_rate_hz = ticks != nullptr && ticks->is_number() ? ticks->get<double>() : 0.0;
    }
    return config;
  }
  throw Error(path.string(), "key agents",
              "no agent has a sensor of sensor_type ImagingSonar: expected a HoloOcean scenario "
              "with an imaging sonar (NeuSIS layout)");
}

}  // namespace sonarcarve
