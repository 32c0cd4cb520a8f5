// `sonarcarve-cli import --format oculus LOG --out MISSION [--nav NAV.csv --nav-map MAP.yaml
//  --mounting M.yaml --time-offset S]`: a vendor log (and its navigation) as a mission folder.
#include <iostream>

#include "cli/commands.h"
#include "cli/terminal_progress.h"
#include "common/error.h"
#include "io/import.h"

namespace sonarcarve::cli {
namespace {

struct Options {
  std::string format = "oculus";
  std::string log, out, name, nav, nav_map, mounting;
  std::vector<std::string> nav_columns, nav_settings;
  double time_offset_s = 0.0;
  double aperture_deg = 0.0;
};

// "KEY=VALUE" -> key, value; throws a user error otherwise.
std::pair<std::string, std::string> keyValue(const std::string& text, const std::string& flag) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw Error(flag, "", "expected KEY=VALUE, found '" + text + "'");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

int runImport(const Options& o) {
  if (o.format != "oculus") {
    throw Error("--format", "", "unknown format '" + o.format + "': this build imports oculus");
  }
  ImportRequest request;
  request.log = o.log;
  request.out = o.out;
  request.name = o.name;
  request.nav_csv = o.nav;
  request.mounting_yaml = o.mounting;
  request.time_offset_s = o.time_offset_s;
  if (o.aperture_deg > 0.0) {
    request.vertical_aperture_deg = o.aperture_deg;
  }
  if (!o.nav_map.empty()) {
    request.nav_mapping = readNavMapping(o.nav_map);
  }
  for (const std::string& c : o.nav_columns) {
    const auto [role, column] = keyValue(c, "--nav-column");
    setNavMapping(request.nav_mapping, "columns." + role, column, "--nav-column");
  }
  for (const std::string& s : o.nav_settings) {
    const auto [key, value] = keyValue(s, "--nav-set");
    setNavMapping(request.nav_mapping, key, value, "--nav-set");
  }
  if (o.nav.empty() && (!o.nav_map.empty() || !o.nav_columns.empty())) {
    throw Error("--nav-map", "", "a navigation mapping needs --nav NAV.csv");
  }

  TerminalProgress progress;
  ImportReport report;
  try {
    report = importOculusToMission(request, progress);
  } catch (const Cancelled&) {
    progress.finish();
    std::cout << "cancelled: " << o.out << " is unfinished (no mission.yaml)\n";
    return 130;
  }
  progress.finish();
  std::cout << "imported " << report.frames_written << " frames of " << report.pings_in_log
            << " pings (" << report.container << ") into " << report.mission.string() << "\n";
  std::cout << "frame times: " << report.time_base << ", plus " << o.time_offset_s << " s\n";
  for (const std::string& w : report.warnings) {
    std::cout << "warning: " << w << "\n";
  }
  for (const std::string& p : report.problems) {
    std::cout << "problem: " << p << "\n";
  }
  for (const std::string& n : report.notes) {
    std::cout << "note: " << n << "\n";
  }
  return 0;
}

}  // namespace

void addImportCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("import", "Import a vendor sonar log into a mission folder");
  auto o = std::make_shared<Options>();
  cmd->add_option("--format", o->format, "Log format: oculus")->capture_default_str();
  cmd->add_option("log", o->log,
                  "The log: Oculus messages back to back, or an Oculus ViewPoint .oculus file")
      ->required();
  cmd->add_option("--out", o->out, "Mission folder to create (new or empty)")->required();
  cmd->add_option("--name", o->name, "Mission name (default: the log's file name)");
  cmd->add_option("--nav", o->nav,
                  "Navigation CSV (default columns: time_s,north_m,east_m,down_m,roll_deg,"
                  "pitch_deg,yaw_deg); without it the vehicle is stationary at the origin");
  cmd->add_option("--nav-map", o->nav_map, "Column mapping YAML for --nav (docs/formats.md)");
  cmd->add_option("--nav-column", o->nav_columns,
                  "ROLE=COLUMN for --nav, repeatable: roles time, north, east, down|depth, "
                  "up|altitude, roll, pitch, yaw|heading; COLUMN is a header name or a 0-based "
                  "index")
      ->allow_extra_args(false);
  cmd->add_option("--nav-set", o->nav_settings,
                  "KEY=VALUE for --nav, repeatable: units.time=s|ms|us, units.position=m|ft, "
                  "units.angles=deg|rad, conventions.heading=compass|enu, "
                  "conventions.pitch=bow_up|bow_down, conventions.roll=starboard_down|port_down, "
                  "delimiter=,|;|tab, header=true|false")
      ->allow_extra_args(false);
  cmd->add_option("--mounting", o->mounting,
                  "Mounting YAML: translation_m and roll_pitch_yaw_deg of the sonar on the "
                  "vehicle");
  cmd->add_option("--time-offset", o->time_offset_s,
                  "Seconds added to the log's frame times to put them on the navigation clock")
      ->capture_default_str();
  cmd->add_option("--aperture-deg", o->aperture_deg,
                  "Vertical aperture (default: 20 below 1.5 MHz, 12 above)");
  cmd->callback([o, &exit_code] { exit_code = runImport(*o); });
}

}  // namespace sonarcarve::cli
