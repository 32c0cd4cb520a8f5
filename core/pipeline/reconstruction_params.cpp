#include "pipeline/reconstruction_params.h"

#include <filesystem>
#include <sstream>

#include "common/error.h"
#include "io/yaml_fields.h"

namespace sonarcarve {

namespace {

// `path` names the document in errors and anchors a relative noise model path.
ReconstructionParams paramsFromYaml(const YAML::Node& root, const YamlFields& f,
                                    const std::string& path) {
  ReconstructionParams p;
  if (root["engine"]) {
    p.engine = f.text(root["engine"], "engine");
    if (p.engine != "fast" && p.engine != "reference") {
      f.fail(root["engine"], "engine", "expected 'fast' or 'reference'");
    }
  }
  if (root["voxel_size_m"]) {
    p.carve.voxel_size_m = f.positive(root["voxel_size_m"], "voxel_size_m");
  }
  if (root["intensity_threshold"]) {
    p.carve.intensity_threshold = f.number(root["intensity_threshold"], "intensity_threshold");
  }
  if (root["elevation_step_deg"]) {
    p.carve.elevation_step_rad =
        degToRad(f.positive(root["elevation_step_deg"], "elevation_step_deg"));
  }
  if (root["vertical_aperture_deg"]) {
    p.vertical_aperture_rad =
        degToRad(f.number(root["vertical_aperture_deg"], "vertical_aperture_deg"));
  }
  if (root["range_min_m"]) {
    p.carve.range_min_m = f.number(root["range_min_m"], "range_min_m");
  }
  if (root["range_max_m"]) {
    p.carve.range_max_m = f.number(root["range_max_m"], "range_max_m");
  }
  if (const YAML::Node region = root["region"]) {
    const auto lo = f.numbers(f.child(region, "region", "min_m"), "region.min_m", 3);
    const auto hi = f.numbers(f.child(region, "region", "max_m"), "region.max_m", 3);
    p.carve.region = Eigen::AlignedBox3d(Eigen::Vector3d(lo[0], lo[1], lo[2]),
                                         Eigen::Vector3d(hi[0], hi[1], hi[2]));
    if (p.carve.region->isEmpty()) {
      f.fail(region, "region", "expected min_m below max_m on every axis");
    }
  }
  if (const YAML::Node frames = root["frames"]) {
    if (frames["first"]) {
      p.first_frame = static_cast<std::size_t>(f.number(frames["first"], "frames.first"));
    }
    if (frames["last"]) {
      p.last_frame = static_cast<long>(f.number(frames["last"], "frames.last"));
    }
    if (frames["stride"]) {
      p.stride = static_cast<std::size_t>(f.positiveInt(frames["stride"], "frames.stride"));
    }
  }
  if (root["occlusion_aware_carving"]) {
    bool value = true;
    if (!YAML::convert<bool>::decode(root["occlusion_aware_carving"], value)) {
      f.fail(root["occlusion_aware_carving"], "occlusion_aware_carving", "expected true or false");
    }
    p.occlusion_aware_carving = value;
  }
  if (const YAML::Node d = root["detector"]) {
    if (d["mode"]) {
      p.detector.mode = f.text(d["mode"], "detector.mode");
    }
    if (d["z"]) {
      p.detector.z = f.number(d["z"], "detector.z");
    }
    if (d["cfar_guard"]) {
      p.detector.cfar_guard = static_cast<int>(f.number(d["cfar_guard"], "detector.cfar_guard"));
    }
    if (d["cfar_train"]) {
      p.detector.cfar_train = f.positiveInt(d["cfar_train"], "detector.cfar_train");
    }
    if (d["cfar_pfa"]) {
      p.detector.cfar_pfa = f.positive(d["cfar_pfa"], "detector.cfar_pfa");
    }
    if (d["smoothing"]) {
      p.detector.smoothing = f.positiveInt(d["smoothing"], "detector.smoothing");
    }
    if (d["arc_prior"]) {
      p.carve.arc_prior = f.number(d["arc_prior"], "detector.arc_prior");
    }
    if (d["carve_log_odds"]) {
      p.carve.carve_log_odds = f.number(d["carve_log_odds"], "detector.carve_log_odds");
    }
  }
  if (const YAML::Node m = root["mesh"]) {
    if (m["enabled"]) {
      p.mesh_enabled = m["enabled"].as<bool>();
    }
    if (m["method"]) {
      p.mesh.method = f.text(m["method"], "mesh.method");
    }
    if (m["smoothing_iterations"]) {
      p.mesh.smoothing_iterations =
          static_cast<int>(f.number(m["smoothing_iterations"], "mesh.smoothing_iterations"));
    }
    if (m["occupancy_sigma_voxels"]) {
      p.mesh.occupancy_sigma_voxels =
          f.positive(m["occupancy_sigma_voxels"], "mesh.occupancy_sigma_voxels");
    }
    if (m["occupancy_iso"]) {
      p.mesh.occupancy_iso = f.positive(m["occupancy_iso"], "mesh.occupancy_iso");
    }
    if (m["decimate"]) {
      p.mesh.decimate = f.number(m["decimate"], "mesh.decimate");
    }
    if (m["min_fragment_triangles"]) {
      p.mesh.min_fragment_triangles = static_cast<std::size_t>(
          f.positiveInt(m["min_fragment_triangles"], "mesh.min_fragment_triangles"));
    }
  }
  if (root["noise_model"]) {
    std::filesystem::path model = f.text(root["noise_model"], "noise_model");
    if (model.is_relative()) {
      model = std::filesystem::path(path).parent_path() / model;
    }
    p.noise_model = model.string();
  }
  if (root["min_views"]) {
    p.min_views = static_cast<std::uint32_t>(f.positiveInt(root["min_views"], "min_views"));
  }
  try {
    p.validate();
  } catch (const Error& e) {
    throw Error(path, e.place(), e.message());
  }
  return p;
}

}  // namespace

ReconstructionParams ReconstructionParams::fromYamlFile(const std::string& path) {
  const YamlFields f(path);
  return paramsFromYaml(f.load(), f, path);
}

ReconstructionParams ReconstructionParams::fromYamlText(const std::string& text,
                                                        const std::string& source) {
  const YamlFields f(source);
  return paramsFromYaml(f.parse(text), f, source);
}

void ReconstructionParams::validate() const {
  if (engine != "fast" && engine != "reference") {
    throw Error("parameters", "engine", "expected 'fast' or 'reference'");
  }
  if (!(carve.voxel_size_m > 0.0)) {
    throw Error("parameters", "voxel_size_m", "expected a positive voxel size");
  }
  if (!(carve.elevation_step_rad > 0.0)) {
    throw Error("parameters", "elevation_step_deg", "expected a positive elevation step");
  }
  if (carve.range_min_m < 0.0 || carve.range_max_m < 0.0 ||
      (carve.range_max_m > 0.0 && carve.range_max_m <= carve.range_min_m)) {
    throw Error("parameters", "range_min_m/range_max_m", "expected 0 <= min < max (0 = sonar's)");
  }
  if (!(vertical_aperture_rad >= 0.0) || vertical_aperture_rad >= degToRad(180.0)) {
    throw Error("parameters", "vertical_aperture_deg",
                "expected 0 (the sonar's own) or an aperture below 180 degrees");
  }
  detector.validate();
  mesh.validate();
  if (detector.needsNoiseModel() && noise_model.empty()) {
    throw Error("parameters", "noise_model",
                "the " + detector.mode + " detector needs a noise model file");
  }
  if (stride < 1) {
    throw Error("parameters", "frames.stride", "expected a stride of at least 1");
  }
}

std::string ReconstructionParams::toYaml() const {
  std::ostringstream out;
  out << "# SonarCarve reconstruction parameters (docs: sonarcarve-cli reconstruct --help)\n"
      << "engine: " << engine << "\n"
      << "voxel_size_m: " << shortestNumber(carve.voxel_size_m) << "\n"
      << "intensity_threshold: " << shortestNumber(carve.intensity_threshold) << "\n"
      << "elevation_step_deg: " << shortestDegrees(carve.elevation_step_rad) << "\n"
      << "range_min_m: " << shortestNumber(carve.range_min_m) << "\n"
      << "range_max_m: " << shortestNumber(carve.range_max_m) << "\n"
      << "vertical_aperture_deg: " << shortestDegrees(vertical_aperture_rad) << "\n";
  if (carve.region) {
    const auto& lo = carve.region->min();
    const auto& hi = carve.region->max();
    out << "region:\n"
        << "  min_m: [" << shortestNumber(lo.x()) << ", " << shortestNumber(lo.y()) << ", "
        << shortestNumber(lo.z()) << "]\n"
        << "  max_m: [" << shortestNumber(hi.x()) << ", " << shortestNumber(hi.y()) << ", "
        << shortestNumber(hi.z()) << "]\n";
  }
  out << "frames: {first: " << first_frame << ", last: " << last_frame << ", stride: " << stride
      << "}\n"
      << "min_views: " << min_views << "\n"
      << "occlusion_aware_carving: " << (occlusion_aware_carving ? "true" : "false") << "\n"
      << "detector: {mode: " << detector.mode << ", z: " << shortestNumber(detector.z)
      << ", cfar_guard: " << detector.cfar_guard << ", cfar_train: " << detector.cfar_train
      << ", cfar_pfa: " << shortestNumber(detector.cfar_pfa)
      << ", arc_prior: " << shortestNumber(carve.arc_prior)
      << ", carve_log_odds: " << shortestNumber(carve.carve_log_odds)
      << ", smoothing: " << detector.smoothing << "}\n";
  out << "mesh: {enabled: " << (mesh_enabled ? "true" : "false") << ", method: " << mesh.method
      << ", smoothing_iterations: " << mesh.smoothing_iterations
      << ", decimate: " << shortestNumber(mesh.decimate)
      << ", min_fragment_triangles: " << mesh.min_fragment_triangles << "}\n";
  if (!noise_model.empty()) {
    out << "noise_model: " << std::filesystem::absolute(noise_model).string() << "\n";
  }
  return out.str();
}

}  // namespace sonarcarve
