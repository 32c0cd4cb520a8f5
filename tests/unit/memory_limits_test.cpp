// Memory-based limits (docs/reliability.md, "Limits"): the memory available is read from the
// kernel, a container's limit or the user's cap, and a reconstruction that needs more than its
// budget (memory_budget.h) is refused before allocation, naming the parameter that takes most.
#include <gtest/gtest.h>

#include "common/available_memory.h"
#include "common/error.h"
#include "pipeline/size_limits.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr std::uint64_t kMiB = 1024 * 1024;
const char* const kMeminfo = "MemTotal:  8000000 kB\nMemFree: 100 kB\nMemAvailable:   2048 kB\n";

TEST(AvailableMemory, TheSmallestKnownFigureWithItsSource) {
  auto m = availableMemoryFrom(kMeminfo, "", "", "");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->bytes, 2048u * 1024);
  EXPECT_EQ(m->source, "MemAvailable in /proc/meminfo");
  m = availableMemoryFrom(kMeminfo, "1500000", "1000000", "");
  EXPECT_EQ(m->bytes, 500000u);
  EXPECT_EQ(m->source, "the container's memory limit (cgroup memory.max)");
  m = availableMemoryFrom(kMeminfo, "max", "1000000", "1");
  EXPECT_EQ(m->bytes, kMiB);
  EXPECT_EQ(m->source, "SONARCARVE_MEMORY_LIMIT_MB");
  m = availableMemoryFrom(kMeminfo, "1000", "2000", "");  // over its limit already
  EXPECT_EQ(m->bytes, 0u);
  EXPECT_FALSE(availableMemoryFrom("", "max", "12", "not a number"));
  EXPECT_TRUE(availableMemory());  // /proc/meminfo exists on Linux
}

TEST(MemoryEstimate, GrowsWithTheVoxelCountTheThreadsAndTheElevationSteps) {
  const SonarModel sonar = test::paperSonar();
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(10, 10, 10));
  CarveParams carve;
  carve.voxel_size_m = 0.02;
  const MemoryEstimate coarse = estimateMemory(box, sonar, carve, 1);
  // ceil(10 m / 16 cm) + 1 = 64 blocks a side: 9 bytes each, and two layers of 64^2 of 2 KiB.
  EXPECT_DOUBLE_EQ(coarse.map, 64.0 * 64 * 64 * 9 + 2.0 * 64 * 64 * 2048);
  EXPECT_DOUBLE_EQ(coarse.frames, 2.0 * sonar.rows() * sonar.cols() * 4);
  carve.voxel_size_m = 0.01;
  EXPECT_GT(estimateMemory(box, sonar, carve, 1).map, 4 * coarse.map);
  EXPECT_DOUBLE_EQ(estimateMemory(box, sonar, carve, 4).frames, 4 * coarse.frames);
  carve.elevation_step_rad /= 10;
  EXPECT_NEAR(estimateMemory(box, sonar, carve, 1).occlusion, 10 * coarse.occlusion,
              coarse.occlusion * 0.1);
}

TEST(MemoryLimits, RefusedNamingTheParameterThatTakesMost) {
  CarveParams carve;
  MemoryEstimate e;
  e.map = 900.0 * kMiB;
  e.frames = 10.0 * kMiB;
  e.occlusion = 20.0 * kMiB;
  const MemoryBudget little{500 * kMiB, "80 % of 625 MiB available, SONARCARVE_MEMORY_LIMIT_MB"};
  test::expectError(
      [&] { requireMemory(e, carve, little); },
      {"parameters: voxel_size_m: the reconstruction needs at least 930 MiB", "map 900 MiB",
       "but the memory budget is 500 MiB (80 % of 625 MiB available, "
       "SONARCARVE_MEMORY_LIMIT_MB)",
       "use a larger voxel size or a smaller region, or set memory_budget_mb"});
  e.occlusion = 2000.0 * kMiB;
  test::expectError([&] { requireMemory(e, carve, little); },
                    {"parameters: elevation_step_deg:", "use a larger elevation step"});
  e.frames = 3000.0 * kMiB;
  test::expectError([&] { requireMemory(e, carve, little); }, {"parameters: frames:"});
  EXPECT_NO_THROW(requireMemory(e, carve, std::nullopt));
  EXPECT_NO_THROW(requireMemory(e, carve, MemoryBudget{6000 * kMiB, "test"}));
}

}  // namespace
}  // namespace sonarcarve
