#include "reconstruction_runner.h"

#include <unordered_map>

#include "common/thread_pool.h"

namespace sonarcarve::gui {

namespace {

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
      widgets::MapViewBlock view;
      view.block = b.block;
      view.points = b.points;
      view.values = b.values;
      view.frames_done = update.frames_done;
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

ReconstructionRunner::ReconstructionRunner(ThreadPool& pool, QObject* parent)
    : QObject(parent), pool_(pool) {
  // Carving yields the CPU to the GUI thread and the software renderer (docs/benchmarks.md).
  pool.setBackgroundPriority(true);
}

int ReconstructionRunner::start(RunRequest request) {
  struct Outcome {
    std::shared_ptr<const ReconstructionResult> result;
    std::shared_ptr<widgets::MapView::PreparedResult> view;
    std::shared_ptr<const std::vector<Eigen::Vector3f>> surface_points;
  };
  // Runs on the GUI thread, for the current job only (BackgroundJob drops superseded ones).
  const auto current = [this] { return job_.currentJob(); };
  const int id = job_.start(
      [this, current, request = std::move(request)](JobContext& progress) {
        lowerThisThreadPriority();
        JobObserver observer(
            request.truth,
            [this, current, &progress](std::vector<widgets::MapViewBlock> blocks) {
              progress.post([this, current, blocks = std::move(blocks)] {
                emit blocksChanged(current(), blocks);
              });
            },
            [this, current, &progress](std::size_t index) {
              progress.post([this, current, index] { emit frameCarved(current(), index); });
            },
            [this, current, &progress](std::string message) {
              progress.post([this, current, message] {
                emit frameSkipped(current(), QString::fromStdString(message));
              });
            });
        auto result = std::make_shared<const ReconstructionResult>(
            Pipeline(*request.mission, request.params, pool_)
                .run(progress, &observer, kMapUpdateFrames));
        auto points =
            std::make_shared<const std::vector<Eigen::Vector3f>>(positionsOf(result->surface));
        std::vector<float> surface_errors_m;
        std::vector<float> mesh_errors_m;
        if (request.truth && !result->cancelled) {
          surface_errors_m = request.truth->distances(*points);
          mesh_errors_m = request.truth->distances(result->mesh.vertices);
        }
        // Built on the GUI thread, the end-of-run handler that made the view's layers of the
        // riser demo's surface and mesh blocked it 0.5 to 0.8 s under load (docs/benchmarks.md):
        // built here, the GUI thread only shows them.
        auto view =
            std::make_shared<widgets::MapView::PreparedResult>(widgets::MapView::prepareResult(
                widgets::surfaceBlock(result->surface, std::move(surface_errors_m)),
                widgets::meshData(result->mesh, std::move(mesh_errors_m)), request.colour_by,
                request.clip));
        return Outcome{result, std::move(view), std::move(points)};
      },
      [this, current](Outcome outcome) {
        emit finished(current(), outcome.result, outcome.view, outcome.surface_points);
      },
      [this, current](const JobError& error) { emit failed(current(), error.message); },
      [this, current](const QString& stage, std::size_t done, std::size_t total) {
        emit progressed(current(), stage, done, total);
      });
  emit started(id);
  return id;
}

}  // namespace sonarcarve::gui
