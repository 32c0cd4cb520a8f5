#include "common/thread_pool.h"

#include <algorithm>
#include <utility>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace {

constexpr int kBackgroundNice = 10;

// On Linux the nice value is per thread: PRIO_PROCESS with the thread id changes only it.
void setThisThreadNice(int nice) {
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  (void)setpriority(PRIO_PROCESS, tid, nice);  // best effort: raising may be refused
}

}  // namespace

namespace sonarcarve {

void lowerThisThreadPriority() {
  setThisThreadNice(kBackgroundNice);
}

void ThreadPool::setBackgroundPriority(bool background) {
  std::lock_guard lock(mutex_);
  background_ = background;
}

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
    try {
      (*body_)(begin, end);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) {
        error_ = std::current_exception();
      }
      next_ = count_;  // hand out no further chunks
      return;
    }
  }
}

void ThreadPool::workerLoop() {
  std::size_t seen_generation = 0;
  bool niced = false;
  while (true) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen_generation; });
      if (stopping_) {
        return;
      }
      seen_generation = generation_;
      ++busy_;
      if (background_ != niced) {
        niced = background_;
        setThisThreadNice(niced ? kBackgroundNice : 0);
      }
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
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  runChunks();
  std::exception_ptr error;
  {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return busy_ == 0 && next_ >= count_; });
    body_ = nullptr;
    error = std::exchange(error_, nullptr);
  }
  if (error) {
    std::rethrow_exception(error);
  }
}

}  // namespace sonarcarve
