#include "reconstruction_runner.h"

#include <QMetaObject>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <unordered_map>

#include "common/error.h"
#include "common/thread_pool.h"

namespace sonarcarve::gui {

// What a job's thread and the runner share: the cancel and pause flags.
struct ReconstructionRunner::Job {
  int id = 0;
  std::atomic<bool> cancel{false};
  std::atomic<bool> done{false};
  mutable std::mutex mutex;
  mutable std::condition_variable resume;
  bool paused = false;
};

namespace {

using Clock = std::chrono::steady_clock;

// Progress that posts to the GUI at most every kProgressInterval_ms and holds the worker
// while the job is paused.
class JobProgress : public Progress {
 public:
  using Post = std::function<void(const std::string&, std::size_t, std::size_t)>;
  JobProgress(std::atomic<bool>& cancel, std::mutex& mutex, std::condition_variable& resume,
              const bool& paused, Post post)
      : cancel_(cancel), mutex_(mutex), resume_(resume), paused_(paused), post_(std::move(post)) {}

  void report(const std::string& stage, std::size_t done, std::size_t total) override {
    const auto now = Clock::now();
    std::lock_guard lock(report_mutex_);
    if (done == total || stage != last_stage_ ||
        now - last_post_ >= std::chrono::milliseconds(ReconstructionRunner::kProgressInterval_ms)) {
      last_post_ = now;
      last_stage_ = stage;
      post_(stage, done, total);
    }
  }

  bool cancelled() const override {
    std::unique_lock lock(mutex_);
    resume_.wait(lock, [&] { return !paused_ || cancel_.load(); });
    return cancel_.load();
  }

 private:
  std::atomic<bool>& cancel_;
  std::mutex& mutex_;
  std::condition_variable& resume_;
  const bool& paused_;
  Post post_;
  std::mutex report_mutex_;
  Clock::time_point last_post_{};
  std::string last_stage_;
};

class JobObserver : public ReconstructionObserver {
 public:
  using PostBlocks = std::function<void(std::vector<widgets::MapViewBlock>)>;
  using PostFrame = std::function<void(std::size_t)>;
  using PostSkip = std::function<void(std::string)>;
  JobObserver(std::shared_ptr<const MeshDistance> truth, PostBlocks blocks, PostFrame frame,
              PostSkip skip)
      : truth_(std::move(truth)),
        blocks_(std::move(blocks)),
        frame_(std::move(frame)),
        skip_(std::move(skip)) {}

  void frameCarved(std::size_t index, const Frame&, const Eigen::Isometry3d&) override {
    frame_(index);
  }
  void frameSkipped(const FrameProblem& problem) override { skip_(problem.message); }
  void mapUpdated(const MapUpdate& update) override {
    std::vector<widgets::MapViewBlock> blocks;
    blocks.reserve(update.blocks.size());
    for (const MapBlockUpdate& b : update.blocks) {
      widgets::MapViewBlock view{b.block, b.points, b.values, {}};
      if (truth_ && !b.points.empty()) {
        view.errors_m = errorsOf(b.points);
      }
      blocks.push_back(std::move(view));
    }
    blocks_(std::move(blocks));
  }

 private:
  // A voxel's centre never moves, so its distance to the truth is computed once: a block
  // changes at nearly every frame, its voxels' errors do not.
  struct CentreHash {
    std::size_t operator()(const Eigen::Vector3f& p) const {
      std::size_t h = 0;
      for (int i = 0; i < 3; ++i) {
        h = h * 1000003u ^ std::hash<float>{}(p[i]);
      }
      return h;
    }
  };
  struct CentreEqual {
    bool operator()(const Eigen::Vector3f& a, const Eigen::Vector3f& b) const { return a == b; }
  };

  std::vector<float> errorsOf(const std::vector<Eigen::Vector3f>& points) {
    std::vector<Eigen::Vector3f> unknown;
    for (const auto& p : points) {
      if (!known_errors_.contains(p)) {
        unknown.push_back(p);
      }
    }
    const std::vector<float> computed = truth_->distances(unknown, kErrorCap_m);
    for (std::size_t i = 0; i < unknown.size(); ++i) {
      known_errors_.emplace(unknown[i], computed[i]);
    }
    std::vector<float> errors;
    errors.reserve(points.size());
    for (const auto& p : points) {
      errors.push_back(known_errors_.at(p));
    }
    return errors;
  }

