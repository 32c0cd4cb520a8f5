#include "common/serial_worker.h"

#include <utility>

#include "common/error.h"

namespace sonarcarve {

SerialWorker::SerialWorker(std::size_t depth) : depth_(depth) {
  if (depth_ < 1) {
    throw Error("serial worker", "depth", "expected at least 1 job allowed to wait");
  }
  thread_ = std::thread([this] { run(); });
}

SerialWorker::~SerialWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    jobs_.clear();
  }
  changed_.notify_all();
  thread_.join();
}

void SerialWorker::rethrowFailure() {
  if (failure_) {
    std::rethrow_exception(std::exchange(failure_, nullptr));
  }
}

void SerialWorker::submit(std::function<void()> job) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return jobs_.size() < depth_ || failure_; });
  rethrowFailure();
  jobs_.push_back(std::move(job));
  lock.unlock();
  changed_.notify_all();
}

void SerialWorker::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return (jobs_.empty() && !running_job_) || failure_; });
  rethrowFailure();
}

void SerialWorker::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
    if (stopping_) {
      return;
    }
    std::function<void()> job = std::move(jobs_.front());
    jobs_.pop_front();
    running_job_ = true;
    lock.unlock();
    std::exception_ptr failure;
    try {
      job();
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    running_job_ = false;
    if (failure) {
      failure_ = failure;
      jobs_.clear();
    }
    changed_.notify_all();
  }
}

}  // namespace sonarcarve
