#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
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

struct ChunkFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs a loop of `count` one-item chunks whose body throws ChunkFailed where `fails` says;
// returns how many chunks ran and the message that reached the caller ("" if none did).
template <typename Fails>
std::pair<std::size_t, std::string> loopThatThrows(ThreadPool& pool, std::size_t count,
                                                   Fails fails) {
  std::atomic<std::size_t> ran{0};
  std::string message;
  try {
    pool.parallelFor(count, 1, [&](std::size_t begin, std::size_t) {
      ran.fetch_add(1);
      if (fails(begin)) {
        throw ChunkFailed("chunk " + std::to_string(begin) + " failed");
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    });
  } catch (const ChunkFailed& e) {
    message = e.what();
  }
  return {ran.load(), message};
}

TEST(ThreadPool, AThrowingChunkStopsTheLoopAndReachesTheCaller) {
  ThreadPool pool(4);
  constexpr std::size_t kCount = 10000;
  const auto [ran, message] = loopThatThrows(pool, kCount, [](std::size_t i) { return i == 10; });
  EXPECT_EQ(message, "chunk 10 failed");
  // Chunks 0 to 10, plus the few the other workers took before the throw (a generous bound:
  // the machine may be busy), not the whole loop.
  EXPECT_GE(ran, 11u);
  EXPECT_LT(ran, kCount / 10);
}

TEST(ThreadPool, RunsTheNextLoopNormallyAfterAThrow) {
  ThreadPool pool(3);
  EXPECT_EQ(loopThatThrows(pool, 500, [](std::size_t i) { return i == 0; }).second,
            "chunk 0 failed");
  std::vector<std::atomic<int>> hits(1000);
  pool.parallelFor(hits.size(), 3, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      hits[i].fetch_add(1);
    }
  });
  for (std::size_t i = 0; i < hits.size(); ++i) {
    ASSERT_EQ(hits[i].load(), 1) << i;
  }
}

TEST(ThreadPool, ManyThrowingChunksRethrowOneAndDoNotDeadlock) {
  ThreadPool pool(4);
  for (int repeat = 0; repeat < 50; ++repeat) {
    const auto [ran, message] = loopThatThrows(pool, 64, [](std::size_t) { return true; });
    EXPECT_LE(ran, 4u);  // each thread's first chunk throws; nothing is handed out after
    EXPECT_EQ(message.rfind("chunk ", 0), 0u) << message;
  }
}

TEST(ThreadPool, AThrowOnASingleThreadPoolReachesTheCaller) {
  ThreadPool pool(1);
  EXPECT_EQ(loopThatThrows(pool, 50, [](std::size_t i) { return i == 0; }).second,
            "chunk 0 failed");
}

}  // namespace
}  // namespace sonarcarve
