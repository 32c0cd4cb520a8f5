// MainWindow: the SonarCarve workbench. It only wires the widgets together: the sonar frame as
// raw and denoised fans with the frame timeline, the 3D map carved live by the
// ReconstructionRunner, the navigation track, the parameter panel, run control, exports, the
// log, sessions and recent files. Loading errors go to a message and the log; nothing the user
// opens can take the window down.
#pragma once

#include <QMainWindow>
#include <QPointer>
#include <QTimer>
#include <QVector3D>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include "background_job.h"
#include "common/thread_pool.h"
#include "denoise/detector.h"
#include "eval/evaluator.h"
#include "export_dialog.h"
#include "frame_image.h"
#include "io/import.h"
#include "io/mission/mission.h"
#include "map_view.h"
#include "pipeline/frame_stage.h"
#include "pipeline/reconstruction.h"
#include "reconstruction_runner.h"
#include "session/run_record.h"
#include "sonar/bearing_deblur.h"

class QAction;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QPlainTextEdit;
class QProgressBar;
class QProgressDialog;

namespace sonarcarve::widgets {
class AccuracyPanel;
class RunChoicesPanel;
class FanView;
class RunHistoryPanel;
class FrameTimeline;
class MapView;
class ParamsPanel;
class TrackView;
}  // namespace sonarcarve::widgets

namespace sonarcarve {
struct Session;
}

namespace sonarcarve::gui {

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  enum class Export { SurfacePly, MapBt, MeshPly, MeshStl, ViewPng };

  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Opens a mission folder (or its mission.yaml) and starts reconstructing it. Returns false,
  /// after telling the user why, if it cannot be read.
  bool openMission(const QString& path);
  bool openSession(const QString& file);
  /// Imports a vendor log into a mission folder on a worker thread (with a cancellable
  /// progress dialog), then opens it; emits importFinished(ok). A new import supersedes a
  /// running one.
  void importLog(const ImportRequest& request);
  /// Asks for the import's choices (navigation, mounting, time offset), then imports.
  void importWithDialog(const QString& log);
  /// Learns a noise model from a recording of empty water (the same sonar, no target) on a
  /// worker thread, with a cancellable progress dialog; writes it to `out_file`, makes it the
  /// parameters' noise model and re-runs the open mission; emits noiseModelLearned(ok).
  void learnNoiseModel(const QString& empty_water, const QString& out_file);
  bool saveSession(const QString& file);
  bool loadParams(const QString& file);
  bool saveParams(const QString& file);
  /// Writes a deliverable of the last finished run; false (and a message) if there is none or
  /// the write failed. The previous file is left intact on failure.
  bool exportTo(Export kind, const QString& file);
  /// Opens the export dialog for the last finished run (window-modal, returned for tests); its
  /// Export writes the deliverable with exportDeliverable. Null, after a message, without a run.
  ExportDialog* openExportDialog();
  /// Writes a deliverable of the last finished run (core/mesh/deliverable.h, as `sonarcarve-cli
  /// export`) on a worker thread, with a progress dialog that can cancel it; a failure says
  /// which file and why, and the previous file is left intact. Emits exportFinished(ok). A new
  /// export supersedes one still going (asked to stop; nothing of it is reported).
  void exportDeliverable(const DeliverableRequest& request, const QString& file);
  void setParams(const ReconstructionParams& params);
  void setColourBy(widgets::MapView::ColourBy by);
  /// Colouring by error is offered only when the mission has its ground truth.
  bool errorColouringAvailable() const;
  /// What the 3D view shows once a run ends (the user's choice in Show; default the surface).
  void chooseLayer(widgets::MapView::Layer layer);

  // Run control. startRun() starts a new run (superseding one that goes); playRun(), the Run
  // action and the toolbar's Play, resumes a paused run and starts one otherwise.
  void startRun();
  void playRun();
  void cancelRun();
  void setPaused(bool paused);
  /// Restores run `index`'s parameters (of the history) and runs them again.
  void goBackToRun(int index);
  /// Asks for the 3D view's clip box and cross-section.
  void editClip();

  // For tests and the screenshot option.
  ReconstructionRunner& runner() { return *runner_; }
  widgets::MapView& mapView() { return *map_view_; }
  widgets::ParamsPanel& paramsPanel() { return *params_panel_; }
  widgets::FrameTimeline& timeline() { return *timeline_; }
  std::shared_ptr<const ReconstructionResult> lastResult() const { return result_; }
  const Mission* mission() const { return mission_.get(); }
  widgets::AccuracyPanel& accuracyPanel() { return *accuracy_panel_; }
  widgets::RunChoicesPanel& choicesPanel() { return *choices_panel_; }
  widgets::RunHistoryPanel& runHistoryPanel() { return *history_panel_; }
  const std::vector<RunRecord>& runs() const { return runs_; }
  QString logText() const;
  /// The detector the denoised view runs (None: it shows the frame as it is).
  DetectorMode denoisedViewDetector() const;

