// `sonarcarve-cli nav-error MISSION --out NAV.csv`: the mission's navigation with seeded
// errors (random walk, constant bias, white noise; docs/simulator.md), to reconstruct with
// `reconstruct MISSION --nav NAV.csv` against the mission's own ground truth. The same flags
// serve `simulate`.
#include <iostream>

#include "cli/commands.h"
#include "cli/nav_error_flags.h"
#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/output_folder.h"
#include "io/mission/mission.h"
#include "io/mission/nav_csv.h"
#include "sim/trajectory.h"

namespace sonarcarve::cli {

void addNavErrorFlags(CLI::App& cmd, NavErrorSpec& spec) {
  struct Flag {
    const char* name;
    double NavErrorSpec::*field;
    const char* help;
  };
  static constexpr Flag kFlags[] = {
      {"--nav-error-position", &NavErrorSpec::position_sigma_m,
       "Random-walk step of the recorded position per navigation sample, m"},
      {"--nav-error-attitude", &NavErrorSpec::attitude_sigma_deg,
       "Random-walk step of the recorded attitude per navigation sample, deg"},
      {"--nav-bias-position", &NavErrorSpec::position_bias_m,
       "Constant position bias: standard deviation of one offset per axis, m"},
      {"--nav-bias-attitude", &NavErrorSpec::attitude_bias_deg,
       "Constant attitude bias: standard deviation of one offset per angle, deg"},
      {"--nav-noise-position", &NavErrorSpec::position_noise_m,
       "White noise on each recorded position, standard deviation per axis, m"},
      {"--nav-noise-attitude", &NavErrorSpec::attitude_noise_deg,
       "White noise on each recorded attitude, standard deviation per angle, deg"},
  };
  for (const Flag& flag : kFlags) {
    cmd.add_option(flag.name, spec.*flag.field, flag.help)
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
  }
  cmd.add_option_function<std::string>(
         "--nav-error-axes",
         [&spec](const std::string& names) { spec.axes = navAxesFromNames(names); },
         "The axes the errors reach, the others kept true: all, or a list of north, east, down, "
         "roll, pitch, yaw (e.g. down,roll,pitch). The draws are those of all axes, so one seed "
         "tells which axes of a drift spoil a map")
      ->check([](const std::string& names) {
        try {
          navAxesFromNames(names);
          return std::string();
        } catch (const Error& e) {
          return std::string(e.what());
        }
      })
      ->default_str("all");
}

void addNavErrorCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "nav-error", "Write a mission's navigation with seeded errors, to reconstruct with --nav");
  struct Options {
    std::string mission, out;
    NavErrorSpec spec;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("mission", o->mission, "Mission folder")->required();
  cmd->add_option("--out", o->out, "Navigation CSV to write (the mission format's columns)")
      ->required();
  cmd->add_option("--seed", o->spec.seed, "Seed of the errors")->capture_default_str();
  addNavErrorFlags(*cmd, o->spec);
  cmd->callback([o, &exit_code] {
    const auto hold = holdOutputFile(o->out);
    const Mission mission = readMission(o->mission);
    const NavTrack recorded(withNavigationError(mission.nav.samples(), o->spec));
    writeFileAtomically(o->out, navCsvText(recorded));
    std::cout << recorded.samples().size() << " navigation samples with errors written to "
              << o->out << "\n";
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
