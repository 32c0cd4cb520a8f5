#include "io/mission/nav_import.h"

#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <utility>

#include "common/angles.h"
#include "common/error.h"
#include "geo/crs.h"
#include "io/files/csv_table.h"
#include "io/files/yaml_fields.h"
#include "io/mission/nav_positions.h"
#include "sonar/attitude.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// The value named `text` among `choices`, or an error listing the names.
template <typename T>
T choose(const std::string& source, const std::string& key, const std::string& text,
         std::initializer_list<std::pair<const char*, T>> choices) {
  std::string names;
  for (const auto& [name, value] : choices) {
    if (text == name) {
      return value;
    }
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  throw Error(source, "", key + ": '" + text + "' is not one of " + names);
}

NavColumn columnFrom(const std::string& value) {
  NavColumn column;
  int index = -1;
  const char* end = value.data() + value.size();
  const auto [ptr, ec] = std::from_chars(value.data(), end, index);
  if (!value.empty() && ec == std::errc() && ptr == end && index >= 0) {
    column.index = index;
  } else {
    column.name = value;
  }
  return column;
}

std::size_t resolve(const CsvTable& table, const NavColumn& column) {
  if (column.index >= 0) {
    if (static_cast<std::size_t>(column.index) >= table.header().size()) {
      throw Error(table.file(), "",
                  "column index " + std::to_string(column.index) + " is past the last column (" +
                      std::to_string(table.header().size()) + " columns, counted from 0)");
    }
    return static_cast<std::size_t>(column.index);
  }
  return table.column(column.name);
}

NavMapping mappingFromYamlUnchecked(const YAML::Node& root, const YamlFields& fields,
                                    const std::string& source) {
  if (!root.IsMap()) {
    throw Error(source, "", "expected a YAML mapping with 'columns' (docs/formats.md)");
  }
  NavMapping mapping;
  // The YAML names only the columns it wants: the defaults apply to none of them.
  if (root["columns"]) {
    mapping.time = mapping.north = mapping.east = mapping.down = {};
    mapping.roll = mapping.pitch = mapping.yaw = {};
    mapping.default_positions = false;
  }
  const auto set = [&](const std::string& key, const YAML::Node& node) {
    try {
      setNavMapping(mapping, key, fields.text(node, key), source);
    } catch (const Error& e) {
      if (!e.place().empty()) {
        throw;
      }
      fields.fail(node, key, e.message().substr(key.size() + 2));
    }
  };
  for (const auto& entry : root) {
    const std::string section = entry.first.as<std::string>();
    const YAML::Node& value = entry.second;
    if (section == "delimiter" || section == "header" || section == "crs") {
      set(section, value);
      continue;
    }
    if (section != "columns" && section != "units" && section != "conventions") {
      fields.fail(entry.first, section,
                  "unknown key: expected columns, units, conventions, delimiter, header or crs");
    }
    if (!value.IsMap()) {
      fields.fail(value, section, "expected a mapping of keys");
    }
    for (const auto& item : value) {
      set(section + "." + item.first.as<std::string>(), item.second);
    }
  }
  if (!mapping.time.given()) {
    throw Error(source, "", "columns.time: missing (the time column is required)");
  }
  return mapping;
}

NavMapping mappingFromYaml(const YAML::Node& root, const YamlFields& fields,
                           const std::string& source) {
  try {
    return mappingFromYamlUnchecked(root, fields, source);
  } catch (const YAML::Exception& e) {
    throw Error(source, linePlace(e.mark.line + 1), "unexpected YAML structure: " + e.msg);
  }
}

// The two columns of the positions' kind: (north, east), (latitude, longitude) or (northing,
// easting). A mapping that names none reads the header as nav.csv does.
std::pair<NavColumn, NavColumn> positionColumns(const CsvTable& table, const NavMapping& m,
                                                PositionKind& kind) {
  if (m.default_positions) {
    kind = positionKind(table.has("north_m") || table.has("east_m"),
                        table.has("latitude_deg") || table.has("longitude_deg"),
                        table.has("easting_m") || table.has("northing_m"),
                        "north_m, east_m, latitude_deg, longitude_deg, easting_m, northing_m",
                        table.file(), table.headerPlace());
    return kind == PositionKind::Geodetic
               ? std::pair{NavColumn{"latitude_deg"}, NavColumn{"longitude_deg"}}
           : kind == PositionKind::Projected
               ? std::pair{NavColumn{"northing_m"}, NavColumn{"easting_m"}}
               : std::pair{m.north, m.east};
  }
  kind = positionKind(m.north.given() || m.east.given(), m.latitude.given() || m.longitude.given(),
                      m.easting.given() || m.northing.given(),
                      "columns north, east, latitude, longitude, easting, northing", table.file(),
                      "the navigation mapping");
  return kind == PositionKind::Geodetic    ? std::pair{m.latitude, m.longitude}
         : kind == PositionKind::Projected ? std::pair{m.northing, m.easting}
                                           : std::pair{m.north, m.east};
}

NavTrack trackFromTable(const CsvTable& table, const NavMapping& mapping, std::string& grid_crs) {
  PositionKind kind = PositionKind::Ned;
  const auto [north, east] = positionColumns(table, mapping, kind);
  if (!mapping.time.given() || !north.given() || !east.given() ||
      !(mapping.down.given() || mapping.up.given())) {
    throw Error(table.file(), "",
                "the navigation mapping must name the time, north, east (or latitude, "
                "longitude, or easting, northing) and down (or up) columns");
  }
  const std::size_t t = resolve(table, mapping.time);
  const std::size_t n = resolve(table, north);
  const std::size_t e = resolve(table, east);
  const std::size_t v = resolve(table, mapping.down.given() ? mapping.down : mapping.up);
  const double v_sign = mapping.down.given() ? 1.0 : -1.0;
  const auto optional = [&](const NavColumn& c) {
    return c.given() ? std::optional<std::size_t>(resolve(table, c)) : std::nullopt;
  };
  const auto roll = optional(mapping.roll);
  const auto pitch = optional(mapping.pitch);
  const auto yaw = optional(mapping.yaw);
  if (table.rows().empty()) {
    throw Error(table.file(), "", "no navigation samples");
  }
  const double angle = mapping.degrees ? std::numbers::pi / 180.0 : 1.0;
  const auto angleAt = [&](const CsvTable::Row& row, std::optional<std::size_t> column) {
    return column ? table.number(row, *column) * angle : 0.0;
  };
  std::vector<NavSample> samples;
  std::vector<Eigen::Vector2d> xy;  // geodetic or projected positions, x first
  samples.reserve(table.rows().size());
  for (const auto& row : table.rows()) {
    NavSample s;
    s.time_s = table.number(row, t) * mapping.seconds_per_time_unit;
    if (!samples.empty() && !(s.time_s > samples.back().time_s)) {
      throw Error(table.file(), linePlace(row.line),
                  "column '" + table.header()[t] +
                      "': time goes backwards or repeats: " + shortestNumber(s.time_s) +
                      " s after " + shortestNumber(samples.back().time_s) + " s");
    }
    if (kind == PositionKind::Ned) {
      s.position_m =
          mapping.metres_per_unit * Eigen::Vector3d(table.number(row, n), table.number(row, e),
                                                    v_sign * table.number(row, v));
    } else {
      // Degrees, or the CRS's metres: the position unit is the depth's only.
      s.position_m = {0.0, 0.0, mapping.metres_per_unit * v_sign * table.number(row, v)};
      xy.push_back(kind == PositionKind::Geodetic
                       ? geodeticXy(table.number(row, n), table.number(row, e), table.file(),
                                    linePlace(row.line))
                       : Eigen::Vector2d(table.number(row, e), table.number(row, n)));
    }
    RollPitchYaw rpy;
    rpy.roll_rad = angleAt(row, roll) * (mapping.roll_port_down ? -1.0 : 1.0);
    rpy.pitch_rad = angleAt(row, pitch) * (mapping.pitch_bow_down ? -1.0 : 1.0);
    const double heading = angleAt(row, yaw);
    rpy.yaw_rad = mapping.heading_enu ? std::numbers::pi / 2 - heading : heading;
    s.q_world_vehicle = quaternionFromRollPitchYaw(rpy);
    if (!s.position_m.allFinite() || !std::isfinite(s.time_s)) {
      throw Error(table.file(), linePlace(row.line), "value out of range after unit conversion");
    }
    if (kind == PositionKind::Ned) {
      requirePlausiblePosition(s.position_m, table.file(), linePlace(row.line));
    }
    samples.push_back(s);
  }
  const auto place = [&](std::size_t i) { return linePlace(table.rows()[i].line); };
  placeNavOnGrid(samples, xy, kind, grid_crs, {table.file(), place}, table.headerPlace());
  if (kind != PositionKind::Ned) {
    for (std::size_t i = 0; i < samples.size(); ++i) {
      requirePlausiblePosition(samples[i].position_m, table.file(), place(i));
    }
  }
  return NavTrack(std::move(samples));
}

NavTrack trackWithCrs(const CsvTable& table, const NavMapping& mapping, std::string* grid_crs) {
  std::string crs = mapping.crs;
  NavTrack track = trackFromTable(table, mapping, crs);
  if (grid_crs != nullptr) {
    *grid_crs = crs;
  }
  return track;
}

}  // namespace