 signals:
  void runFinished(std::shared_ptr<const ReconstructionResult> result);
  void runFailed(const QString& message);
  void importFinished(bool ok);
  void noiseModelLearned(bool ok);
  void exportFinished(bool ok);
  /// The last run measured against the ground truth (the accuracy panel shows it).
  void accuracyMeasured(double fscore);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildMenus();
  void buildToolbar();
  void buildDocks();
  void wireRunner();
  void showError(const QString& title, const QString& message);
  /// A progress dialog for a job (0 to 100, shown after half a second, deleted when closed):
  /// progressTo() makes the job's progress handler, cancelJobFrom() ties its Cancel to the job.
  /// Close it when the job delivers.
  QPointer<QProgressDialog> jobProgressDialog(const QString& label);
  static BackgroundJob::ProgressHandler progressTo(QPointer<QProgressDialog> dialog);
  void cancelJobFrom(QProgressDialog* dialog, BackgroundJob& job, int id);
  /// The last run's products and the mission's place, for a deliverable.
  DeliverableSource deliverableSource() const;
  ExportPlace exportPlace() const;
  /// The 3D view's intensity unit: the fitted reflectance after a run with the map fit.
  void showIntensityUnit(bool fitted);
  void log(const QString& line);
  // A frame read and denoised off the GUI thread, ready to draw.
  struct ShownFrame {
    int index = 0;
    cv::Mat raw;
    cv::Mat denoised;
    DisplayWindow range;
  };
  void showFrame(int index);
  void drawFrame(const ShownFrame& shown);
  void paramsEdited();
  void readBeamWidth();
  void followParams();  // the width and the detector, after the parameters changed
  void updateDetector();
  /// The noise model the denoised view's detector uses with parameters `p` (null: none).
  std::shared_ptr<const NoiseModel> viewNoiseModel(const ReconstructionParams& p) const;
  /// A session, a vendor log (through the import dialog) or a mission, by what `path` is.
  void openPath(const QString& path);
  /// Opens a mission; `own_params`: a mission opened after another starts from the parameters
  /// of its own last run here, or the defaults (never the other mission's noise model).
  bool openMissionWith(const QString& path, bool own_params);
  void takeMissionParams();
  void updateColourChoices();
  void addRecent(const QString& path);
  void fillRecentMenu();
  void updateRunActions();
  void recordRun(const ReconstructionResult& result);
  void measureAccuracy(std::shared_ptr<const std::vector<Eigen::Vector3f>> points);
  /// Lets go of the last run's result and of the 3D view's copy of its map; a worker frees them.
  void releaseRun(widgets::MapView::MapBlocks shown_map);
  Session currentSession() const;

  ThreadPool pool_;  // the workbench's one pool; it outlives the jobs that use it
  std::unique_ptr<ReconstructionRunner> runner_;
  std::shared_ptr<const Mission> mission_;
  std::shared_ptr<const MeshDistance> truth_;
  std::shared_ptr<const Scene> truth_mesh_;
  std::vector<RunRecord> runs_;  // this mission's runs, oldest first (kept in the session)
  std::shared_ptr<const ReconstructionResult> result_;
  std::shared_ptr<const Detector> detector_;
  std::shared_ptr<const BearingDeblur> deblur_;  // the beams' blur, as carving takes it out
  std::shared_ptr<const NoiseModel> noise_model_;
  // The model the last run learned from the mission's own frames (the detector auto, no file).
  std::shared_ptr<const NoiseModel> run_noise_model_;
  std::string noise_model_path_;
  ReconstructionParams run_params_;
  /// The running run's report.html, in the workbench's data folder (runs/<started>/).
  QString run_report_;

  widgets::FanView* raw_view_ = nullptr;
  widgets::FanView* denoised_view_ = nullptr;
  widgets::FrameTimeline* timeline_ = nullptr;
  widgets::MapView* map_view_ = nullptr;
  widgets::TrackView* track_view_ = nullptr;
  widgets::ParamsPanel* params_panel_ = nullptr;
  widgets::AccuracyPanel* accuracy_panel_ = nullptr;
  widgets::RunChoicesPanel* choices_panel_ = nullptr;
  QDockWidget* choices_dock_ = nullptr;
  widgets::RunHistoryPanel* history_panel_ = nullptr;
  QPlainTextEdit* log_ = nullptr;
  QProgressBar* progress_bar_ = nullptr;
  QLabel* progress_label_ = nullptr;
  QComboBox* colour_by_ = nullptr;
  QComboBox* layer_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  QAction* run_action_ = nullptr;
  QAction* pause_action_ = nullptr;
  QAction* cancel_action_ = nullptr;
  QAction* follow_action_ = nullptr;
  QTimer follow_timer_;
  long latest_carved_frame_ = -1;
  // The mission's view is the user's (a run has ended, or a session set it): re-runs keep the
  // camera, the frame and the layer.
  bool view_settled_ = false;
  std::optional<QVector3D> last_pick_;  // the 3D view's previous pick, for distances
  int preferred_layer_ = static_cast<int>(widgets::MapView::Layer::Surface);
  // The first carve report of the run (frames done then; -1: none yet), for the time left.
  std::chrono::steady_clock::time_point carve_started_;
  long long carve_started_done_ = -1;
  // Off the GUI thread: reading a noise model, reading and denoising the frame shown, and
  // importing a vendor log (with its progress dialog).
  BackgroundJob noise_model_job_;
  // A mission that does not say how wide its beams are: the width read from its frames for the
  // denoised view, as a run reads it (0 until read, or when none can be).
  BackgroundJob beam_width_job_;
  double read_beam_width_rad_ = 0.0;
  std::optional<std::vector<std::size_t>> beam_width_frames_;  // what it is read from, if read
  BackgroundJob frame_job_;
  BackgroundJob import_job_;
  BackgroundJob learn_job_;
  BackgroundJob accuracy_job_;
  BackgroundJob release_job_;
  BackgroundJob export_job_;
  QPointer<QProgressDialog> import_dialog_;
  QPointer<QProgressDialog> export_dialog_;  // of the export going, if any
};

}  // namespace sonarcarve::gui
