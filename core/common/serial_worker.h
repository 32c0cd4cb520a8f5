// SerialWorker: one background thread that runs jobs in the order they were submitted, so that
// a producer can go on to its next item while the last one is finished (the simulator renders a
// frame while the one before is noised, encoded and written). At most `depth` jobs wait; submit()
// blocks beyond that, which bounds the memory the queued jobs hold. When a job throws, the jobs
// queued after it are dropped and its exception is rethrown by the next submit() or finish().
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace sonarcarve {

class SerialWorker {
 public:
  /// `depth` >= 1: how many jobs may wait (besides the one running).
  explicit SerialWorker(std::size_t depth);
  /// Drops the jobs still waiting, lets the running one end, and joins the thread.
  ~SerialWorker();
  SerialWorker(const SerialWorker&) = delete;
  SerialWorker& operator=(const SerialWorker&) = delete;

  /// Queues `job`, waiting while `depth` jobs wait; rethrows a failed job's exception.
  void submit(std::function<void()> job);
  /// Waits until every job submitted has run; rethrows a failed job's exception.
  void finish();

 private:
  void run();
  void rethrowFailure();  // with `mutex_` held

  const std::size_t depth_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> jobs_;
  bool running_job_ = false;
  bool stopping_ = false;
  std::exception_ptr failure_;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace sonarcarve
