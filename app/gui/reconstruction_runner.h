// ReconstructionRunner: runs reconstruct() on a worker thread for the GUI, one job at a time
// (a BackgroundJob). Each start() gets a job id; starting a job cancels the running one, whose
// late results are dropped (superseded). Results reach the GUI thread as values through
// queued calls: map blocks that changed (with their error against the ground truth, computed
// on the worker), progress (at most every BackgroundJob::kProgressInterval_ms), skipped
// frames, the noise model the run denoises with (given or learned, before it carves), the final
// result (with the 3D view's layers of its surface and mesh built on the worker) or an error. Pause
// holds the worker at its next cancellation check. The GUI thread never waits on a worker, except
// in the destructor, which cancels every job and joins its thread.
#pragma once

#include <QObject>
#include <QString>
#include <memory>
#include <vector>

#include "background_job.h"
#include "common/thread_pool.h"
#include "eval/evaluator.h"
#include "io/mission/mission.h"
#include "map_view.h"
#include "pipeline/reconstruction.h"

namespace sonarcarve::gui {

struct RunRequest {
  std::shared_ptr<const Mission> mission;
  ReconstructionParams params;
  /// The ground truth, to colour points by their error (optional).
  std::shared_ptr<const MeshDistance> truth;
  /// The 3D view's colouring and clip when the run started: the worker builds the surface's
  /// and the mesh's layers for them.
  widgets::MapView::ColourBy colour_by = widgets::MapView::ColourBy::Intensity;
  widgets::ViewClip clip;
  /// The 3D view's budget of map points: the errors against the truth are kept for as many
  /// voxels at most.
  std::size_t view_points = widgets::MapLod::kDefaultMaxPoints;
  /// Where the run writes its report.json and report.html (made if missing); none if empty.
  std::filesystem::path report_folder;
};

class ReconstructionRunner : public QObject {
  Q_OBJECT
 public:
  /// Map updates every this many frames: each update carries every block the frames changed
  /// (most of the frustum), so one per frame cost the demo five times its carving time; at 4
  /// the map still grows about four times a second.
  static constexpr std::size_t kMapUpdateFrames = 4;

  /// Lowers the priority of `pool`, on which the jobs compute, while they carve.
  explicit ReconstructionRunner(ThreadPool& pool, QObject* parent = nullptr);

  /// Cancels the running job, if any, and starts `request`; returns the new job's id.
  int start(RunRequest request);
  /// Stops the running job; nothing more of it arrives.
  void cancel() { job_.discard(); }
  void setPaused(bool paused) { job_.setPaused(paused); }
  bool paused() const { return job_.paused(); }
  bool running() const { return job_.running(); }
  int currentJob() const { return job_.currentJob(); }

 signals:
  void started(int job);
  void progressed(int job, const QString& stage, qulonglong done, qulonglong total);
  void blocksChanged(int job, const std::vector<widgets::MapViewBlock>& blocks);
  void frameCarved(int job, qulonglong frame_index);
  void frameSkipped(int job, const QString& message);
  /// The noise model the job's detector uses (null: none), learned or given, before it carves.
  void noiseModelChosen(int job, std::shared_ptr<const NoiseModel> model);
  /// `view`: the surface and the mesh with their errors against the truth (none without one)
  /// and their layers, built on the worker for the request's colouring and clip (for
  /// MapView::setResult); `surface_points`: the surface's positions (to measure it).
  void finished(int job, std::shared_ptr<const ReconstructionResult> result,
                std::shared_ptr<widgets::MapView::PreparedResult> view,
                std::shared_ptr<const std::vector<Eigen::Vector3f>> surface_points);
  void failed(int job, const QString& message);

 private:
  ThreadPool& pool_;
  BackgroundJob job_;
};

}  // namespace sonarcarve::gui
