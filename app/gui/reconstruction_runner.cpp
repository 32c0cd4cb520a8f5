#include "reconstruction_runner.h"

#include <algorithm>
#include <unordered_map>

#include "common/error.h"
#include "common/thread_pool.h"

namespace sonarcarve::gui {

namespace {

class JobObserver : public ReconstructionObserver {
 public:
  using PostBlocks = std::function<void(std::vector<widgets::MapViewBlock>)>;
  using PostFrame = std::function<void(std::size_t)>;
  using PostSkip = std::function<void(std::string)>;
  using PostNoise = std::function<void(std::shared_ptr<const NoiseModel>)>;
  JobObserver(std::shared_ptr<const MeshDistance> truth, std::size_t max_cached_voxels,
              PostBlocks blocks, PostFrame frame, PostSkip skip, PostNoise noise)
      : max_cached_voxels_(max_cached_voxels),
        truth_(std::move(truth)),
        blocks_(std::move(blocks)),
        frame_(std::move(frame)),
        skip_(std::move(skip)),
        noise_(std::move(noise)) {}

  void frameCarved(std::size_t index, const Frame&, const Eigen::Isometry3d&) override {
    frame_(index);
  }
  void frameSkipped(const FrameProblem& problem) override { skip_(problem.message); }
  void noiseModelChosen(const std::shared_ptr<const NoiseModel>& model) override { noise_(model); }
  void mapUpdated(const MapUpdate& update) override {
    std::vector<widgets::MapViewBlock> blocks;
    blocks.reserve(update.blocks.size());
    for (const MapBlockUpdate& b : update.blocks) {
      widgets::MapViewBlock view;
      view.block = b.block;
      view.points = b.points;
      view.values = b.values;
      view.frames_done = update.frames_done;
      if (truth_) {
        view.errors_m = errorsOf(b.block, b.points, update.frames_done);
      }
      blocks.push_back(std::move(view));
    }
    if (cached_voxels_ > max_cached_voxels_) {
      forgetOldestBlocks();
    }
    blocks_(std::move(blocks));
  }

 private:
  // A voxel's centre never moves, so its distance to the truth is computed once: a block
  // changes at nearly every frame, its voxels' errors do not. The errors are kept per block for
  // the voxels last sent (a block sent empty is forgotten), for at most `max_cached_voxels_`
  // voxels: past it, those of the blocks changed longest ago are forgotten (computed again if
  // such a block changes again), as the 3D view holds them coarser (widgets/map_lod.h).
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
  struct BlockErrors {
    std::vector<Eigen::Vector3f> points;
    std::vector<float> errors_m;
    std::size_t frames_done = 0;
  };

  std::vector<float> errorsOf(std::size_t block, const std::vector<Eigen::Vector3f>& points,
                              std::size_t frames_done) {
    std::unordered_map<Eigen::Vector3f, float, CentreHash, CentreEqual> known;
    if (const auto cached = known_errors_.find(block); cached != known_errors_.end()) {
      for (std::size_t k = 0; k < cached->second.points.size(); ++k) {
        known.emplace(cached->second.points[k], cached->second.errors_m[k]);
      }
      cached_voxels_ -= cached->second.points.size();
      known_errors_.erase(cached);
    }
    std::vector<Eigen::Vector3f> unknown;
    for (const auto& p : points) {
      if (!known.contains(p)) {
        unknown.push_back(p);
      }
    }
    const std::vector<float> computed = truth_->distances(unknown, kErrorCap_m);
    for (std::size_t i = 0; i < unknown.size(); ++i) {
      known.emplace(unknown[i], computed[i]);
    }
    std::vector<float> errors;
    errors.reserve(points.size());
    for (const auto& p : points) {
      errors.push_back(known.at(p));
    }
    if (!points.empty()) {
      known_errors_[block] = BlockErrors{points, errors, frames_done};
      cached_voxels_ += points.size();
    }
    return errors;
  }

  void forgetOldestBlocks() {
    std::vector<std::pair<std::size_t, std::size_t>> by_age;  // frames done, block
    for (const auto& [block, cached] : known_errors_) {
      by_age.emplace_back(cached.frames_done, block);
    }
    std::sort(by_age.begin(), by_age.end());
    const std::size_t target = max_cached_voxels_ - max_cached_voxels_ / 10;
    for (const auto& [frames_done, block] : by_age) {
      if (cached_voxels_ <= target) {
        break;
      }
      cached_voxels_ -= known_errors_.at(block).points.size();
      known_errors_.erase(block);
    }
  }

  // Colours saturate at 10 cm: farther voxels need no exact distance.
  static constexpr double kErrorCap_m = 0.2;
  std::size_t max_cached_voxels_;
  std::unordered_map<std::size_t, BlockErrors> known_errors_;
  std::size_t cached_voxels_ = 0;
  std::shared_ptr<const MeshDistance> truth_;
  PostBlocks blocks_;
  PostFrame frame_;
  PostSkip skip_;
  PostNoise noise_;
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
            request.truth, request.view_points,
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
            },
            [this, current, &progress](std::shared_ptr<const NoiseModel> model) {
              progress.post([this, current, model = std::move(model)] {
                emit noiseModelChosen(current(), model);
              });
            });
        Pipeline pipeline(*request.mission, request.params, pool_);
        if (!request.report_folder.empty()) {
          std::error_code ec;
          std::filesystem::create_directories(request.report_folder, ec);
          if (ec) {
            throw Error(request.report_folder.string(), "",
                        "cannot make the run's report folder: " + ec.message());
          }
          OutputSettings report;
          report.folder = request.report_folder;
          report.arguments = {"sonarcarve", "(workbench run)", request.mission->folder.string()};
          report.report_only = true;
          pipeline.writeOutputsTo(std::move(report));
        }
        auto result = std::make_shared<const ReconstructionResult>(
            pipeline.run(progress, &observer, kMapUpdateFrames));
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
