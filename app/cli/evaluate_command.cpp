// `sonarcarve-cli evaluate --reference MESH --reconstruction POINTS.ply`: accuracy figures.
#include <iostream>

#include "cli/commands.h"
#include "eval/evaluator.h"
#include "geometry/scene_io.h"
#include "io/mesh/point_cloud_ply.h"
#include "occlusion/surface_points.h"

namespace sonarcarve::cli {

void addEvaluateCommand(CLI::App& app, ThreadPool& pool, int& exit_code) {
  auto* cmd = app.add_subcommand("evaluate", "Compare a reconstruction with a ground-truth mesh");
  struct Options {
    std::string reference, reconstruction, visible, errors;
    double tau = 0.05;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--reference", o->reference, "Ground-truth mesh (PLY, STL, OBJ)")->required();
  cmd->add_option(
         "--reconstruction", o->reconstruction,
         "Reconstructed points (PLY; local to the mission origin of its comment "
         "origin_ned_m, if any, which is subtracted from the reference and visible points)")
      ->required();
  cmd->add_option("--visible", o->visible,
                  "Surface points the sonar saw (PLY); completeness is measured on them");
  cmd->add_option("--tau", o->tau, "Distance threshold of precision and completeness, m")
      ->capture_default_str();
  cmd->add_option("--errors", o->errors, "Write the points with their error (PLY, 'error_m')");
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o, &pool, &exit_code] {
    const std::vector<Eigen::Vector3f> points =
        positionsOf(readSurfacePointsPly(o->reconstruction));
    // Points local to a mission origin (their PLY comment) meet a reference in the world frame
    // in that local frame: the reference minus the origin, in double.
    const Eigen::Vector3d origin = plyOrigin(o->reconstruction);
    const EvaluationResult r = evaluate(
        points, loadSceneMesh(o->reference, kDefaultReflectivity, origin),
        o->visible.empty() ? std::vector<Eigen::Vector3f>{} : readPointsPly(o->visible, origin),
        pool, o->tau);
    if (!o->errors.empty()) {
      writePointsPly(points, o->errors, r.point_errors_m, "error_m");
    }
    if (o->json) {
      std::cout << r.toJson() << "\n";
    } else {
      std::printf("points %zu, reference points %zu\n", r.reconstructed_points, r.reference_points);
      std::printf("accuracy  mean %.4f m  median %.4f m  p90 %.4f m\n", r.accuracy_mean_m,
                  r.accuracy_median_m, r.accuracy_p90_m);
      std::printf("at tau %.3f m: precision %.3f  completeness %.3f  F-score %.3f\n", r.tau_m,
                  r.precision, r.completeness, r.fscore);
      std::printf(
          "completeness by orientation: horizontal faces %.3f (%zu points), the rest "
          "%.3f (%zu points)\n",
          r.completeness_horizontal, r.reference_points_horizontal, r.completeness_other,
          r.reference_points_other);
      std::printf("chamfer %.4f m, points farther than 10 cm: %zu\n", r.chamfer_m,
                  r.floating_points);
    }
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
