#include "common/thread_pool.h"

#include <algorithm>

namespace sonarcarve {

ThreadPool::ThreadPool(unsigned threads) {
  if (threads == 0) {
    threads = std::max(1u, std::thread::hardware_concurrency());
  }
  for (unsigned i = 1; i < threads; ++i) {
    workers_.emplace_back([this] { workerLoop(); });
  }
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& w : workers_) {
    w.join();
  }
}

ThreadPool& ThreadPool::shared() {
  static ThreadPool pool;
  return pool;
}

void ThreadPool::runChunks() {
  while (true) {
    std::size_t begin = 0;
    std::size_t end = 0;
    {
      std::lock_guard lock(mutex_);
      if (next_ >= count_) {
        return;
      }
      begin = next_;
      end = std::min(count_, begin + grain_);
      next_ = end;
    }
    (*body_)(begin, end);
  }
}

void ThreadPool::workerLoop() {
  std::size_t seen_generation = 0;
  while (true) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen_generation; });
      if (stopping_) {
        return;
      }
      seen_generation = generation_;
      ++busy_;
    }
    runChunks();
    {
      std::lock_guard lock(mutex_);
      --busy_;
    }
    done_.notify_all();
  }
}

void ThreadPool::parallelFor(std::size_t count, std::size_t grain,
                             const std::function<void(std::size_t, std::size_t)>& body) {
  if (count == 0) {
    return;
  }
  if (workers_.empty() || count <= grain) {
    body(0, count);
    return;
  }
  const std::lock_guard call_lock(call_mutex_);
  {
    std::lock_guard lock(mutex_);
    body_ = &body;
    count_ = count;
    grain_ = std::max<std::size_t>(1, grain);
    next_ = 0;
    ++generation_;
  }
  wake_.notify_all();
  runChunks();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return busy_ == 0 && next_ >= count_; });
  body_ = nullptr;
}

}  // namespace sonarcarve
