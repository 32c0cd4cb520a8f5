#include "pipeline/report.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "common/angles.h"
#include "eval/evaluator.h"
#include "geometry/scene_io.h"
#include "io/files/json_text.h"
#include "io/frame_source.h"
#include "pipeline/keep_level.h"
#include "pipeline/param_schema.h"
#include "pipeline/refined_track.h"

namespace sonarcarve {
namespace {

nlohmann::json sonarReport(const SonarModel& sonar) {
  return {{"id", sonar.id()},
          {"range_min_m", sonar.range().min_m},
          {"range_max_m", sonar.range().maxRange()},
          {"range_bins", sonar.rows()},
          {"beams", sonar.cols()},
          {"horizontal_aperture_deg", radToDeg(sonar.bearings().fieldOfView())},
          {"vertical_aperture_deg", radToDeg(sonar.verticalAperture())}};
}

nlohmann::json surveyReport(const SurveyPlan& survey) {
  return {{"track_length_m", survey.track_length_m},
          {"depth_min_m", survey.depth_min_m},
          {"depth_max_m", survey.depth_max_m},
          {"coverage_area_m2", survey.coverage_area_m2}};
}

// Every parameter as params.yaml writes it, with its unit, its help line and whether the run
// changed it from its default.
nlohmann::json parametersReport(const ReconstructionParams& params) {
  nlohmann::json list = nlohmann::json::array();
  for (const ParamSpec& spec : paramSchema()) {
    const std::string value = formatParam(spec, spec.get(params));
    list.push_back({{"key", spec.key},
                    {"value", value},
                    {"unit", spec.unit},
                    {"help", spec.help},
                    {"changed", value != formatParam(spec, spec.defaultValue())}});
  }
  return list;
}

}  // namespace

std::string reconstructionReport(const Mission& mission, const SonarModel& sonar,
                                 const ReconstructionParams& params,
                                 const ReconstructionResult& result, const SurveyPlan& survey,
                                 ThreadPool& pool) {
  const Eigen::Vector3d& origin = mission.origin_ned_m;
  nlohmann::json report = {{"mission", mission.folder.string()},
                           {"mission_name", mission.name},
                           {"sonar", sonarReport(sonar)},
                           {"frames_in_mission", mission.frames.size()},
                           {"survey", surveyReport(survey)},
                           {"origin_ned_m", {origin.x(), origin.y(), origin.z()}},
                           {"engine", std::string(toString(params.engine))},
                           {"detector", result.detector},
                           {"smoothing", params.detector.smoothing},
                           {"z", params.detector.z},
                           {"frames_used", result.frames_used},
                           {"frames_skipped", result.skipped.size()},
                           {"cancelled", result.cancelled},
                           {"occupied_voxels", result.occupied_voxels},
                           {"surface_points", result.surface.size()},
                           {"mesh_vertices", result.mesh.vertices.size()},
                           {"mesh_triangles", result.mesh.triangles.size()},
                           {"map_megabytes", static_cast<double>(result.map_bytes) / 1e6},
                           {"carve_ms_per_frame_median", result.carve_ms_median},
                           {"occlusion_ms_per_frame", result.occlusion_ms_per_frame},
                           {"total_s", result.total_s}};
  if (!mission.crs.empty()) {  // absent for NED navigation without a CRS, as before
    report["crs"] = mission.crs;
  }
  nlohmann::json choices = nlohmann::json::array();
  for (const RunChoice& c : result.choices) {
    choices.push_back({{"name", c.name},
                       {"value", c.value},
                       {"reason", c.reason},
                       {"detail", c.detail},
                       {"action", c.action},
                       {"warning", c.warning}});
  }
  report["choices"] = std::move(choices);
  report["parameters"] = parametersReport(params);
  if (result.evicted) {
    report["eviction"] = {{"pages_freed_early", result.pages_freed_early},
                          {"pages_set_aside", result.pages_set_aside},
                          {"set_aside_file_bytes_most", result.aside_file_bytes},
                          {"temporary_file_problem", result.temporary_file_problem}};
  }
  if (params.carve.beam_aware && result.keep_level.frames > 0) {
    report["beam_aware_carving"] = {{"bright_returns", result.keep_level.bright_returns},
                                    {"dynamic_range_db", params.carve.dynamic_range_db},
                                    {"keep_level", result.keep_level.level},
                                    {"raised_to_a_count", result.keep_level.raised_to_a_count},
                                    {"frames_measured", result.keep_level.frames}};
  }
  if (!result.refinement.empty()) {
    report["pose_refinement"] = poseRefinementReport(mission, result.refinement);
  }
  if (mission.source) {
    report["source"] = mission.source->kind();
  }
  if (!mission.warnings.empty()) {
    report["warnings"] = mission.warnings;
  }
  std::error_code ec;
  const auto truth = mission.folder / "ground_truth.ply";
  if (std::filesystem::exists(truth, ec) && !result.surface.empty()) {
    const std::vector<Eigen::Vector3f> points = positionsOf(result.surface);
    // Ground truth read once, for the points and for the mesh.
    // The ground truth is in the world frame, as the navigation was: moved to the origin too.
    const Scene truth_mesh = loadSceneMesh(truth, kDefaultReflectivity, origin);
    const auto visible_file = mission.folder / "visible_points.ply";
    const std::vector<Eigen::Vector3f> visible = std::filesystem::exists(visible_file, ec)
                                                     ? readPointsPly(visible_file, origin)
                                                     : std::vector<Eigen::Vector3f>{};
    report["evaluation"] =
        nlohmann::json::parse(evaluate(points, truth_mesh, visible, pool).toJson());
    if (!result.mesh.vertices.empty()) {
      // Mesh accuracy: distance from the mesh vertices to the ground truth.
      report["mesh_evaluation"] =
          nlohmann::json::parse(evaluate(result.mesh.vertices, truth_mesh, visible, pool).toJson());
    }
  }
  return jsonText(report) + "\n";
}

}  // namespace sonarcarve
