// Importing vendor sonar logs into a mission folder (format v1): the API behind
// `sonarcarve-cli import` and the GUI's import dialog. docs/formats.md, "Importing".
//
// Time: a frame's time on the navigation clock is its time in the log (OculusLog::timeBase())
// plus `time_offset_s`: with a navigation whose clock runs 3 s ahead of the sonar's, pass +3.
// Without navigation the vehicle is stationary at the origin with zero attitude over the
// frames' time span (a warning says so). One mission has one sonar geometry: pings with
// another range window or bearing table than the log's most common one are reported and left
// out.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "common/progress.h"
#include "io/frame_source.h"
#include "io/mission/nav_import.h"
#include "io/oculus/oculus_log.h"
#include "sonar/mounting.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// The vertical aperture used for an Oculus ping without an override: 20 deg in low-frequency
/// mode (below 1.5 MHz: M370s, M750d LF, M1200d LF), 12 deg in high-frequency mode (M750d HF
/// at 1.2 MHz... see docs/formats.md for the table and its sources).
double oculusVerticalApertureDeg(const OculusPing& ping);

/// The sonar model of a ping: its bearing table as is, nRanges bins of rangeResolution from
/// range 0, and the vertical aperture (`aperture_deg` or oculusVerticalApertureDeg).
SonarModel sonarModelFromPing(const OculusPing& ping, std::optional<double> aperture_deg);
/// How a ping's samples relate to the sonar's linear scale: its gammaCorrection (0 and 255:
/// linear; 127: gamma 0.498) over the full scale of its sample size. Throws Error for a gamma
/// too small for its samples (IntensityScale::gamma).
IntensityScale oculusIntensityScale(const OculusPing& ping);
/// What the pings of one mission share: range bins, beams, bearing table and samples' scale
/// (a gamma too small to take is a scale of its own, which no sonar model has).
using OculusPingFormat = std::tuple<int, int, double, std::vector<double>, IntensityScale::Key>;
OculusPingFormat oculusPingFormat(const OculusPing& ping);
OculusPingFormat oculusPingFormat(const SonarModel& sonar);

/// What a log gives before anything is written: shared by import and `info`.
struct OculusImportPlan {
  SonarModel sonar;
  std::vector<std::size_t> pings;     ///< pings of the log's main geometry, in time order
  std::vector<double> frame_times_s;  ///< their times on the navigation clock
  std::size_t other_geometry = 0;     ///< pings left out: another geometry
  double frequency_hz = 0.0;          ///< of the first ping used
  double speed_of_sound_mps = 0.0;
  std::vector<std::string> warnings;
};
OculusImportPlan planOculusImport(const OculusLog& log, double time_offset_s,
                                  std::optional<double> aperture_deg);

/// A stationary vehicle at the origin, zero attitude, covering [first - 1 s, last + 1 s].
NavTrack stationaryTrack(const std::vector<double>& times_s);

struct ImportRequest {
  std::filesystem::path log;
  std::filesystem::path out;            ///< mission folder to create (must not hold files)
  std::string name;                     ///< mission name; default: the log's file name
  std::filesystem::path nav_csv;        ///< empty: stationary vehicle
  NavMapping nav_mapping;               ///< how to read nav_csv
  std::filesystem::path mounting_yaml;  ///< empty: sonar at the vehicle origin, aligned
  double time_offset_s = 0.0;
  std::optional<double> vertical_aperture_deg;
};

struct ImportReport {
  std::filesystem::path mission;
  std::string container;
  std::string time_base;
  std::size_t pings_in_log = 0;
  std::size_t frames_written = 0;
  std::size_t frames_outside_nav = 0;
  std::vector<std::string> notes;     ///< skipped non-ping content
  std::vector<std::string> problems;  ///< corrupt data skipped
  std::vector<std::string> warnings;  ///< choices the user should know about
};

/// Imports an Oculus log. Throws Error on an unusable log, navigation or mounting, and
/// Cancelled if `progress` asks to stop (the folder then lacks mission.yaml: unfinished).
ImportReport importOculusToMission(const ImportRequest& request, Progress& progress);

/// Imports any recording openMission() reads (ARIS files, ROS 2 bags, ...) with `options`
/// (the request's log, out and name are used; its other fields are in `options`). The mission
/// keeps the recording's sonar (elevation beam included), navigation and mounting.
ImportReport importRecordingToMission(const ImportRequest& request, const OpenOptions& options,
                                      Progress& progress);

/// Reads a mounting YAML: a `mounting:` mapping, or its keys at the top level.
Mounting readMountingYaml(const std::filesystem::path& path);

}  // namespace sonarcarve
