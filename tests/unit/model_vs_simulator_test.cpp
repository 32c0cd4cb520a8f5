// The forward model (model/forward_model.h) of a voxelised scene against the simulator's
// noise-free frame of the same scene and pose: the same energy per range bin.
#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "model/forward_model.h"
#include "sim/ray_caster.h"
#include "sim/scene_shapes.h"
#include "sim/sonar_simulator.h"
#include "support/model_scenes.h"
#include "support/sim_scenes.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;

// Energy of each range bin, summed over the beams.
std::vector<double> rangeProfile(const cv::Mat& frame) {
  std::vector<double> profile;
  for (int row = 0; row < frame.rows; ++row) {
    profile.push_back(cv::sum(frame.row(row))[0]);
  }
  return profile;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const auto n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ma += a[i] / n;
    mb += b[i] / n;
  }
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

TEST(ModelVsSimulator, WallAndCylinderGiveTheSimulatorsRangeProfile) {
  // A wall facing the sonar 4 m ahead and a vertical cylinder in front of it, reflectivity 0.8.
  const Eigen::Vector3d wall_centre(4.0, 0.0, 0.0);
  const Eigen::Vector3d wall_normal(-1.0, 0.0, 0.0);
  const Eigen::Vector3d axis_point(3.0, 0.5, 0.0);
  const double radius = 0.3;
  Scene scene = test::plate(wall_centre, wall_normal, 8.0, 0.8f);
  scene.append(tubeShape(axis_point + Eigen::Vector3d(0, 0, -4),
                         axis_point + Eigen::Vector3d(0, 0, 4), radius, 128, 0.8f));
  BlockGrid grid(kVoxel);
  const double band = 4.0;   // voxels each side of the surface
  const double slope = 3.0;  // logit per voxel across the surface
  test::voxelise(
      grid, test::slab(wall_centre, wall_normal, 0.5),
      Eigen::AlignedBox3d(Eigen::Vector3d(3.85, -3.0, -3.2), Eigen::Vector3d(4.15, 3.0, 3.2)), band,
      slope, 0.8f);
  test::voxelise(
      grid, test::cylinder(axis_point, Eigen::Vector3d::UnitZ(), radius),
      Eigen::AlignedBox3d(Eigen::Vector3d(2.6, 0.1, -3.2), Eigen::Vector3d(3.4, 0.9, 3.2)), band,
      slope, 0.8f);

  const SonarModel sonar("compare", RangeBins{1.0, 0.02, 200},
                         BearingTable::uniform(degToRad(60), 64), degToRad(20));
  ThreadPool pool(2);
  ImagingSettings imaging;
  imaging.gain = 1.0;
  const RayCaster caster(scene);
  const SonarSimulator simulator(caster, sonar, imaging, pool);
  // Off the origin, yawed and pitched: the two must agree on the frames' conventions too.
  Eigen::Isometry3d T_world_sonar = Eigen::Isometry3d::Identity();
  T_world_sonar.translate(Eigen::Vector3d(0.1, -0.2, 0.15));
  T_world_sonar.rotate(Eigen::AngleAxisd(degToRad(4), Eigen::Vector3d::UnitZ()));
  T_world_sonar.rotate(Eigen::AngleAxisd(degToRad(-6), Eigen::Vector3d::UnitY()));
  const cv::Mat simulated = simulator.render(T_world_sonar);

  ModelSettings settings;
  const ForwardModel model(sonar, settings, pool);
  const FrameView view{
      T_world_sonar,
      ElevationProfile::sincSquared(sonar.verticalAperture(), simulator.tracedElevation(), 12),
      1.0,
      {}};
  const cv::Mat predicted = model.predict(grid, view);

  const std::vector<double> sim_profile = rangeProfile(simulated);
  const std::vector<double> model_profile = rangeProfile(predicted);
  const double r = correlation(sim_profile, model_profile);
  const auto peak = [](const std::vector<double>& p) {
    return static_cast<int>(std::max_element(p.begin(), p.end()) - p.begin());
  };
  const double total_ratio = cv::sum(predicted)[0] / cv::sum(simulated)[0];
  std::printf(
      "range profile correlation %.4f, peak bins %d (simulator) %d (model), energy "
      "model / simulator %.3f\n",
      r, peak(sim_profile), peak(model_profile), total_ratio);
  EXPECT_GT(r, 0.9);
  // The peak: the model's surface is the logit's ramp across the voxels, alpha = 1/2 on it, so
  // its returns sit within a voxel of the true surface; each frame puts a return into the bin
  // that contains its range, a bin's width from the other's at most. Hence |model - simulator|
  // <= one voxel + one range bin.
  // The energy: both normalise a sample by dtheta / A and weigh it by p(theta) cos(theta) and
  // cos(incidence). What differs is second order: the model's normal from central differences
  // of a ramped logit (a few degrees off the cylinder's: cos 5 deg = 0.996), its rays cut below
  // alpha = 1e-3 and transmittance 1e-4, one ray at each beam's centre against the simulator's
  // two sub-rays and its leakage of the outer beams' side lobes beyond the fan (the 64 beams'
  // two outer ones hold 3 % of the energy). 5 % bounds them.
  EXPECT_NEAR(total_ratio, 1.0, 0.05);
  const double tolerance_bins = (kVoxel + sonar.range().resolution_m) / sonar.range().resolution_m;
  EXPECT_LE(std::abs(peak(sim_profile) - peak(model_profile)), tolerance_bins);
}

}  // namespace
}  // namespace sonarcarve
