#include <gtest/gtest.h>

#include <thread>

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

// A superseded GUI job may still be in a loop when the next one starts: loops called from
// several threads at once each cover their own range exactly once, also in the background.
TEST(ThreadPool, LoopsFromSeveralThreadsDoNotMix) {
  ThreadPool pool(3);
  pool.setBackgroundPriority(true);
  constexpr std::size_t kCount = 5000;
  std::vector<std::vector<std::atomic<int>>> hits(4);
  for (auto& h : hits) {
    h = std::vector<std::atomic<int>>(kCount);
  }
  std::vector<std::thread> callers;
  for (std::size_t c = 0; c < hits.size(); ++c) {
    callers.emplace_back([&, c] {
      for (int repeat = 0; repeat < 20; ++repeat) {
        pool.parallelFor(kCount, 7, [&](std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i) {
            hits[c][i].fetch_add(1);
          }
        });
      }
    });
  }
  for (auto& t : callers) {
    t.join();
  }
  for (const auto& h : hits) {
    for (std::size_t i = 0; i < kCount; ++i) {
      ASSERT_EQ(h[i].load(), 20) << i;
    }
  }
}

}  // namespace
}  // namespace sonarcarve