std::string NavColumn::describe() const {
  return index >= 0 ? "column " + std::to_string(index) : "column '" + name + "'";
}

void setNavMapping(NavMapping& m, const std::string& key, const std::string& value,
                   const std::string& source) {
  if (key.starts_with("columns.")) {
    const std::string what = key.substr(8);
    const NavColumn column = columnFrom(value);
    // Naming a position column ends the choice by the header; a geodetic or projected one
    // also ends the default north and east.
    const bool grid_or_geodetic =
        what == "latitude" || what == "longitude" || what == "easting" || what == "northing";
    if (grid_or_geodetic && m.default_positions) {
      m.north = m.east = {};
    }
    if (grid_or_geodetic || what == "north" || what == "east") {
      m.default_positions = false;
    }
    if (what == "time") {
      m.time = column;
    } else if (what == "north") {
      m.north = column;
    } else if (what == "east") {
      m.east = column;
    } else if (what == "latitude") {
      m.latitude = column;
    } else if (what == "longitude") {
      m.longitude = column;
    } else if (what == "easting") {
      m.easting = column;
    } else if (what == "northing") {
      m.northing = column;
    } else if (what == "down" || what == "depth") {
      m.down = column;
      m.up = {};
    } else if (what == "up" || what == "altitude") {
      m.up = column;
      m.down = {};
    } else if (what == "roll") {
      m.roll = column;
    } else if (what == "pitch") {
      m.pitch = column;
    } else if (what == "yaw" || what == "heading") {
      m.yaw = column;
    } else {
      throw Error(source, "",
                  key +
                      ": unknown column role: expected time, north, east (or latitude, "
                      "longitude, or easting, northing), down (or depth), up (or altitude), "
                      "roll, pitch, yaw (or heading)");
    }
  } else if (key == "units.time") {
    m.seconds_per_time_unit =
        choose<double>(source, key, value, {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}});
  } else if (key == "units.position") {
    m.metres_per_unit = choose<double>(source, key, value, {{"m", 1.0}, {"ft", 0.3048}});
  } else if (key == "units.angles") {
    m.degrees = choose<bool>(source, key, value, {{"deg", true}, {"rad", false}});
  } else if (key == "conventions.heading") {
    m.heading_enu = choose<bool>(source, key, value, {{"compass", false}, {"enu", true}});
  } else if (key == "conventions.pitch") {
    m.pitch_bow_down = choose<bool>(source, key, value, {{"bow_up", false}, {"bow_down", true}});
  } else if (key == "conventions.roll") {
    m.roll_port_down =
        choose<bool>(source, key, value, {{"starboard_down", false}, {"port_down", true}});
  } else if (key == "delimiter") {
    m.delimiter =
        choose<char>(source, key, value, {{",", ','}, {";", ';'}, {"|", '|'}, {"tab", '\t'}});
  } else if (key == "header") {
    m.header = choose<bool>(source, key, value, {{"true", true}, {"false", false}});
  } else if (key == "crs") {
    if (const auto problem = gridCrsProblem(value)) {
      throw Error(source, "", key + ": " + *problem);
    }
    m.crs = value;
  } else {
    throw Error(source, "", key + ": unknown setting");
  }
}

NavMapping readNavMapping(const std::filesystem::path& path) {
  const YamlFields fields(path.string());
  return mappingFromYaml(fields.load(), fields, path.string());
}

NavMapping parseNavMapping(std::string_view text, const std::string& source) {
  const YamlFields fields(source);
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw Error(source, linePlace(e.mark.line + 1), "not valid YAML: " + e.msg);
  }
  fields.requireUniqueKeys(root);
  return mappingFromYaml(root, fields, source);
}

NavTrack importNavCsv(const std::filesystem::path& path, const NavMapping& mapping,
                      std::string* grid_crs) {
  return trackWithCrs(CsvTable::read(path, {mapping.delimiter, mapping.header}), mapping, grid_crs);
}

NavTrack importNavCsvText(std::string_view text, const std::string& source,
                          const NavMapping& mapping, std::string* grid_crs) {
  return trackWithCrs(CsvTable::parse(text, source, {mapping.delimiter, mapping.header}), mapping,
                      grid_crs);
}

}  // namespace sonarcarve
