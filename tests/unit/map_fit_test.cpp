// The model-based fit (fit/map_fit.h): a surface that carving left 2 voxels behind where the
// frames put it is moved back by fitting the band to the frames, and the fitted map explains
// the frames better than the start did.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "fit/fitted_surface.h"
#include "fit/map_fit.h"
#include "model/forward_model.h"
#include "support/model_scenes.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;
constexpr double kWallNorth = 2.0;  // the wall's face, facing the sonar (north)

SonarModel narrowSonar() {
  return SonarModel("fit", RangeBins{1.0, 0.02, 100}, BearingTable::uniform(degToRad(16), 16),
                    degToRad(20));
}

MapFitParams fitParams() {
  MapFitParams params;
  params.enabled = true;
  // 80 steps, as many as a run of 100 frames takes in its 3 passes of 4 frames a step.
  params.passes = 16;
  params.frames_per_step = 2;
  params.elevation_step_rad = degToRad(0.5);
  return params;
}

// The sonar facing north at several depths and headings, as a vertical pass would see a wall.
std::vector<MapFitFrame> views() {
  std::vector<MapFitFrame> frames;
  std::size_t index = 0;
  for (const double down : {-0.4, -0.2, 0.0, 0.2, 0.4}) {
    for (const double yaw_deg : {-4.0, 4.0}) {
      MapFitFrame frame;
      frame.index = index++;
      frame.T_world_sonar = Eigen::Translation3d(0.0, 0.0, down) *
                            Eigen::AngleAxisd(degToRad(yaw_deg), Eigen::Vector3d::UnitZ());
      frames.push_back(frame);
    }
  }
  return frames;
}

// The band box around the wall: north 1.8 to 2.3 m, east and down +-0.7 m.
Eigen::AlignedBox3d bandBox() {
  return {Eigen::Vector3d(1.8, -0.7, -0.9), Eigen::Vector3d(2.3, 0.7, 0.9)};
}

// The band as carving might leave it: opaque behind `face_north`, carved in front.
FitGrid carvedBand(double face_north) {
  FitGrid fit{BlockGrid(kVoxel), {}};
  Eigen::Vector3i lo;
  Eigen::Vector3i hi;
  fit.grid.voxelOf(bandBox().min(), lo);
  fit.grid.voxelOf(bandBox().max(), hi);
  for (int z = lo.z(); z <= hi.z(); ++z) {
    for (int y = lo.y(); y <= hi.y(); ++y) {
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Eigen::Vector3i voxel(x, y, z);
        const auto index = static_cast<std::size_t>(fit.grid.addVoxel(voxel));
        fit.in_band.resize(fit.grid.voxelCount(), 0);
        fit.in_band[index] = 1;
        fit.grid.logits()[index] =
            fit.grid.voxelCentre(voxel).x() > face_north ? kOccupiedLogit : kCarvedLogit;
        fit.grid.reflectance()[index] = 1.0f;
      }
    }
  }
  return fit;
}

double medianNorthError(const SurfacePoints& points) {
  std::vector<double> errors;
  for (const SurfacePoint& p : points) {
    errors.push_back(std::abs(p.position_m.x() - kWallNorth));
  }
  std::nth_element(errors.begin(), errors.begin() + static_cast<long>(errors.size() / 2),
                   errors.end());
  return errors[errors.size() / 2];
}

TEST(MapFit, MovesASurfaceCarvedTwoVoxelsDeepBackToWhereTheFramesPutIt) {
  const SonarModel sonar = narrowSonar();
  ThreadPool pool(2);
  const MapFitParams params = fitParams();
  ModelSettings settings;
  settings.elevation_step_rad = params.elevation_step_rad;
  settings.samples_per_bin = params.samples_per_bin;
  const ForwardModel model(sonar, settings, pool);

  BlockGrid truth(kVoxel);
  test::voxelise(truth, test::slab({kWallNorth, 0.0, 0.0}, -Eigen::Vector3d::UnitX(), 0.2),
                 bandBox(), 4.0, 2.0, 0.7f);
  const std::vector<MapFitFrame> frames = views();
  FrameView view{Eigen::Isometry3d::Identity(), declaredProfile(sonar), 3.0, {}};
  std::vector<cv::Mat> observed;
  for (const MapFitFrame& frame : frames) {
    view.T_world_sonar = frame.T_world_sonar;
    cv::Mat image;
    model.predict(truth, view).convertTo(image, CV_32F);
    observed.push_back(image);
  }
  const auto load = [&observed](std::size_t index) { return observed[index]; };

  FitGrid fit = carvedBand(kWallNorth + 2 * kVoxel);
  SilentProgress progress;
  const SurfacePoints start = fittedSurface(fit.grid, sonar, frames, params, 2, pool, progress);
  ASSERT_FALSE(start.empty());
  EXPECT_GT(medianNorthError(start), 1.5 * kVoxel);  // the start is as wrong as it was made

  const MapFitSummary summary = MapFit(sonar, params, pool).run(fit, frames, load, {}, progress);
  const SurfacePoints fitted = fittedSurface(fit.grid, sonar, frames, params, 2, pool, progress);
  ASSERT_FALSE(fitted.empty());
  // Within a range bin (2 cm, as fine as the frames tell range), from two and a half. (The
  // truth's own grid gives 0.5 cm by the same reading; the fit stops near 1.2 cm.)
  EXPECT_LT(medianNorthError(fitted), sonar.range().resolution_m);
  EXPECT_LT(summary.after.unexplained, 0.5 * summary.before.unexplained);
  EXPECT_LT(summary.after.nll_per_pixel, summary.before.nll_per_pixel);
}

}  // namespace
}  // namespace sonarcarve