  // Colours saturate at 10 cm: farther voxels need no exact distance.
  static constexpr double kErrorCap_m = 0.2;
  std::unordered_map<Eigen::Vector3f, float, CentreHash, CentreEqual> known_errors_;
  std::shared_ptr<const MeshDistance> truth_;
  PostBlocks blocks_;
  PostFrame frame_;
  PostSkip skip_;
};

}  // namespace

ReconstructionRunner::ReconstructionRunner(ThreadPool& pool, QObject* parent) : QObject(parent) {
  // Carving yields the CPU to the GUI thread and the software renderer (docs/benchmarks.md).
  pool.setBackgroundPriority(true);
  ThreadPool::shared().setBackgroundPriority(true);  // reconstruct() still carves on it
}

ReconstructionRunner::~ReconstructionRunner() {
  for (auto& [job, thread] : threads_) {
    {
      std::lock_guard lock(job->mutex);
      job->cancel = true;
    }
    job->resume.notify_all();
  }
  for (auto& [job, thread] : threads_) {
    thread.join();
  }
}

void ReconstructionRunner::post(int job, std::function<void()> deliver) {
  // Called from a worker: runs `deliver` on the GUI thread unless the job was superseded.
  // Qt drops the call if the runner is gone by then (it is the call's context object).
  QMetaObject::invokeMethod(
      this,
      [this, job, deliver = std::move(deliver)] {
        if (current_job_ == job) {
          deliver();
        }
      },
      Qt::QueuedConnection);
}

int ReconstructionRunner::start(RunRequest request) {
  cancel();
  reapFinishedThreads();
  auto job = std::make_shared<Job>();
  job->id = next_id_++;
  current_job_ = job->id;
  running_job_ = job->id;
  job_ = job;
  emit started(job->id);
  const int id = job->id;
  std::thread worker([this, job, id, request = std::move(request)] {
    lowerThisThreadPriority();
    JobProgress progress(job->cancel, job->mutex, job->resume, job->paused,
                         [this, id](const std::string& stage, std::size_t done, std::size_t total) {
                           post(id, [this, id, stage, done, total] {
                             emit progressed(id, QString::fromStdString(stage), done, total);
                           });
                         });
    JobObserver observer(
        request.truth,
        [this, id](std::vector<widgets::MapViewBlock> blocks) {
          post(id, [this, id, blocks = std::move(blocks)] { emit blocksChanged(id, blocks); });
        },
        [this, id](std::size_t index) {
          post(id, [this, id, index] { emit frameCarved(id, index); });
        },
        [this, id](std::string message) {
          post(id, [this, id, message] { emit frameSkipped(id, QString::fromStdString(message)); });
        });
    try {
      auto result = std::make_shared<const ReconstructionResult>(
          reconstruct(*request.mission, request.params, progress, &observer, kMapUpdateFrames));
      std::vector<float> errors;
      if (request.truth && !result->cancelled) {
        errors = request.truth->distances(positionsOf(result->surface));
      }
      post(id, [this, id, result, errors = std::move(errors)] {
        running_job_ = 0;
        emit finished(id, result, errors);
      });
    } catch (const std::exception& e) {
      post(id, [this, id, message = std::string(e.what())] {
        running_job_ = 0;
        emit failed(id, QString::fromStdString(message));
      });
    }
    job->done = true;
  });
  threads_.emplace_back(job, std::move(worker));
  return id;
}

void ReconstructionRunner::cancel() {
  if (!job_) {
    return;
  }
  {
    std::lock_guard lock(job_->mutex);
    job_->cancel = true;
    job_->paused = false;
  }
  job_->resume.notify_all();
  job_.reset();
  running_job_ = 0;
  current_job_ = 0;  // late results of the cancelled job are dropped
}

void ReconstructionRunner::setPaused(bool paused) {
  if (!job_) {
    return;
  }
  {
    std::lock_guard lock(job_->mutex);
    job_->paused = paused;
  }
  job_->resume.notify_all();
}

bool ReconstructionRunner::paused() const {
  if (!job_) {
    return false;
  }
  std::lock_guard lock(job_->mutex);
  return job_->paused;
}

void ReconstructionRunner::reapFinishedThreads() {
  for (auto it = threads_.begin(); it != threads_.end();) {
    if (it->first->done) {
      it->second.join();  // already returned: no wait
      it = threads_.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace sonarcarve::gui
