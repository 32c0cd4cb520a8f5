#include "io/mission/nav_csv.h"

#include "common/angles.h"
#include "common/error.h"
#include "io/files/csv_table.h"
#include "io/files/yaml_fields.h"
#include "io/mission/nav_positions.h"
#include "sonar/attitude.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

NavTrack readTable(const CsvTable& table, std::string& grid_crs, bool geo_allowed) {
  const PositionKind kind =
      positionKind(table.has("north_m") || table.has("east_m"),
                   table.has("latitude_deg") || table.has("longitude_deg"),
                   table.has("easting_m") || table.has("northing_m"),
                   "north_m, east_m, latitude_deg, longitude_deg, easting_m, northing_m",
                   table.file(), table.headerPlace());
  if (kind != PositionKind::Ned && !geo_allowed) {
    throw Error(table.file(), table.headerPlace(),
                "geodetic or projected positions outside a mission: expected north_m, east_m "
                "(world NED metres) here");
  }
  const bool ned = kind == PositionKind::Ned;
  const bool geodetic = kind == PositionKind::Geodetic;
  const std::size_t t = table.column("time_s");
  const std::size_t n = table.column(ned ? "north_m" : geodetic ? "latitude_deg" : "northing_m");
  const std::size_t e = table.column(ned ? "east_m" : geodetic ? "longitude_deg" : "easting_m");
  const std::size_t d = table.column("down_m");
  const std::size_t roll = table.column("roll_deg");
  const std::size_t pitch = table.column("pitch_deg");
  const std::size_t yaw = table.column("yaw_deg");
  if (table.rows().empty()) {
    throw Error(table.file(), "", "no navigation samples after the header");
  }
  std::vector<NavSample> samples;
  std::vector<Eigen::Vector2d> xy;  // geodetic or projected positions, x first
  samples.reserve(table.rows().size());
  for (const auto& row : table.rows()) {
    NavSample s;
    s.time_s = table.number(row, t);
    if (!samples.empty() && !(s.time_s > samples.back().time_s)) {
      throw Error(table.file(), linePlace(row.line),
                  "time goes backwards or repeats: " + table.text(row, t) + " s after " +
                      shortestNumber(samples.back().time_s) + " s");
    }
    s.position_m = {table.number(row, n), table.number(row, e), table.number(row, d)};
    if (ned) {
      requirePlausiblePosition(s.position_m, table.file(), linePlace(row.line));
    } else if (geodetic) {
      xy.push_back(
          geodeticXy(s.position_m.x(), s.position_m.y(), table.file(), linePlace(row.line)));
    } else {
      xy.emplace_back(s.position_m.y(), s.position_m.x());
    }
    s.q_world_vehicle = quaternionFromRollPitchYaw({degToRad(table.number(row, roll)),
                                                    degToRad(table.number(row, pitch)),
                                                    degToRad(table.number(row, yaw))});
    samples.push_back(s);
  }
  const auto place = [&](std::size_t i) { return linePlace(table.rows()[i].line); };
  placeNavOnGrid(samples, xy, kind, grid_crs, {table.file(), place}, table.headerPlace());
  if (!ned) {
    for (std::size_t i = 0; i < samples.size(); ++i) {
      requirePlausiblePosition(samples[i].position_m, table.file(), place(i));
    }
  }
  return NavTrack(std::move(samples));
}

}  // namespace

NavTrack readNavCsv(const std::filesystem::path& path) {
  std::string no_crs;
  return readTable(CsvTable::read(path), no_crs, false);
}

NavTrack readNavCsv(const std::filesystem::path& path, std::string& grid_crs) {
  return readTable(CsvTable::read(path), grid_crs, true);
}

std::string navCsvText(const NavTrack& track) {
  std::string text = "time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg\n";
  for (const NavSample& s : track.samples()) {
    const RollPitchYaw rpy = rollPitchYawFromQuaternion(s.q_world_vehicle);
    text += shortestNumber(s.time_s) + "," + shortestNumber(s.position_m.x()) + "," +
            shortestNumber(s.position_m.y()) + "," + shortestNumber(s.position_m.z()) + "," +
            shortestDegrees(rpy.roll_rad) + "," + shortestDegrees(rpy.pitch_rad) + "," +
            shortestDegrees(rpy.yaw_rad) + "\n";
  }
  return text;
}

}  // namespace sonarcarve
