// Speed of the forward model (model/forward_model.h) on one riser-like frame: 256 beams x 500
// range bins, a vertical riser of 0.3 m radius 4.5 m ahead voxelised at 2 cm in a band of
// +-15 voxels about its surface, elevations +-24 deg every 0.4 deg (docs/model.md).
#include <benchmark/benchmark.h>

#include "common/angles.h"
#include "model/forward_model.h"
#include "support/model_scenes.h"

namespace sonarcarve {
namespace {

struct RiserFrame {
  SonarModel sonar{"riser", RangeBins{0.0, 0.02, 500}, BearingTable::uniform(degToRad(130), 256),
                   degToRad(20)};
  ThreadPool pool{2};
  ModelSettings settings = [] {
    ModelSettings s;
    s.elevation_step_rad = degToRad(0.4);
    return s;
  }();
  ForwardModel model{sonar, settings, pool};
  BlockGrid grid{0.02};
  FrameView view{Eigen::Isometry3d::Identity(),
                 ElevationProfile::sincSquared(degToRad(20), degToRad(24), 9), 1.0,
                 std::vector<double>(500, 1e-3)};

  RiserFrame() {
    const Eigen::Vector3d axis_point(4.5, 0.0, 0.0);
    test::voxelise(
        grid, test::cylinder(axis_point, Eigen::Vector3d::UnitZ(), 0.3),
        Eigen::AlignedBox3d(Eigen::Vector3d(3.9, -0.6, -2.2), Eigen::Vector3d(5.1, 0.6, 2.2)), 15.0,
        3.0, 0.8f);
  }
};

void BM_ForwardModelPredict(benchmark::State& state) {
  const RiserFrame riser;
  for (auto _ : state) {
    benchmark::DoNotOptimize(riser.model.predict(riser.grid, riser.view));
  }
  state.counters["voxels"] = static_cast<double>(riser.grid.voxelCount());
}
BENCHMARK(BM_ForwardModelPredict)->Unit(benchmark::kMillisecond);

void BM_ForwardModelPredictAndGradient(benchmark::State& state) {
  const RiserFrame riser;
  cv::Mat dloss(riser.sonar.rows(), riser.sonar.cols(), CV_64F);
  cv::randu(dloss, -1.0, 1.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(riser.model.predict(riser.grid, riser.view));
    benchmark::DoNotOptimize(riser.model.gradient(riser.grid, riser.view, dloss));
  }
}
BENCHMARK(BM_ForwardModelPredictAndGradient)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sonarcarve
