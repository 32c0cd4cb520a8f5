#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "common/thread_pool.h"

namespace sonarcarve {
namespace {

TEST(ThreadPool, EveryIndexRunsExactlyOnceAcrossManyLoops) {
  ThreadPool pool(4);
  for (std::size_t count : {0u, 1u, 7u, 1000u, 4097u}) {
    for (int repeat = 0; repeat < 50; ++repeat) {
      std::vector<std::atomic<int>> hits(count);
      pool.parallelFor(count, 13, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
          hits[i].fetch_add(1);
        }
      });
      for (std::size_t i = 0; i < count; ++i) {
        ASSERT_EQ(hits[i].load(), 1) << "count " << count << " index " << i;
      }
    }
  }
}

TEST(ThreadPool, SingleThreadPoolRunsOnTheCaller) {
  ThreadPool pool(1);
  EXPECT_EQ(pool.size(), 1u);
  std::size_t total = 0;
  pool.parallelFor(100, 10, [&](std::size_t b, std::size_t e) { total += e - b; });
  EXPECT_EQ(total, 100u);
}

}  // namespace
}  // namespace sonarcarve
