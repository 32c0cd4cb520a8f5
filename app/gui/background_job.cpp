#include "background_job.h"

#include <QMetaObject>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace sonarcarve::gui {

using Clock = std::chrono::steady_clock;

// What a job's worker and the GUI thread share.
struct JobContext::State {
  int id = 0;
  std::atomic<bool> cancel{false};
  std::atomic<bool> dropped{false};   // superseded or discarded: nothing of it is delivered
  std::atomic<bool> finished{false};  // the worker has posted its outcome and is returning
  std::mutex mutex;
  std::condition_variable resume;
  bool paused = false;  // under `mutex`
  BackgroundJob::ProgressHandler progress;
  std::mutex report_mutex;
  Clock::time_point last_report{};  // under `report_mutex`, as is last_stage
  std::string last_stage;

  // Sets the cancel flag and releases a paused worker.
  void stop() {
    {
      std::lock_guard lock(mutex);
      cancel = true;
      paused = false;
    }
    resume.notify_all();
  }
};

struct BackgroundJob::Thread {
  std::shared_ptr<JobContext::State> state;
  std::thread thread;
};

JobContext::JobContext(BackgroundJob& owner, std::shared_ptr<State> state)
    : owner_(owner), state_(std::move(state)) {}

bool JobContext::cancelled() const {
  std::unique_lock lock(state_->mutex);
  state_->resume.wait(lock, [&] { return !state_->paused || state_->cancel.load(); });
  return state_->cancel.load();
}

void JobContext::report(const std::string& stage, std::size_t done, std::size_t total) {
  if (!state_->progress) {
    return;
  }
  const auto now = Clock::now();
  std::lock_guard lock(state_->report_mutex);
  if (done == total || stage != state_->last_stage ||
      now - state_->last_report >= std::chrono::milliseconds(BackgroundJob::kProgressInterval_ms)) {
    state_->last_report = now;
    state_->last_stage = stage;
    owner_.post(
        state_->id,
        [progress = state_->progress, stage = QString::fromStdString(stage), done, total] {
          progress(stage, done, total);
        },
        false);
  }
}

void JobContext::post(std::function<void()> deliver) {
  owner_.post(state_->id, std::move(deliver), false);
}

BackgroundJob::BackgroundJob(QObject* parent) : QObject(parent) {}

BackgroundJob::~BackgroundJob() {
  for (Thread& t : threads_) {
    t.state->dropped = true;
    t.state->stop();
  }
  for (Thread& t : threads_) {
    t.thread.join();
  }
}

int BackgroundJob::startJob(std::function<Deliver(JobContext&)> run, ErrorHandler failed,
                            ProgressHandler progress) {
  discard();
  joinFinishedThreads();
  auto state = std::make_shared<JobContext::State>();
  state->id = next_id_++;
  state->progress = std::move(progress);
  current_ = state;
  current_id_ = state->id;
  running_ = true;
  std::thread worker([this, state, run = std::move(run), failed = std::move(failed)] {
    if (state->dropped) {
      state->finished = true;  // superseded before it began (a burst of frame requests)
      return;
    }
    JobContext context(*this, state);
    Deliver outcome;
    try {
      outcome = run(context);
    } catch (const Cancelled& e) {
      outcome = [failed, message = QString::fromUtf8(e.what())] { failed({message, true}); };
    } catch (const std::exception& e) {
      outcome = [failed, message = QString::fromStdString(e.what())] { failed({message, false}); };
    } catch (...) {
      outcome = [failed] { failed({QStringLiteral("unknown error"), false}); };
    }
    if (state->dropped) {
      // Superseded: nothing of it arrives, and what its outcome holds (a cancelled run's map)
      // is freed here rather than on the GUI thread.
      outcome = nullptr;
    } else {
      post(state->id, std::move(outcome), true);
    }
    state->finished = true;
  });
  threads_.push_back({state, std::move(worker)});
  return current_id_;
}

void BackgroundJob::post(int job, Deliver deliver, bool outcome) {
  // Called from a worker. Qt drops the call if this object is gone by then (it is the call's
  // context), and the destructor joins every worker before that.
  QMetaObject::invokeMethod(
      this,
      [this, job, outcome, deliver = std::move(deliver)] {
        if (current_id_ != job) {
          return;  // superseded or discarded
        }
        if (outcome) {
          running_ = false;
        }
        deliver();
      },
      Qt::QueuedConnection);
}

void BackgroundJob::cancel() {
  if (current_) {
    current_->stop();
  }
}

void BackgroundJob::discard() {
  if (current_) {
    current_->dropped = true;
  }
  cancel();
  current_.reset();
  current_id_ = 0;
  running_ = false;
}

void BackgroundJob::setPaused(bool paused) {
  if (!current_) {
    return;
  }
  {
    std::lock_guard lock(current_->mutex);
    current_->paused = paused;
  }
  current_->resume.notify_all();
}

bool BackgroundJob::paused() const {
  if (!current_) {
    return false;
  }
  std::lock_guard lock(current_->mutex);
  return current_->paused;
}

void BackgroundJob::joinFinishedThreads() {
  for (auto it = threads_.begin(); it != threads_.end();) {
    if (it->state->finished) {
      it->thread.join();  // it has posted its outcome and is returning: no wait
      it = threads_.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace sonarcarve::gui
