// BackgroundJob: runs one kind of long work of the GUI (loading a frame, a noise model,
// importing a log, a reconstruction) on a worker thread, one job at a time. Starting a job
// supersedes the earlier one of the same BackgroundJob: it is asked to stop and whatever it
// delivers later is dropped. The task gets a JobContext, the engine's Progress (cancellation,
// pause, progress reports at most every kProgressInterval_ms) with post() for results along
// the way. Its result, or its error, reaches the GUI thread as a value through a queued call.
// The GUI thread never waits on a worker, except in the destructor, which cancels every job
// and joins its thread. Use it from the GUI thread only.
#pragma once

#include <QObject>
#include <QString>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <type_traits>

#include "common/progress.h"

namespace sonarcarve::gui {

/// Why a job failed: the exception's message; `cancelled` if it was sonarcarve::Cancelled.
struct JobError {
  QString message;
  bool cancelled = false;
};

class BackgroundJob;

/// What a running task sees; thread safe.
class JobContext : public Progress {
 public:
  /// True once the job is cancelled or superseded; while it is paused, holds the worker here.
  bool cancelled() const override;
  /// Reaches the job's progress handler on the GUI thread, at most every kProgressInterval_ms
  /// unless the stage changes or it is done.
  void report(const std::string& stage, std::size_t done, std::size_t total) override;
  /// Runs `deliver` on the GUI thread, unless the job has been superseded or discarded by then.
  void post(std::function<void()> deliver);

 private:
  friend class BackgroundJob;
  struct State;
  JobContext(BackgroundJob& owner, std::shared_ptr<State> state);
  BackgroundJob& owner_;
  std::shared_ptr<State> state_;
};

class BackgroundJob : public QObject {
  Q_OBJECT
 public:
  static constexpr int kProgressInterval_ms = 100;
  using ProgressHandler =
      std::function<void(const QString& stage, std::size_t done, std::size_t total)>;
  using ErrorHandler = std::function<void(const JobError&)>;
  /// What `Task` returns when called with a JobContext.
  template <typename Task>
  using ResultOf = std::invoke_result_t<Task&, JobContext&>;

  explicit BackgroundJob(QObject* parent = nullptr);
  ~BackgroundJob() override;

  /// Supersedes the current job and runs `task(JobContext&)` on a new worker thread. On the GUI
  /// thread, unless superseded first: `done` gets its result, or `failed` what it threw, and
  /// `progress` (optional) its reports. Returns the job's id (> 0).
  template <typename Task>
  int start(Task task, std::function<void(ResultOf<Task>)> done, ErrorHandler failed,
            ProgressHandler progress = {}) {
    return startJob(
        [task = std::move(task), done = std::move(done)](JobContext& context) mutable {
          return std::function<void()>(
              [done, result = task(context)]() mutable { done(std::move(result)); });
        },
        std::move(failed), std::move(progress));
  }

  /// Asks the current job to stop; what it delivers (often a Cancelled error) still arrives.
  void cancel();
  /// Cancels the current job and drops whatever it delivers from now on.
  void discard();
  /// Holds the current job at its next cancellation check, or lets it go on.
  void setPaused(bool paused);
  bool paused() const;
  /// True from start() until its job's result or error is delivered, or it is discarded.
  bool running() const { return running_; }
  /// The id of the job whose deliveries arrive (0: none).
  int currentJob() const { return current_id_; }

 private:
  friend class JobContext;
  using Deliver = std::function<void()>;
  int startJob(std::function<Deliver(JobContext&)> run, ErrorHandler failed,
               ProgressHandler progress);
  /// Queues `deliver` to the GUI thread for `job`; an `outcome` ends the job's running().
  void post(int job, Deliver deliver, bool outcome);
  void joinFinishedThreads();

  struct Thread;
  std::list<Thread> threads_;
  std::shared_ptr<JobContext::State> current_;
  int next_id_ = 1;
  int current_id_ = 0;
  bool running_ = false;
};

}  // namespace sonarcarve::gui
