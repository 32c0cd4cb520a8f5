// Speed of the sensor model and the mission reader. Run: build/release/tests/sonarcarve_bench
#include <benchmark/benchmark.h>

#include <random>

#include "common/angles.h"
#include "io/mission/mission.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {
namespace {

SonarModel paperSonar() {
  return SonarModel("paper", RangeBins{0.0, 0.02, 500}, BearingTable::uniform(degToRad(130), 650),
                    degToRad(20));
}

void BM_PixelOfPoint(benchmark::State& state) {
  const SonarModel sonar = paperSonar();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-6.0, 6.0);
  std::vector<Eigen::Vector3d> points(4096);
  for (auto& p : points) {
    p = {std::abs(u(rng)) + 0.5, u(rng), 0.2 * u(rng)};
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sonar.pixelOf(points[i++ & 4095]));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PixelOfPoint);

void BM_LoadExampleFrame(benchmark::State& state) {
  const Mission mission =
      readMission(std::filesystem::path(SONARCARVE_RESOURCE_DIR) / "example_mission");
  for (auto _ : state) {
    benchmark::DoNotOptimize(loadFrame(mission, 0));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LoadExampleFrame);

}  // namespace
}  // namespace sonarcarve

BENCHMARK_MAIN();
