#include "session/session_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/yaml_fields.h"

namespace sonarcarve {
namespace {

constexpr const char* kFormat = "sonarcarve-session";
constexpr int kVersion = 1;

YAML::Node vector3(const Eigen::Vector3d& v) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.SetStyle(YAML::EmitterStyle::Flow);
  for (int i = 0; i < 3; ++i) {
    n.push_back(v[i]);
  }
  return n;
}

Eigen::Vector3d vector3(const YamlFields& f, const YAML::Node& camera, const std::string& key) {
  const auto v = f.numbers(f.child(camera, "camera", key), "camera." + key, 3);
  return {v[0], v[1], v[2]};
}

YAML::Node runNode(const RunRecord& run) {
  YAML::Node n;
  n["started"] = run.started;
  n["frames"] = run.frames;
  n["occupied_voxels"] = run.occupied_voxels;
  n["surface_points"] = run.surface_points;
  n["mesh_triangles"] = run.mesh_triangles;
  n["seconds"] = run.seconds;
  if (!run.report.empty()) {
    n["report"] = run.report;
  }
  if (run.accuracy) {
    YAML::Node a;
    a["fscore"] = run.accuracy->fscore;
    a["median_m"] = run.accuracy->median_m;
    a["p90_m"] = run.accuracy->p90_m;
    a["precision"] = run.accuracy->precision;
    a["completeness"] = run.accuracy->completeness;
    n["accuracy"] = a;
  }
  n["params"] = YAML::Load(run.params.toYaml());
  return n;
}

std::size_t count(const YamlFields& f, const YAML::Node& node, const std::string& path) {
  const double v = f.number(node, path);
  if (!(v >= 0.0 && v <= 1e15)) {
    f.fail(node, path, "expected a count from 0 to 1e15");
  }
  return static_cast<std::size_t>(v);
}

RunRecord runOf(const YamlFields& f, const YAML::Node& n, const std::string& path,
                const std::string& file) {
  if (!n.IsMap()) {
    f.fail(n, path, "expected a run (a mapping)");
  }
  RunRecord run;
  if (n["started"]) {
    run.started = f.text(n["started"], path + ".started");
  }
  run.frames = count(f, f.child(n, path, "frames"), path + ".frames");
  run.occupied_voxels = count(f, f.child(n, path, "occupied_voxels"), path + ".occupied_voxels");
  run.surface_points = count(f, f.child(n, path, "surface_points"), path + ".surface_points");
  if (n["mesh_triangles"]) {
    run.mesh_triangles = count(f, n["mesh_triangles"], path + ".mesh_triangles");
  }
  run.seconds = f.number(f.child(n, path, "seconds"), path + ".seconds");
  if (n["report"]) {
    run.report = f.text(n["report"], path + ".report");
  }
  if (const YAML::Node a = n["accuracy"]) {
    const std::string at = path + ".accuracy";
    RunAccuracy accuracy;
    accuracy.fscore = f.number(f.child(a, at, "fscore"), at + ".fscore");
    accuracy.median_m = f.number(f.child(a, at, "median_m"), at + ".median_m");
    accuracy.p90_m = f.number(f.child(a, at, "p90_m"), at + ".p90_m");
    accuracy.precision = f.number(f.child(a, at, "precision"), at + ".precision");
    accuracy.completeness = f.number(f.child(a, at, "completeness"), at + ".completeness");
    run.accuracy = accuracy;
  }
  run.params = ReconstructionParams::fromYamlNode(f.child(n, path, "params"), file);
  return run;
}

}  // namespace

void saveSession(const Session& s, const std::filesystem::path& file) {
  YAML::Node root;
  root["format"] = kFormat;
  root["version"] = kVersion;
  root["mission"] = s.mission;
  root["frame"] = s.frame;
  root["colour_by"] = s.colour_by;
  YAML::Node camera;
  camera["position"] = vector3(s.camera.position);
  camera["focal_point"] = vector3(s.camera.focal_point);
  camera["view_up"] = vector3(s.camera.view_up);
  camera["parallel"] = s.camera.parallel;
  camera["parallel_scale"] = s.camera.parallel_scale;
  camera["view_angle_deg"] = s.camera.view_angle_deg;
  root["camera"] = camera;
  root["params"] = YAML::Load(s.params.toYaml());
  if (!s.runs.empty()) {
    YAML::Node runs(YAML::NodeType::Sequence);
    for (const RunRecord& run : s.runs) {
      runs.push_back(runNode(run));
    }
    root["runs"] = runs;
  }
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << root;
  writeFileAtomically(file, std::string("# SonarCarve GUI session\n") + out.c_str() + "\n");
}

Session loadSession(const std::filesystem::path& file) {
  const YamlFields f(file.string());
  const YAML::Node root = f.load();
  if (f.text(f.child(root, "", "format"), "format") != kFormat) {
    f.fail(root["format"], "format", std::string("expected '") + kFormat + "'");
  }
  if (f.number(f.child(root, "", "version"), "version") != kVersion) {
    f.fail(root["version"], "version", "expected version 1");
  }
  Session s;
  s.mission = f.text(f.child(root, "", "mission"), "mission");
  if (root["frame"]) {
    const double frame = f.number(root["frame"], "frame");
    if (!(frame >= 0.0 && frame <= 1e9)) {
      f.fail(root["frame"], "frame", "expected a frame index from 0 to 1e9");
    }
    s.frame = static_cast<int>(frame);
  }
  if (root["colour_by"]) {
    s.colour_by = f.text(root["colour_by"], "colour_by");
  }
  if (const YAML::Node camera = root["camera"]) {
    s.camera.position = vector3(f, camera, "position");
    s.camera.focal_point = vector3(f, camera, "focal_point");
    s.camera.view_up = vector3(f, camera, "view_up");
    s.camera.parallel = camera["parallel"] && camera["parallel"].as<bool>(false);
    s.camera.parallel_scale =
        f.positive(f.child(camera, "camera", "parallel_scale"), "camera.parallel_scale");
    s.camera.view_angle_deg =
        f.positive(f.child(camera, "camera", "view_angle_deg"), "camera.view_angle_deg");
  }
  if (const YAML::Node params = root["params"]) {
    s.params = ReconstructionParams::fromYamlNode(params, file.string());
  }
  if (const YAML::Node runs = root["runs"]) {
    if (!runs.IsSequence()) {
      f.fail(runs, "runs", "expected a list of runs");
    }
    for (std::size_t i = 0; i < runs.size(); ++i) {
      s.runs.push_back(runOf(f, runs[i], "runs[" + std::to_string(i) + "]", file.string()));
    }
  }
  return s;
}

bool looksLikeSessionFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head.find(std::string("format: ") + kFormat) != std::string::npos;
}

}  // namespace sonarcarve
