// `sonarcarve-cli import [--format auto|oculus] LOG --out MISSION [--nav NAV.csv --nav-map
//  MAP.yaml --mounting M.yaml --time-offset S ...]`: a vendor log or a ROS 2 bag (and its
//  navigation) as a mission folder.
#include <iostream>

#include "cli/commands.h"
#include "cli/source_flags.h"
#include "cli/terminal_progress.h"
#include "common/error.h"
#include "io/files/output_folder.h"
#include "io/import.h"

namespace sonarcarve::cli {
namespace {

struct Options {
  std::string format = "auto";
  std::string log, out, name;
  SourceFlags source;
};

int runImport(const Options& o) {
  if (o.format != "auto" && o.format != "oculus") {
    throw Error("--format", "", "unknown format '" + o.format + "': expected auto or oculus");
  }
  requireOutputFolder(o.out);  // before the log is read
  const OpenOptions open = openOptionsFrom(o.source);
  // Oculus logs through their importer, which also explains what is wrong with a file that no
  // reader recognises.
  const std::optional<std::string> reader = recognisingReader(o.log);
  const bool oculus = o.format == "oculus" || !reader || *reader == "oculus";
  ImportRequest request;
  request.log = o.log;
  request.out = o.out;
  request.name = o.name;
  request.nav_csv = open.nav_csv;
  request.nav_mapping = open.nav_mapping;
  request.mounting_yaml = open.mounting;
  request.time_offset_s = open.time_offset_s;
  request.vertical_aperture_deg = open.vertical_aperture_deg;

  TerminalProgress progress;
  ImportReport report;
  try {
    report = oculus ? importOculusToMission(request, progress)
                    : importRecordingToMission(request, open, progress);
  } catch (const Cancelled&) {
    progress.finish();
    std::cout << "cancelled: " << o.out << " is unfinished (no mission.yaml)\n";
    return 130;
  }
  progress.finish();
  std::cout << "imported " << report.frames_written << " frames of " << report.pings_in_log
            << " pings (" << report.container << ") into " << report.mission.string() << "\n";
  std::cout << "frame times: " << report.time_base << ", plus " << o.source.time_offset_s << " s\n";
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
  auto* cmd = app.add_subcommand("import",
                                 "Import a vendor sonar log or a ROS 2 bag into a mission folder");
  auto o = std::make_shared<Options>();
  cmd->add_option("--format", o->format,
                  "auto: by content (Oculus logs, ARIS recordings, ROS 2 bags, HoloOcean / NeuSIS "
                  "datasets); oculus")
      ->capture_default_str();
  cmd->add_option("log", o->log,
                  "The log: Oculus messages or an Oculus ViewPoint .oculus file, an ARIS "
                  "recording, a ROS 2 bag (.mcap, .db3 or its folder), a HoloOcean / NeuSIS "
                  "dataset folder (Config.json and Data/*.pkl)")
      ->required();
  cmd->add_option("--out", o->out, "Mission folder to create (new or empty)")->required();
  cmd->add_option("--name", o->name, "Mission name (default: the log's file name)");
  addSourceFlags(*cmd, o->source);
  cmd->callback([o, &exit_code] { exit_code = runImport(*o); });
}

}  // namespace sonarcarve::cli
