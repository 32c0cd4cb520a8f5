#include "cli/bench_validate.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/error.h"
#include "io/files/atomic_file.h"

namespace sonarcarve::cli {
namespace {

struct ValidationMission {
  const char* name;
  const char* what;      // for the table
  const char* simulate;  // simulate's arguments
};

// Scenes seen from one side and from several, noise-free and noisy, seabeds, and a beam that is
// not as declared (docs/validation.md).
const std::vector<ValidationMission>& missions() {
  static const std::vector<ValidationMission> set = {
      {"riser-vertical", "riser, vertical pass, noise-free", "--scene riser --noise none"},
      {"riser-vertical-noisy", "riser, vertical pass, default noise", "--scene riser"},
      {"riser-vertical-coherent", "riser, vertical pass, coherent noise",
       "--scene riser --noise coherent"},
      {"riser-orbit", "riser, orbit, noise-free", "--scene riser --trajectory orbit --noise none"},
      {"jacket-vertical", "jacket node, vertical pass, noise-free",
       "--scene jacket-node --noise none"},
      {"jacket-orbit", "jacket node, orbit, noise-free",
       "--scene jacket-node --trajectory orbit --noise none"},
      {"manifold", "manifold on the seabed, noise-free", "--scene manifold --noise none"},
      {"seabed-objects", "seabed with objects, lawnmower, noise-free",
       "--scene seabed-objects --noise none"},
      {"riser-no-tails", "riser, beam without tails declared sinc, noise-free",
       "--scene riser --noise none --beam clipped --declared-beam sinc"},
      {"riser-cut-beam", "riser, beam cut past -6 dB declared sinc, noise-free",
       "--scene riser --noise none --elevation-beam truncated"},
      {"riser-gaussian-beam", "riser, gaussian beam declared sinc, noise-free",
       "--scene riser --noise none --elevation-beam gaussian"},
      {"riser-orbit-cut-beam", "riser, orbit, beam cut past -6 dB declared sinc, noise-free",
       "--scene riser --trajectory orbit --noise none --elevation-beam truncated"},
      {"riser-two-levels", "riser, level orbits at two depths tilted 20 deg down, noise-free",
       "--scene riser --trajectory orbit --orbit-levels 2 --tilt -20 --noise none"},
      {"jacket-descents", "jacket node, 4 descents, noise-free",
       "--scene jacket-node --trajectory descents --noise none"},
      {"jacket-relief", "jacket node, vertical pass, seabed with 0.3 m relief, noise-free",
       "--scene jacket-node --noise none --seabed-relief 0.3"},
  };
  return set;
}

std::string shellQuoted(const std::filesystem::path& path) {
  std::string text = "'";
  for (const char c : path.string()) {
    text += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return text + "'";
}

// Runs this program with `arguments`, its output to `log`; throws Error when it fails.
void runProgram(const std::string& program, const std::string& arguments,
                const std::filesystem::path& log) {
  const std::string command = shellQuoted(std::filesystem::path(program)) + " " + arguments +
                              " > " + shellQuoted(log) + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    throw Error(log.string(), "",
                "failed: " + program + " " + arguments + " (its output is there)");
  }
}

std::string figure(const nlohmann::json& evaluation, const char* key, double scale, int digits) {
  if (!evaluation.contains(key)) {
    return "";
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, scale * evaluation.at(key).get<double>());
  return text;
}

}  // namespace

std::vector<std::string> validationMissions() {
  std::vector<std::string> names;
  for (const ValidationMission& m : missions()) {
    names.emplace_back(m.name);
  }
  return names;
}

int benchValidate(const BenchValidateOptions& o) {
  const std::filesystem::path out(o.out);
  std::filesystem::create_directories(out);
  std::ostringstream table;
  table << "| mission | frames | surface points | F@5cm | median (cm) | p90 (cm) | precision | "
           "completeness | warnings | run (s) |\n"
        << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  const std::string frames =
      o.max_frames > 0 ? " --max-frames " + std::to_string(o.max_frames) : std::string();
  for (const ValidationMission& m : missions()) {
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), m.name) == o.only.end()) {
      continue;
    }
    const std::filesystem::path mission = out / m.name;
    const std::filesystem::path run = out / (std::string(m.name) + "-run");
    std::cerr << "validate: " << m.name << "\n";
    runProgram(
        o.program,
        std::string("simulate ") + m.simulate + frames + " --force --out " + shellQuoted(mission),
        out / (std::string(m.name) + "-simulate.log"));
    const auto t0 = std::chrono::steady_clock::now();
    runProgram(o.program, "reconstruct " + shellQuoted(mission) + " --out " + shellQuoted(run),
               out / (std::string(m.name) + "-reconstruct.log"));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::ifstream report_file(run / "report.json");
    const nlohmann::json report = nlohmann::json::parse(report_file);
    const nlohmann::json evaluation = report.value("evaluation", nlohmann::json::object());
    std::string warnings;
    for (const nlohmann::json& choice : report.value("choices", nlohmann::json::array())) {
      if (choice.value("warning", false)) {
        warnings += (warnings.empty() ? "" : "; ") + choice.value("name", std::string()) + ": " +
                    choice.value("value", std::string());
      }
    }
    char time[32];
    std::snprintf(time, sizeof time, "%.1f", seconds);
    table << "| " << m.what << " | " << report.value("frames_used", 0) << " | "
          << report.value("surface_points", 0) << " | " << figure(evaluation, "fscore", 1, 3)
          << " | " << figure(evaluation, "accuracy_median_m", 100, 1) << " | "
          << figure(evaluation, "accuracy_p90_m", 100, 1) << " | "
          << figure(evaluation, "precision", 1, 3) << " | "
          << figure(evaluation, "completeness", 1, 3) << " | " << warnings << " | " << time
          << " |\n";
  }
  writeFileAtomically(out / "validation.md", table.str());
  std::cout << table.str();
  return 0;
}

}  // namespace sonarcarve::cli
