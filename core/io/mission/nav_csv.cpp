#include "io/mission/nav_csv.h"

#include "common/angles.h"
#include "common/error.h"
#include "io/files/csv_table.h"
#include "io/files/yaml_fields.h"
#include "sonar/attitude.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {

NavTrack readNavCsv(const std::filesystem::path& path) {
  const CsvTable table = CsvTable::read(path);
  const std::size_t t = table.column("time_s");
  const std::size_t n = table.column("north_m");
  const std::size_t e = table.column("east_m");
  const std::size_t d = table.column("down_m");
  const std::size_t roll = table.column("roll_deg");
  const std::size_t pitch = table.column("pitch_deg");
  const std::size_t yaw = table.column("yaw_deg");
  if (table.rows().empty()) {
    throw Error(table.file(), "", "no navigation samples after the header");
  }
  std::vector<NavSample> samples;
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
    requirePlausiblePosition(s.position_m, table.file(), linePlace(row.line));
    s.q_world_vehicle = quaternionFromRollPitchYaw({degToRad(table.number(row, roll)),
                                                    degToRad(table.number(row, pitch)),
                                                    degToRad(table.number(row, yaw))});
    samples.push_back(s);
  }
  return NavTrack(std::move(samples));
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
