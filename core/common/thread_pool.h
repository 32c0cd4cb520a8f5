// ThreadPool: a fixed set of worker threads that run a parallel loop and park cheaply between
// loops (a condition variable, not OpenMP's spin-then-sleep, which costs milliseconds to
// wake). One parallelFor runs at a time per pool; it is not reentrant.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sonarcarve {

/// Nice 10 for the calling thread only (Linux threads each have their own nice value); a
/// no-op where that is not possible.
void lowerThisThreadPriority();

class ThreadPool {
 public:
  /// `threads` workers in all, the calling thread included; 0 means hardware concurrency.
  explicit ThreadPool(unsigned threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// Calls body(begin, end) on disjoint chunks covering [0, count), in parallel, and returns
  /// when all are done. Chunks are handed out dynamically, `grain` items at a time.
  /// If a chunk throws, no further chunks are handed out, the running ones finish, and the
  /// first exception is rethrown here once every worker is idle; the pool stays usable.
  void parallelFor(std::size_t count, std::size_t grain,
                   const std::function<void(std::size_t, std::size_t)>& body);

  /// Runs the workers at a lower scheduling priority (Linux nice 10) from their next loop
  /// on, so that an interactive thread (the GUI's, and the software OpenGL renderer's) gets
  /// the CPU first while they carve. The calling thread is not changed.
  void setBackgroundPriority(bool background);

 private:
  void workerLoop();
  void runChunks();

  std::vector<std::thread> workers_;
  std::mutex call_mutex_;  // held for a whole parallelFor: one loop at a time
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void(std::size_t, std::size_t)>* body_ = nullptr;
  std::size_t count_ = 0;
  std::size_t grain_ = 1;
  std::size_t next_ = 0;
  std::exception_ptr error_;  // the loop's first exception
  std::size_t generation_ = 0;
  unsigned busy_ = 0;
  bool stopping_ = false;
  bool background_ = false;
};

}  // namespace sonarcarve
