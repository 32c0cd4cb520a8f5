#include "main_window.h"

#include <QAction>
#include <QApplication>
#include <QBuffer>
#include <QCloseEvent>
#include <QComboBox>
#include <QDateTime>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QProgressDialog>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTime>
#include <QToolBar>
#include <QUrl>
#include <QVBoxLayout>
#include <algorithm>

#include "accuracy_panel.h"
#include "carve/occupancy_export.h"
#include "clip_dialog.h"
#include "common/error.h"
#include "fan_view.h"
#include "frame_image.h"
#include "frame_timeline.h"
#include "geometry/scene_io.h"
#include "gui_conventions.h"
#include "import_dialog.h"
#include "io/files/atomic_file.h"
#include "io/frame_source.h"
#include "io/oculus/oculus_log.h"
#include "map_view.h"
#include "mesh/deliverable.h"
#include "occlusion/surface_points.h"
#include "params_panel.h"
#include "pipeline/report.h"
#include "run_choices_panel.h"
#include "run_history_panel.h"
#include "session/session_file.h"
#include "track_view.h"

namespace sonarcarve::gui {
namespace {

constexpr int kMaxRecent = 8;
constexpr int kFollowInterval_ms = 400;

QString describe(const std::exception& e) {
  return QString::fromStdString(e.what());
}

// Where the parameters of a mission's last run are remembered (QSettings).
QString paramsKey(const std::filesystem::path& folder) {
  return QStringLiteral("mission_params/") +
         QString::fromStdString(folder.string()).toUtf8().toBase64(QByteArray::Base64UrlEncoding);
}

// QProgressBar::setValue() repaints at once when its text changes, and with the 3D view in
// the window a repaint composes the whole window through OpenGL: 40 to 70 ms with software
// OpenGL under load, at every progress report. With its updates held, the bar is repainted
// with the rest of the window at the next update instead.
void showProgress(QProgressBar& bar, int maximum, int value, const QString& format) {
  bar.setUpdatesEnabled(false);
  bar.setMaximum(maximum);
  bar.setValue(value);
  bar.setFormat(format);
  bar.setUpdatesEnabled(true);  // schedules an update
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), runner_(std::make_unique<ReconstructionRunner>(pool_)) {
  setWindowTitle(tr("SonarCarve"));
  setAcceptDrops(true);
  resize(1280, 800);

  raw_view_ = new widgets::FanView(tr("raw"));
  denoised_view_ = new widgets::FanView(tr("denoised"));
  timeline_ = new widgets::FrameTimeline;
  auto* fans = new QSplitter(Qt::Vertical);
  fans->addWidget(raw_view_);
  fans->addWidget(denoised_view_);
  auto* left = new QWidget;
  auto* left_layout = new QVBoxLayout(left);
  left_layout->setContentsMargins(0, 0, 0, 0);
  left_layout->addWidget(fans, 1);
  left_layout->addWidget(timeline_);
  map_view_ = new widgets::MapView;
  auto* centre = new QSplitter(Qt::Horizontal);
  centre->addWidget(left);
  centre->addWidget(map_view_);
  centre->setStretchFactor(0, 2);
  centre->setStretchFactor(1, 3);
  setCentralWidget(centre);

  progress_bar_ = new QProgressBar;
  // Its text changes at every report: a fixed size keeps Qt from re-laying out the window.
  progress_bar_->setFixedSize(260, progress_bar_->sizeHint().height());
  progress_bar_->setTextVisible(true);
  progress_label_ = new QLabel(tr("Open a mission (File > Open, or drop its folder here)"));
  // A label of fixed size: Qt re-lays out the whole window each time another label's text
  // changes (60 ms and more with software OpenGL while carving).
  progress_label_->setFixedSize(760, progress_label_->sizeHint().height());
  statusBar()->addWidget(progress_label_, 1);
  statusBar()->addPermanentWidget(progress_bar_);

  buildDocks();
  buildMenus();
  buildToolbar();
  updateColourChoices();
  wireRunner();

  connect(timeline_, &widgets::FrameTimeline::currentFrameChanged, this, &MainWindow::showFrame);
  connect(map_view_, &widgets::MapView::pointPicked, this,
          [this](const QString& text, const QVector3D& ned) {
            QString message = text;
            if (last_pick_) {
              // Two picks measure: the distance from the one before, and its components.
              const QVector3D d = ned - *last_pick_;
              message += tr("; %1 m from the previous pick (N %2, E %3, D %4)")
                             .arg(d.length(), 0, 'f', 3)
                             .arg(d.x(), 0, 'f', 3)
                             .arg(d.y(), 0, 'f', 3)
                             .arg(d.z(), 0, 'f', 3);
            }
            last_pick_ = ned;
            statusBar()->showMessage(message);
            log(tr("picked %1").arg(message));
          });
  connect(params_panel_, &widgets::ParamsPanel::paramsEdited, this, &MainWindow::paramsEdited);
  for (auto* view : {raw_view_, denoised_view_}) {
    connect(view, &widgets::FanView::hovered, this,
            [this](const QString& text) { statusBar()->showMessage(text, 3000); });
  }
  follow_timer_.setInterval(kFollowInterval_ms);
  connect(&follow_timer_, &QTimer::timeout, this, [this] {
    if (latest_carved_frame_ >= 0 && follow_action_->isChecked()) {
      timeline_->setCurrentFrame(static_cast<int>(latest_carved_frame_));
    }
  });
  updateRunActions();
}

MainWindow::~MainWindow() = default;

void MainWindow::buildDocks() {
  params_panel_ = new widgets::ParamsPanel;
  auto* scroll = new QScrollArea;
  scroll->setWidget(params_panel_);
  scroll->setWidgetResizable(true);
  const auto dock = [this](const QString& title, const char* name, QWidget* widget,
                           Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    d->setWidget(widget);
    addDockWidget(area, d);
    return d;
  };
  dock(tr("Parameters"), "parameters", scroll, Qt::LeftDockWidgetArea);

  track_view_ = new widgets::TrackView;
  auto* track_dock = dock(tr("Navigation"), "navigation", track_view_, Qt::BottomDockWidgetArea);
  log_ = new QPlainTextEdit;
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(5000);
  auto* log_dock = dock(tr("Log"), "log", log_, Qt::BottomDockWidgetArea);
  splitDockWidget(track_dock, log_dock, Qt::Horizontal);

  // Accuracy and the run history share the bottom right, as tabs.
  accuracy_panel_ = new widgets::AccuracyPanel;
  auto* accuracy_dock = dock(tr("Accuracy"), "accuracy", accuracy_panel_, Qt::BottomDockWidgetArea);
  splitDockWidget(log_dock, accuracy_dock, Qt::Horizontal);
  history_panel_ = new widgets::RunHistoryPanel;
  tabifyDockWidget(accuracy_dock,
                   dock(tr("Run history"), "history", history_panel_, Qt::BottomDockWidgetArea));
  choices_panel_ = new widgets::RunChoicesPanel;
  choices_dock_ = dock(tr("Choices"), "choices", choices_panel_, Qt::BottomDockWidgetArea);
  tabifyDockWidget(accuracy_dock, choices_dock_);
  accuracy_dock->raise();
  connect(history_panel_, &widgets::RunHistoryPanel::goBackRequested, this,
          &MainWindow::goBackToRun);
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(style()->standardIcon(QStyle::SP_DirOpenIcon), tr("&Open mission…"),
                  QKeySequence::Open, this, [this] {
                    const QString dir =
                        QFileDialog::getExistingDirectory(this, tr("Open a mission folder"));
                    if (!dir.isEmpty()) {
                      openMission(dir);
                    }
                  });
  // Recordings read in place (core/io/frame_source.h picks the reader by content): ROS 2 bags
  // (a .mcap or .db3 file; a bag folder opens as a mission), ARIS and Oculus recordings.
  file->addAction(tr("Open &recording…"), QKeySequence(tr("Ctrl+Shift+O")), this, [this] {
    const QString recording = QFileDialog::getOpenFileName(
        this, tr("Open a sonar recording"), QString(),
        tr("Sonar recordings (*.mcap *.db3 *.aris *.oculus);;All files (*)"));
    if (!recording.isEmpty()) {
      openMission(recording);
    }
  });
  file->addAction(tr("&Import a sonar log…"), QKeySequence(tr("Ctrl+I")), this, [this] {
    const QString log =
        QFileDialog::getOpenFileName(this, tr("Import a sonar log"), QString(),
                                     tr("Oculus logs (*.oculus *.raw *.bin);;All files (*)"));
    if (!log.isEmpty()) {
      importWithDialog(log);
    }
  });
  recent_menu_ = file->addMenu(tr("Open &recent"));
  fillRecentMenu();
  file->addSeparator();
  file->addAction(tr("Open &session…"), this, [this] {
    const QString f = QFileDialog::getOpenFileName(this, tr("Open a session"), QString(),
                                                   tr("SonarCarve sessions (*.sonarcarve)"));
    if (!f.isEmpty()) {
      openSession(f);
    }
  });
  file->addAction(tr("Save s&ession…"), QKeySequence::Save, this, [this] {
    const QString f =
        withSuffix(QFileDialog::getSaveFileName(this, tr("Save the session"), QString(),
                                                tr("SonarCarve sessions (*.sonarcarve)")),
                   ".sonarcarve");
    if (!f.isEmpty()) {
      saveSession(f);
    }
  });
  file->addAction(tr("Learn a &noise model from empty water…"), this, [this] {
    const QString empty = QFileDialog::getExistingDirectory(
        this, tr("A mission of empty water (the same sonar, no target)"));
    if (empty.isEmpty()) {
      return;
    }
    const QString out =
        withSuffix(QFileDialog::getSaveFileName(this, tr("Save the noise model"),
                                                QDir(empty).filePath("noise_model.yaml"),
                                                tr("Noise models (*.yaml *.yml)")),
                   ".yaml", {".yml"});
    if (!out.isEmpty()) {
      learnNoiseModel(empty, out);
    }
  });
  file->addSeparator();
  file->addAction(tr("&Load parameters…"), this, [this] {
    const QString f = QFileDialog::getOpenFileName(this, tr("Load parameters"), QString(),
                                                   tr("Parameters (*.yaml *.yml)"));
    if (!f.isEmpty()) {
      loadParams(f);
    }
  });
  file->addAction(tr("Save &parameters…"), this, [this] {
    const QString f =
        withSuffix(QFileDialog::getSaveFileName(this, tr("Save parameters"), "params.yaml",
                                                tr("Parameters (*.yaml *.yml)")),
                   ".yaml", {".yml"});
    if (!f.isEmpty()) {
      saveParams(f);
    }
  });
  file->addSeparator();
  QMenu* exports = file->addMenu(tr("&Export"));
  const auto add_export = [&](const QString& label, Export kind, const QString& kind_name,
                              const QString& suffix) {
    exports->addAction(label, this, [this, kind, kind_name, suffix] {
      const QString filter = QStringLiteral("%1 (*%2)").arg(kind_name, suffix);
      const QString f =
          withSuffix(QFileDialog::getSaveFileName(this, tr("Export"), QString(), filter), suffix);
      if (!f.isEmpty()) {
        exportTo(kind, f);
      }
    });
  };
  exports->addAction(tr("&Map: mesh, points, LAS or GeoTIFF…"), QKeySequence(tr("Ctrl+E")), this,
                     &MainWindow::openExportDialog);
  add_export(tr("Carved map (OctoMap .bt)…"), Export::MapBt, tr("OctoMap"), ".bt");
  add_export(tr("3D view (PNG)…"), Export::ViewPng, tr("PNG"), ".png");
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

  QMenu* run = menuBar()->addMenu(tr("&Run"));
  run_action_ = run->addAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("&Start"), this,
                               &MainWindow::playRun);
  run_action_->setShortcut(Qt::Key_F5);
  pause_action_ = run->addAction(style()->standardIcon(QStyle::SP_MediaPause), tr("&Pause"));
  pause_action_->setCheckable(true);
  connect(pause_action_, &QAction::toggled, this, &MainWindow::setPaused);
  cancel_action_ = run->addAction(style()->standardIcon(QStyle::SP_MediaStop), tr("&Cancel"), this,
                                  &MainWindow::cancelRun);
  cancel_action_->setShortcut(Qt::Key_Escape);
  run->addSeparator();
  run->addAction(tr("&Reset parameters to defaults"), this, [this] {
    ReconstructionParams defaults;
    defaults.noise_model = params_panel_->params().noise_model;  // data, not a tuning
    setParams(defaults);
    paramsEdited();
  });
  follow_action_ = run->addAction(tr("&Follow the carving in the frame view"));
  follow_action_->setCheckable(true);
  follow_action_->setChecked(true);

  QMenu* frames = menuBar()->addMenu(tr("F&rames"));
  frames->addAction(tr("&Play / pause"), QKeySequence(Qt::Key_Space), this,
                    [this] { timeline_->setPlaying(!timeline_->playing()); });
  frames->addAction(tr("&Next frame"), QKeySequence(Qt::Key_Right), timeline_,
                    &widgets::FrameTimeline::stepForward);
  frames->addAction(tr("P&revious frame"), QKeySequence(Qt::Key_Left), timeline_,
                    &widgets::FrameTimeline::stepBack);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(tr("&Fit (reset the view)"), QKeySequence(Qt::Key_Home), this,
                  [this] { map_view_->fitCamera(); });
  view->addAction(tr("&Top"), this, [this] { map_view_->viewFromTop(); });
  view->addAction(tr("&Side"), this, [this] { map_view_->viewFromSide(); });
  QAction* grey = view->addAction(tr("&Grey sonar images"));
  grey->setCheckable(true);
  connect(grey, &QAction::toggled, this, [this](bool on) {
    for (auto* fan : {raw_view_, denoised_view_}) {
      fan->setColourMap(on ? widgets::ColourMap::Grey : widgets::ColourMap::Copper);
    }
  });
  view->addAction(tr("&Clip box and cross-section…"), QKeySequence(tr("Ctrl+K")), this,
                  &MainWindow::editClip);
  view->addAction(tr("Show &everything (no clip)"), this,
                  [this] { map_view_->setClip(widgets::ViewClip{}); });
  QAction* ortho = view->addAction(tr("&Orthographic"));
  ortho->setCheckable(true);
  connect(ortho, &QAction::toggled, this, [this](bool on) { map_view_->setOrthographic(on); });

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&User guide"), QKeySequence::HelpContents, this, [this] {
    const QString guide = userGuideFile();
    if (guide.isEmpty() || !QDesktopServices::openUrl(QUrl::fromLocalFile(guide))) {
      showError(tr("User guide"),
                tr("The user guide was not found beside the program (share/doc/sonarcarve). It "
                   "is docs/user-guide/README.md in SonarCarve's sources."));
    }
  });
  help->addAction(tr("&Keyboard shortcuts"), this, [this] {
    QMessageBox::information(this, tr("Keyboard shortcuts"), shortcutList(*menuBar()));
  });
  help->addAction(tr("&About SonarCarve"), this, [this] {
    QMessageBox::about(this, tr("About SonarCarve"),
                       tr("SonarCarve %1\n3D maps of underwater structures from 2D imaging "
                          "sonar logs and navigation (space carving, after Guerneve and "
                          "Petillot 2015).")
                           .arg(QCoreApplication::applicationVersion()));
  });
}

void MainWindow::buildToolbar() {
  QToolBar* bar = addToolBar(tr("Run"));
  bar->setObjectName("run");
  bar->addAction(run_action_);
  bar->addAction(pause_action_);
  bar->addAction(cancel_action_);
  bar->addSeparator();
  bar->addAction(tr("Fit"), this, [this] { map_view_->fitCamera(); });
  bar->addAction(tr("Top"), this, [this] { map_view_->viewFromTop(); });
  bar->addAction(tr("Side"), this, [this] { map_view_->viewFromSide(); });
  bar->addSeparator();
  bar->addWidget(new QLabel(tr(" Show ")));
  layer_ = new QComboBox;
  layer_->addItems({tr("carved map"), tr("surface points"), tr("mesh")});
  layer_->setToolTip(tr("The carved map grows live; the surface and its mesh come at the end"));
  bar->addWidget(layer_);
  connect(layer_, &QComboBox::currentIndexChanged, this,
          [this](int i) { map_view_->setLayer(static_cast<widgets::MapView::Layer>(i)); });
  connect(layer_, &QComboBox::activated, this,
          [this](int i) { chooseLayer(static_cast<widgets::MapView::Layer>(i)); });
  bar->addWidget(new QLabel(tr(" Colour by ")));
  colour_by_ = new QComboBox;
  colour_by_->addItems({tr("intensity"), tr("depth"), tr("error vs ground truth")});
  bar->addWidget(colour_by_);
  connect(colour_by_, &QComboBox::currentIndexChanged, this,
          [this](int i) { map_view_->setColourBy(static_cast<widgets::MapView::ColourBy>(i)); });
}

void MainWindow::wireRunner() {
  connect(runner_.get(), &ReconstructionRunner::progressed, this,
          [this](int, const QString& stage, qulonglong done, qulonglong total) {
            // A stage that reports no steps (the mesh: 0 of 1 until it ends) shows as busy.
            const bool busy = total <= 1 && done == 0;
            showProgress(*progress_bar_, busy ? 0 : static_cast<int>(total), static_cast<int>(done),
                         stage + " %v/%m");
            QString text =
                busy ? tr("%1…").arg(stage) : tr("%1: %2 of %3").arg(stage).arg(done).arg(total);
            if (stage == "carve") {
              // Time left from the carving's own pace: the stages before it (noise model, keep
              // level) are not frames.
              const auto now = std::chrono::steady_clock::now();
              if (carve_started_done_ < 0 || done < static_cast<qulonglong>(carve_started_done_)) {
                carve_started_ = now;
                carve_started_done_ = static_cast<long long>(done);
              }
              const auto carved = done - static_cast<qulonglong>(carve_started_done_);
              if (carved > 0) {
                const double elapsed = std::chrono::duration<double>(now - carve_started_).count();
                const double left =
                    elapsed * static_cast<double>(total - done) / static_cast<double>(carved);
                text += tr(" frames, about %1 s left").arg(left, 0, 'f', 0);
              }
            }
            progress_label_->setText(text);
          });
  connect(runner_.get(), &ReconstructionRunner::blocksChanged, this,
          [this](int, const std::vector<widgets::MapViewBlock>& blocks) {
            map_view_->applyBlocks(blocks);
          });
  connect(runner_.get(), &ReconstructionRunner::frameCarved, this,
          [this](int, qulonglong index) { latest_carved_frame_ = static_cast<long>(index); });
  connect(runner_.get(), &ReconstructionRunner::frameSkipped, this,
          [this](int, const QString& message) { log(tr("skipped: %1").arg(message)); });
  connect(
      runner_.get(), &ReconstructionRunner::noiseModelChosen, this,
      [this](int, std::shared_ptr<const NoiseModel> model) {
        // Only a model the run learned (the run's own parameters: the panel's may have
        // changed since); whether the view uses it is for viewNoiseModel to say.
        if (!run_params_.noise_model.empty() || run_params_.detector.mode != DetectorMode::Auto) {
          return;
        }
        if (model == run_noise_model_) {
          return;
        }
        const DetectorMode before = denoisedViewDetector();
        run_noise_model_ = std::move(model);
        updateDetector();
        showFrame(timeline_->currentFrame());
        if (before != DetectorMode::ZTest && denoisedViewDetector() == DetectorMode::ZTest) {
          log(
              tr("denoised view: the Z-test with the noise model the run learned from the "
                 "mission's own frames"));
        }
      });
  connect(runner_.get(), &ReconstructionRunner::finished, this,
          [this](int, std::shared_ptr<const ReconstructionResult> result,
                 std::shared_ptr<widgets::MapView::PreparedResult> view,
                 std::shared_ptr<const std::vector<Eigen::Vector3f>> surface_points) {
            result_ = result;
            follow_timer_.stop();
            map_view_->setCaption({});
            map_view_->setLive(false);
            map_view_->flush();
            map_view_->setResult(std::move(*view));  // built on the worker
            showIntensityUnit(std::any_of(
                result->choices.begin(), result->choices.end(),
                [](const RunChoice& c) { return c.name == "map fit" && c.value == "on"; }));
            if (!result->surface.empty()) {
              layer_->setCurrentIndex(preferred_layer_);  // the surface, or the user's choice
              if (!view_settled_) {
                map_view_->fitCamera();
              }
            }
            view_settled_ = true;
            progress_bar_->setFormat(tr("done"));
            const QString summary =
                tr("done: %1 frames, %2 occupied voxels, %3 surface points, %4 mesh triangles, "
                   "%5 s (carving %6 ms/frame)")
                    .arg(result->frames_used)
                    .arg(result->occupied_voxels)
                    .arg(result->surface.size())
                    .arg(result->mesh.triangles.size())
                    .arg(result->total_s, 0, 'f', 1)
                    .arg(result->carve_ms_median, 0, 'f', 1);
            for (const RunChoice& choice : result->choices) {
              log(QString::fromStdString(choiceLine(choice)));
            }
            choices_panel_->setChoices(result->choices);
            // A choice that may harm the map is shown, not left behind a tab.
            if (std::any_of(result->choices.begin(), result->choices.end(),
                            [](const RunChoice& c) { return c.warning; })) {
              choices_dock_->raise();
            }
            log(summary);
            progress_label_->setText(summary);
            updateRunActions();
            recordRun(*result);
            measureAccuracy(std::move(surface_points));
            emit runFinished(result);
          });
  connect(runner_.get(), &ReconstructionRunner::failed, this, [this](int, const QString& message) {
    follow_timer_.stop();
    map_view_->setLive(false);
    progress_label_->setText(tr("Reconstruction failed"));
    map_view_->setCaption(tr("Failed: what was carved before the error, not a result"));
    showError(tr("Reconstruction failed"), message);
    updateRunActions();
    emit runFailed(message);
  });
}

void MainWindow::showIntensityUnit(bool fitted) {
  // Carving keeps power, which a decibel or gamma sonar's counts are not; a fitted map keeps
  // each point's fitted reflectance (core/fit/fitted_surface.h).
  if (fitted) {
    map_view_->setIntensityUnit(tr("fitted reflectance"));
  } else if (mission_) {
    map_view_->setIntensityUnit(mission_->sonar.intensityScale().isLinear() ? tr("counts")
                                                                            : tr("power"));
  }
}

void MainWindow::log(const QString& line) {
  log_->appendPlainText(QTime::currentTime().toString("HH:mm:ss  ") + line);
}

QString MainWindow::logText() const {
  return log_->toPlainText();
}

void MainWindow::showError(const QString& title, const QString& message) {
  log(tr("error: %1").arg(message));
  // Window-modal and non-blocking: the event loop (and a running job) carry on.
  auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setObjectName("errorMessage");
  box->open();
}

namespace {

// A recording without its own navigation (a vendor log) is placed with the navigation CSV
// beside it: LOG_STEM.nav.csv, LOG_STEM.csv or nav.csv in its folder, the first that exists.
OpenOptions optionsBeside(const std::filesystem::path& recording) {
  OpenOptions options;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(recording, ec)) {
    return options;
  }
  const std::filesystem::path folder = recording.parent_path();
  const std::string stem = recording.stem().string();
  for (const std::filesystem::path& nav :
       {folder / (stem + ".nav.csv"), folder / (stem + ".csv"), folder / "nav.csv"}) {
    if (std::filesystem::is_regular_file(nav, ec)) {
      options.nav_csv = nav;
      break;
    }
  }
  return options;
}

}  // namespace

bool MainWindow::openMission(const QString& path) {
  return openMissionWith(path, true);
}

void MainWindow::takeMissionParams() {
  const QString key = paramsKey(mission_->folder);
  const QString saved = QSettings().value(key).toString();
  if (!saved.isEmpty()) {
    try {
      setParams(ReconstructionParams::fromYamlText(saved.toStdString(), "saved parameters"));
      log(tr("parameters: this mission's own, from its last run here"));
      return;
    } catch (const std::exception& e) {
      log(tr("parameters: this mission's saved ones are not readable (%1)").arg(describe(e)));
    }
  }
  setParams(ReconstructionParams{});
  log(
      tr("parameters: the defaults (a mission opened after another does not take its "
         "parameters or noise model)"));
}

bool MainWindow::openMissionWith(const QString& path, bool own_params) {
  std::shared_ptr<const Mission> mission;
  try {
    mission = std::make_shared<const Mission>(
        sonarcarve::openMission(path.toStdString(), optionsBeside(path.toStdString())));
    if (mission->frames.empty()) {
      throw Error(path.toStdString(), "", "the mission has no frames");
    }
  } catch (const std::exception& e) {
    showError(tr("Cannot open the mission"), describe(e));
    return false;
  }
  runner_->cancel();
  const bool another = mission_ && mission_->folder != mission->folder;
  mission_ = mission;
  run_noise_model_.reset();   // learned again by this mission's run
  beam_width_job_.discard();  // read again for this mission (readBeamWidth)
  read_beam_width_rad_ = 0.0;
  beam_width_frames_.reset();
  view_settled_ = false;
  last_pick_.reset();
  map_view_->clearPicks();
  if (another && own_params) {
    takeMissionParams();
  }
  releaseRun(map_view_->takeMap());
  truth_.reset();
  truth_mesh_.reset();
  runs_.clear();
  history_panel_->setRuns(runs_);
  accuracy_job_.discard();
  const auto truth_file = mission_->folder / "ground_truth.ply";
  if (std::filesystem::exists(truth_file)) {
    try {
      truth_mesh_ = std::make_shared<const Scene>(loadSceneMesh(truth_file));
      truth_ = std::make_shared<const MeshDistance>(*truth_mesh_, pool_);
      log(tr("ground truth loaded: points can be coloured by their error"));
    } catch (const std::exception& e) {
      log(tr("ground truth not used: %1").arg(describe(e)));
    }
  }
  updateColourChoices();
  if (!truth_) {
    accuracy_panel_->showNoGroundTruth();
  }
  for (const std::string& warning : mission_->warnings) {
    log(tr("note: %1").arg(QString::fromStdString(warning)));
  }
  setWindowTitle(tr("SonarCarve — %1").arg(QString::fromStdString(mission_->name)));
  raw_view_->setSonar(mission_->sonar);
  denoised_view_->setSonar(mission_->sonar);
  std::vector<double> times;
  std::vector<Eigen::Vector3d> sonar_track;
  const Eigen::Isometry3d T_vehicle_sonar = mission_->mounting.T_vehicle_sonar();
  for (const FrameRecord& f : mission_->frames) {
    times.push_back(f.time_s);
    if (mission_->nav.covers(f.time_s)) {
      sonar_track.push_back(mission_->nav.T_world_sonar(f.time_s, T_vehicle_sonar).translation());
    }
  }
  std::vector<widgets::TrackPoint> nav;
  for (const NavSample& s : mission_->nav.samples()) {
    nav.push_back({s.time_s, s.position_m});
  }
  track_view_->setTrack(std::move(nav));
  map_view_->clearMap();
  map_view_->setTrack(sonar_track);
  showIntensityUnit(false);
  timeline_->setFrameTimes(times);
  followParams();
  showFrame(0);
  addRecent(QString::fromStdString(mission_->folder.string()));
  log(tr("opened %1: %2 frames, sonar %3 (%4 beams x %5 bins)")
          .arg(QString::fromStdString(mission_->folder.string()))
          .arg(mission_->frames.size())
          .arg(QString::fromStdString(mission_->sonar.id()))
          .arg(mission_->sonar.cols())
          .arg(mission_->sonar.rows()));
  startRun();
  return true;
}

void MainWindow::readBeamWidth() {
  if (!mission_) {
    return;
  }
  const ReconstructionParams p = params_panel_->params();
  if (p.horizontal_beam_width_rad > 0.0 || mission_->sonar.horizontalBeamWidth() > 0.0) {
    return;  // given: nothing to read (updateDetector ignores a reading still under way)
  }
  // The frames a run with these parameters reads; read again only when they change, the last
  // width standing in meanwhile (the same sonar's).
  std::vector<std::size_t> frames = placedFrames(*mission_, p);
  if (beam_width_frames_ && *beam_width_frames_ == frames) {
    return;
  }
  beam_width_job_.discard();
  beam_width_frames_ = frames;
  log(tr("reading the beams' width from %1 of %2 frames (neither the mission nor the parameters "
         "give one)")
          .arg(std::min(frames.size(), kBeamWidthFrames))
          .arg(frames.size()));
  beam_width_job_.start(
      [mission = mission_, frames = std::move(frames)](JobContext& context) {
        return chooseBeamWidth(*mission, mission->sonar, frames, context);
      },
      [this](const BeamWidthChoice& choice) {
        read_beam_width_rad_ = choice.sonar.horizontalBeamWidth();
        log(tr("beams' width: %1").arg(QString::fromStdString(choice.reason)));
        updateDetector();
        showFrame(timeline_->currentFrame());
      },
      [this](const JobError& error) {
        log(tr("beams' width not read: %1").arg(error.message));  // a run reads it again
      });
}

void MainWindow::updateDetector() {
  detector_.reset();
  deblur_.reset();
  if (!mission_) {
    return;
  }
  const ReconstructionParams p = params_panel_->params();
  if (p.noise_model != noise_model_path_) {
    // A noise model is megabytes of YAML: a worker reads it, then the frame is redrawn.
    noise_model_.reset();
    noise_model_path_ = p.noise_model;
    noise_model_job_.discard();  // a model still loading for the previous path
    if (!p.noise_model.empty()) {
      noise_model_job_.start(
          [path = p.noise_model](JobContext&) {
            return std::make_shared<const NoiseModel>(NoiseModel::load(path));
          },
          [this](std::shared_ptr<const NoiseModel> model) {
            noise_model_ = std::move(model);
            updateDetector();
            showFrame(timeline_->currentFrame());
          },
          [this](const JobError& error) {
            log(tr("denoised view unavailable: %1").arg(error.message));
          });
      return;
    }
  }
  if (!p.noise_model.empty() && !noise_model_) {
    return;  // still loading
  }
  try {
    const SonarModel sonar = carvingSonar(*mission_, p);
    deblur_ = std::make_shared<const BearingDeblur>(
        sonar.horizontalBeamWidth() > 0.0 || !(read_beam_width_rad_ > 0.0)
            ? sonar
            : sonar.withHorizontalBeamWidth(read_beam_width_rad_));
    detector_ = std::make_shared<const Detector>(p.detector, viewNoiseModel(p), mission_->sonar);
  } catch (const std::exception& e) {
    log(tr("denoised view unavailable: %1").arg(describe(e)));
  }
}

DetectorMode MainWindow::denoisedViewDetector() const {
  return detector_ ? detector_->params().mode : DetectorMode::None;
}

std::shared_ptr<const NoiseModel> MainWindow::viewNoiseModel(const ReconstructionParams& p) const {
  if (!p.noise_model.empty()) {
    return noise_model_;
  }
  // The detector auto with no model: the one the last run learned from the mission's frames,
  // while it fits these parameters (a run learns another after a change of smoothing).
  const bool fits = run_noise_model_ && p.detector.mode == DetectorMode::Auto &&
                    run_noise_model_->smoothing() == p.detector.smoothing;
  return fits ? run_noise_model_ : nullptr;
}

void MainWindow::showFrame(int index) {
  if (!mission_ || index < 0 || static_cast<std::size_t>(index) >= mission_->frames.size()) {
    return;
  }
  // Reading and denoising a frame takes tens of milliseconds: a worker does it and the GUI
  // thread only draws the result, unless the user has asked for another frame since.
  frame_job_.start(
      [mission = mission_, detector = detector_, deblur = deblur_, index](JobContext&) {
        ShownFrame shown;
        shown.index = index;
        Frame frame = loadFrame(*mission, static_cast<std::size_t>(index));
        // Shown in the sonar's own counts (a decibel or gamma sonar's power would show only its
        // brightest returns), with the same window for the denoised view.
        const IntensityScale& scale = mission->sonar.intensityScale();
        shown.raw = scale.powerToCounts(frame.image);
        shown.range = widgets::displayRange(shown.raw);
        if (detector && deblur) {  // set together by updateDetector
          shown.denoised = scale.powerToCounts(denoiseFrame(*detector, *deblur, frame.image));
        }
        return shown;
      },
      [this](const ShownFrame& shown) { drawFrame(shown); },
      [this, index](const JobError& error) {
        raw_view_->clearFrame();
        denoised_view_->clearFrame();
        log(tr("frame %1: %2").arg(index).arg(error.message));
      });
}

void MainWindow::drawFrame(const ShownFrame& shown) {
  raw_view_->setFrame(shown.raw, shown.range.low, shown.range.high);
  if (!shown.denoised.empty()) {
    denoised_view_->setFrame(shown.denoised, shown.range.low, shown.range.high);
  } else {
    denoised_view_->clearFrame();
  }
  const double t = mission_->frames[static_cast<std::size_t>(shown.index)].time_s;
  track_view_->setCurrentTime(t);
  if (mission_->nav.covers(t)) {
    map_view_->setCurrentFrame(mission_->nav.T_world_sonar(t, mission_->mounting.T_vehicle_sonar()),
                               mission_->sonar,
                               shown.denoised.empty() ? shown.raw : shown.denoised);
  }
}

void MainWindow::setParams(const ReconstructionParams& params) {
  params_panel_->setParams(params);
  followParams();
}

void MainWindow::updateColourChoices() {
  auto* model = qobject_cast<QStandardItemModel*>(colour_by_->model());
  QStandardItem* error = model->item(static_cast<int>(widgets::MapView::ColourBy::Error));
  error->setEnabled(truth_ != nullptr);
  error->setToolTip(
      truth_ ? QString() : tr("needs the mission's ground truth (ground_truth.ply in its folder)"));
  if (!truth_ &&
      colour_by_->currentIndex() == static_cast<int>(widgets::MapView::ColourBy::Error)) {
    colour_by_->setCurrentIndex(static_cast<int>(widgets::MapView::ColourBy::Intensity));
  }
}

bool MainWindow::errorColouringAvailable() const {
  const auto* model = qobject_cast<const QStandardItemModel*>(colour_by_->model());
  return model->item(static_cast<int>(widgets::MapView::ColourBy::Error))->isEnabled();
}

void MainWindow::setColourBy(widgets::MapView::ColourBy by) {
  colour_by_->setCurrentIndex(static_cast<int>(by));
}

void MainWindow::followParams() {
  readBeamWidth();
  updateDetector();
}

void MainWindow::paramsEdited() {
  followParams();
  showFrame(timeline_->currentFrame());
  if (mission_) {
    log(tr("parameters changed: re-running"));
    startRun();
  }
}

void MainWindow::startRun() {
  if (!mission_) {
    showError(tr("Nothing to run"), tr("Open a mission first."));
    return;
  }
  ReconstructionParams params = params_panel_->params();
  try {
    params.validate();
  } catch (const std::exception& e) {
    showError(tr("Invalid parameters"), describe(e));
    return;
  }
  run_params_ = params;
  QSettings().setValue(paramsKey(mission_->folder), QString::fromStdString(params.toYaml()));
  // A re-run keeps the user's camera and frame; the map being carved shows until it ends.
  const CameraState camera = map_view_->cameraState();
  widgets::MapView::MapBlocks shown_map = map_view_->takeMap();
  map_view_->setVoxelSize(params.carve.voxel_size_m);
  map_view_->setLive(true);
  if (view_settled_) {
    map_view_->setCameraState(camera);
  }
  layer_->setCurrentIndex(0);
  releaseRun(std::move(shown_map));
  accuracy_job_.discard();  // of the run superseded
  choices_panel_->clear();
  if (truth_mesh_) {
    accuracy_panel_->showPending();
  }
  latest_carved_frame_ = -1;
  carve_started_done_ = -1;
  {
    const QSignalBlocker block(pause_action_);
    pause_action_->setChecked(false);
  }
  // The run's report scores the mission's ground truth itself: a ground truth the workbench
  // could not read (it said so in the log, and carries on without it) would fail the run, so
  // such a run writes no report.
  std::error_code ec;
  const bool truth_unreadable =
      !truth_ && std::filesystem::exists(mission_->folder / "ground_truth.ply", ec);
  QString report_folder;
  if (!truth_unreadable) {
    report_folder = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
                    "/runs/" + QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss-zzz");
  }
  run_report_ = report_folder.isEmpty() ? QString() : report_folder + "/report.html";
  runner_->start({mission_, params, truth_, map_view_->colourBy(), map_view_->clip(),
                  map_view_->mapPointBudget(), report_folder.toStdString()});
  map_view_->setCaption(
      tr("Carving: provisional; translucent voxels are still in view and may yet be carved "
         "away (ghosts in the beam's tails go as more views arrive)"));
  if (!view_settled_) {
    follow_timer_.start();  // the frame view follows the carving on a mission's first run
  }
  showProgress(*progress_bar_, progress_bar_->maximum(), 0, progress_bar_->format());
  progress_label_->setText(tr("carving…"));
  updateRunActions();
}

void MainWindow::chooseLayer(widgets::MapView::Layer layer) {
  preferred_layer_ = static_cast<int>(layer);
  layer_->setCurrentIndex(preferred_layer_);
}

void MainWindow::playRun() {
  if (runner_->running() && runner_->paused()) {
    setPaused(false);  // Play after Pause resumes where the run was held
    return;
  }
  startRun();
}

void MainWindow::cancelRun() {
  if (!runner_->running()) {
    return;
  }
  runner_->cancel();
  follow_timer_.stop();
  map_view_->setLive(false);
  {
    const QSignalBlocker block(pause_action_);
    pause_action_->setChecked(false);
  }
  log(tr("cancelled: the map shows what was carved so far"));
  map_view_->setCaption(tr("Cancelled: the map carved so far, not a finished result"));
  progress_label_->setText(tr("Cancelled"));
  updateRunActions();
}

void MainWindow::setPaused(bool paused) {
  runner_->setPaused(paused);
  {
    const QSignalBlocker block(pause_action_);
    pause_action_->setChecked(paused);
  }
  progress_label_->setText(paused ? tr("Paused") : tr("carving…"));
  updateRunActions();
}

void MainWindow::updateRunActions() {
  const bool running = runner_->running();
  run_action_->setEnabled(mission_ != nullptr);
  run_action_->setText(!running ? tr("Start") : runner_->paused() ? tr("Resume") : tr("Restart"));
  pause_action_->setEnabled(running);
  cancel_action_->setEnabled(running);
}

bool MainWindow::exportTo(Export kind, const QString& file) {
  const std::filesystem::path path = file.toStdString();
  try {
    if (kind == Export::ViewPng) {
      const QImage image = map_view_->grabImage();
      QByteArray bytes;
      QBuffer buffer(&bytes);
      buffer.open(QIODevice::WriteOnly);
      if (image.isNull() || !image.save(&buffer, "PNG")) {
        throw Error(path.string(), "", "could not render the 3D view");
      }
      writeFileAtomically(path,
                          std::string(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    } else {
      if (!result_) {
        throw Error(path.string(), "", "no finished reconstruction to export yet");
      }
      // The result is local to its mission's origin: the files say so (docs/conventions.md).
      const Eigen::Vector3d origin =
          mission_ ? mission_->origin_ned_m : Eigen::Vector3d::Zero().eval();
      const std::string crs = mission_ ? mission_->crs : std::string();
      switch (kind) {
        case Export::SurfacePly:
          writeSurfacePointsPly(result_->surface, path, origin, crs);
          break;
        case Export::MapBt:
          if (!result_->map) {
            throw Error(path.string(), "", "the reference engine keeps no map to export");
          }
          writeOccupancyBt(*result_->map, path, origin, crs);
          break;
        case Export::MeshPly:
        case Export::MeshStl: {
          DeliverableRequest request;
          request.options.format = kind == Export::MeshPly ? "ply" : "stl";
          request.options.mission_origin_ned_m = origin;
          request.options.mission_crs = crs;
          writeDeliverable(request, deliverableSource(), path);
          break;
        }
        case Export::ViewPng:
          break;
      }
    }
  } catch (const std::exception& e) {
    showError(tr("Export failed"), describe(e));
    return false;
  }
  log(tr("exported %1").arg(file));
  return true;
}

QPointer<QProgressDialog> MainWindow::jobProgressDialog(const QString& label) {
  auto* dialog = new QProgressDialog(label, tr("Cancel"), 0, 100, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->setMinimumDuration(500);
  return dialog;
}

BackgroundJob::ProgressHandler MainWindow::progressTo(QPointer<QProgressDialog> dialog) {
  return [dialog](const QString&, std::size_t done, std::size_t total) {
    if (dialog) {
      dialog->setValue(total > 0 ? static_cast<int>(100 * done / total) : 0);
    }
  };
}

void MainWindow::cancelJobFrom(QProgressDialog* dialog, BackgroundJob& job, int id) {
  connect(dialog, &QProgressDialog::canceled, this, [&job, id] {
    if (job.currentJob() == id) {
      job.cancel();
    }
  });
}

DeliverableSource MainWindow::deliverableSource() const {
  DeliverableSource source;
  if (result_) {
    source.mesh = &result_->mesh;
    source.points = &result_->surface;
    source.voxel_size_m = run_params_.carve.voxel_size_m;  // the run's (reset with result_)
  }
  return source;
}

ExportPlace MainWindow::exportPlace() const {
  ExportPlace place;
  if (mission_) {
    place.crs = mission_->crs;
    place.origin_ned_m = mission_->origin_ned_m;
  }
  place.has_mesh = result_ && !result_->mesh.triangles.empty();
  if (mission_) {  // beside the mission folder, named after it
    const std::filesystem::path folder =
        std::filesystem::absolute(mission_->folder).lexically_normal();
    const std::filesystem::path named = folder.has_filename() ? folder : folder.parent_path();
    place.file_stem = QString::fromStdString(named.string()) + "-map";
  }
  return place;
}

ExportDialog* MainWindow::openExportDialog() {
  if (!result_) {
    showError(tr("Nothing to export"), tr("No finished reconstruction to export yet."));
    return nullptr;
  }
  auto* dialog = new ExportDialog(exportPlace(), this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this,
          [this, dialog] { exportDeliverable(dialog->request(), dialog->file()); });
  dialog->open();
  return dialog;
}

void MainWindow::exportDeliverable(const DeliverableRequest& request, const QString& file) {
  if (!result_) {
    showError(tr("Export failed"), tr("%1: no finished reconstruction to export yet").arg(file));
    emit exportFinished(false);
    return;
  }
  if (export_dialog_) {
    export_dialog_->close();  // the export it showed is superseded below
  }
  const QPointer<QProgressDialog> shown = export_dialog_ =
      jobProgressDialog(tr("Exporting %1…").arg(QFileInfo(file).fileName()));
  const QString summary = QString::fromStdString(deliverableSummary(request));
  const int job = export_job_.start(
      // The result is held by the job: a run started meanwhile does not free it under it.
      [result = result_, source = deliverableSource(), request,
       path = std::filesystem::path(file.toStdString())](JobContext& progress) {
        writeDeliverable(request, source, path, &progress);
        return 0;
      },
      [this, shown, file, summary](int) {
        if (shown) {
          shown->close();
        }
        log(tr("exported %1 (%2)").arg(file, summary));
        emit exportFinished(true);
      },
      [this, shown, file](const JobError& error) {
        if (shown) {
          shown->close();
        }
        if (error.cancelled) {
          log(tr("export cancelled: %1 not written (a previous file is as it was)").arg(file));
        } else {
          showError(
              tr("Export failed"),
              tr("%1 was not written (a previous file is as it was): %2").arg(file, error.message));
        }
        emit exportFinished(false);
      },
      progressTo(shown));
  cancelJobFrom(shown, export_job_, job);
}

Session MainWindow::currentSession() const {
  Session s;
  s.mission = mission_ ? mission_->folder.string() : std::string();
  s.params = params_panel_->params();
  s.camera = map_view_->cameraState();
  s.frame = timeline_->currentFrame();
  s.colour_by =
      widgets::MapView::nameOf(static_cast<widgets::MapView::ColourBy>(colour_by_->currentIndex()));
  s.runs = runs_;
  return s;
}

bool MainWindow::saveSession(const QString& file) {
  try {
    sonarcarve::saveSession(currentSession(), file.toStdString());
  } catch (const std::exception& e) {
    showError(tr("Cannot save the session"), describe(e));
    return false;
  }
  log(tr("session saved to %1").arg(file));
  return true;
}

bool MainWindow::openSession(const QString& file) {
  Session s;
  try {
    s = sonarcarve::loadSession(file.toStdString());
  } catch (const std::exception& e) {
    showError(tr("Cannot open the session"), describe(e));
    return false;
  }
  params_panel_->setParams(s.params);  // followed by the mission it opens, not the one open
  if (!openMissionWith(QString::fromStdString(s.mission), false)) {
    followParams();  // the mission still open takes them
    return false;
  }
  map_view_->setCameraState(s.camera);
  view_settled_ = true;  // the session's view, kept by the run it starts
  runs_ = s.runs;        // the run the session starts adds to its history
  history_panel_->setRuns(runs_);
  setColourBy(widgets::MapView::colourByNamed(s.colour_by));
  timeline_->setCurrentFrame(s.frame);
  follow_action_->setChecked(false);  // keep the saved frame in view
  addRecent(file);
  return true;
}

bool MainWindow::loadParams(const QString& file) {
  try {
    setParams(ReconstructionParams::fromYamlFile(file.toStdString()));
  } catch (const std::exception& e) {
    showError(tr("Cannot load the parameters"), describe(e));
    return false;
  }
  log(tr("parameters loaded from %1").arg(file));
  paramsEdited();
  return true;
}

bool MainWindow::saveParams(const QString& file) {
  try {
    writeFileAtomically(file.toStdString(), params_panel_->params().toYaml());
  } catch (const std::exception& e) {
    showError(tr("Cannot save the parameters"), describe(e));
    return false;
  }
  log(tr("parameters saved to %1 (sonarcarve-cli reconstruct --params reads it)").arg(file));
  return true;
}

void MainWindow::addRecent(const QString& path) {
  QSettings settings;
  QStringList recent = settings.value("recent").toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > kMaxRecent) {
    recent.removeLast();
  }
  settings.setValue("recent", recent);
  fillRecentMenu();
}

void MainWindow::fillRecentMenu() {
  recent_menu_->clear();
  const QStringList recent = QSettings().value("recent").toStringList();
  for (const QString& path : recent) {
    recent_menu_->addAction(path, this, [this, path] { openPath(path); });
  }
  recent_menu_->setEnabled(!recent.isEmpty());
}

void MainWindow::importWithDialog(const QString& log) {
  ImportDialog dialog(log, this);
  if (dialog.exec() != QDialog::Accepted) {
    return;
  }
  try {
    importLog(dialog.request());
  } catch (const std::exception& e) {
    showError(tr("Cannot import"), describe(e));
  }
}

void MainWindow::learnNoiseModel(const QString& empty_water, const QString& out_file) {
  const QPointer<QProgressDialog> shown = jobProgressDialog(
      tr("Learning the noise model from %1…").arg(QFileInfo(empty_water).fileName()));
  const std::filesystem::path in = empty_water.toStdString();
  const std::filesystem::path out = out_file.toStdString();
  const int smoothing = params_panel_->params().detector.smoothing;
  log(tr("learning a noise model from %1 (smoothing %2)").arg(empty_water).arg(smoothing));
  const int job = learn_job_.start(
      [in, out, smoothing](JobContext& progress) {
        const Mission empty = sonarcarve::openMission(in, OpenOptions{});
        const NoiseModel model = NoiseModel::learn(empty, progress, nullptr, smoothing);
        model.save(out);
        return model.frames();
      },
      [this, shown, out_file](int frames) {
        if (shown) {
          shown->close();
        }
        log(tr("noise model of %1 empty-water frames written to %2").arg(frames).arg(out_file));
        ReconstructionParams params = params_panel_->params();
        params.noise_model = out_file.toStdString();
        setParams(params);
        if (mission_) {
          paramsEdited();
        }
        emit noiseModelLearned(true);
      },
      [this, shown](const JobError& error) {
        if (shown) {
          shown->close();
        }
        if (error.cancelled) {
          log(tr("learning the noise model cancelled: nothing written"));
        } else {
          showError(tr("Cannot learn the noise model"), error.message);
        }
        emit noiseModelLearned(false);
      },
      progressTo(shown));
  cancelJobFrom(shown, learn_job_, job);
}

void MainWindow::importLog(const ImportRequest& request) {
  if (import_dialog_) {
    import_dialog_->close();  // the import it showed is superseded below
  }
  import_dialog_ = jobProgressDialog(
      tr("Importing %1…").arg(QString::fromStdString(request.log.filename().string())));
  log(tr("importing %1 into %2")
          .arg(QString::fromStdString(request.log.string()),
               QString::fromStdString(request.out.string())));
  const int job = import_job_.start(
      [request](JobContext& progress) { return importOculusToMission(request, progress); },
      [this, dialog = import_dialog_](const ImportReport& report) {
        if (dialog) {
          dialog->close();
        }
        log(tr("imported %1 frames of %2 pings (%3)")
                .arg(report.frames_written)
                .arg(report.pings_in_log)
                .arg(QString::fromStdString(report.container)));
        for (const auto& lines : {report.warnings, report.problems, report.notes}) {
          for (const std::string& line : lines) {
            log(QString::fromStdString(line));
          }
        }
        const bool ok = openMission(QString::fromStdString(report.mission.string()));
        emit importFinished(ok);
      },
      [this, dialog = import_dialog_](const JobError& error) {
        if (error.cancelled) {
          log(tr("import cancelled: the folder has no mission.yaml and is not a mission"));
        } else {
          if (dialog) {
            dialog->close();
          }
          showError(tr("Cannot import the log"), error.message);
        }
        emit importFinished(false);
      },
      progressTo(import_dialog_));
  cancelJobFrom(import_dialog_, import_job_, job);
}

void MainWindow::openPath(const QString& path) {
  if (path.endsWith(".sonarcarve") || looksLikeSessionFile(path.toStdString())) {
    openSession(path);
  } else {
    openMission(path);
  }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) {
    event->acceptProposedAction();
  }
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.isEmpty()) {
    return;
  }
  openPath(urls.front().toLocalFile());
  event->acceptProposedAction();
}

void MainWindow::recordRun(const ReconstructionResult& result) {
  RunRecord run;
  run.started = QDateTime::currentDateTime()
                    .addMSecs(-static_cast<qint64>(1000.0 * result.total_s))
                    .toString("yyyy-MM-dd HH:mm:ss")
                    .toStdString();
  run.params = run_params_;
  run.frames = result.frames_used;
  run.occupied_voxels = result.occupied_voxels;
  run.surface_points = result.surface.size();
  run.mesh_triangles = result.mesh.triangles.size();
  run.seconds = result.total_s;
  run.report = run_report_.toStdString();
  runs_.push_back(run);
  history_panel_->setRuns(runs_);
}

void MainWindow::measureAccuracy(std::shared_ptr<const std::vector<Eigen::Vector3f>> points) {
  if (!truth_mesh_ || points->empty()) {
    accuracy_panel_->showNoGroundTruth();
    return;
  }
  accuracy_panel_->showEvaluating();
  // Sampling the truth and measuring both ways takes a second or more: on a worker.
  const std::size_t run = runs_.size() - 1;
  accuracy_job_.start(
      // The points, not the result: the worker must not keep the run's map alive.
      [this, truth = truth_mesh_, folder = mission_->folder, points](JobContext&) {
        std::error_code ec;
        const auto visible_file = folder / "visible_points.ply";
        std::vector<Eigen::Vector3f> visible;
        if (std::filesystem::exists(visible_file, ec)) {
          visible = readPointsPly(visible_file);
        }
        return evaluate(*points, *truth, std::move(visible), pool_);
      },
      [this, run](const EvaluationResult& evaluation) {
        accuracy_panel_->showResult(evaluation);
        if (run < runs_.size()) {
          runs_[run].accuracy =
              RunAccuracy{evaluation.fscore, evaluation.accuracy_median_m,
                          evaluation.accuracy_p90_m, evaluation.precision, evaluation.completeness};
          history_panel_->setRuns(runs_);
        }
        log(tr("accuracy against the ground truth: F-score %1 at 5 cm, median %2 cm, "
               "completeness %3 %")
                .arg(evaluation.fscore, 0, 'f', 3)
                .arg(100.0 * evaluation.accuracy_median_m, 0, 'f', 2)
                .arg(100.0 * evaluation.completeness, 0, 'f', 1));
        emit accuracyMeasured(evaluation.fscore);
      },
      [this](const JobError& error) {
        accuracy_panel_->showNoGroundTruth();
        log(tr("accuracy not measured: %1").arg(error.message));
      });
}

void MainWindow::releaseRun(widgets::MapView::MapBlocks shown_map) {
  // The run's map (the carver's blocks) and the 3D view's copy of its occupied voxels: freeing
  // them at a re-run's start took the GUI thread 130 to 200 ms on the riser demo (perf: glibc
  // merging its free lists; see allocator.h). A worker frees them (the result only if nothing
  // else holds it).
  release_job_.start(
      [result = std::move(result_), map = std::move(shown_map)](JobContext&) mutable {
        result.reset();
        map.clear();
        return 0;
      },
      [](int) {}, [](const JobError&) {});
  result_.reset();
}

void MainWindow::goBackToRun(int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= runs_.size()) {
    return;
  }
  log(tr("back to run %1's parameters (%2)")
          .arg(index + 1)
          .arg(QString::fromStdString(runs_[static_cast<std::size_t>(index)].started)));
  setParams(runs_[static_cast<std::size_t>(index)].params);
  paramsEdited();
}

void MainWindow::editClip() {
  auto* dialog = new widgets::ClipDialog(map_view_->clip(), map_view_->dataBounds(), this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    map_view_->setClip(dialog->clip());
    const widgets::ViewClip& clip = map_view_->clip();
    log(clip.active() ? tr("3D view clipped: %1 points drawn").arg(map_view_->drawnPointCount())
                      : tr("3D view: everything drawn"));
  });
  dialog->open();
}

void MainWindow::closeEvent(QCloseEvent* event) {
  runner_->cancel();
  event->accept();
}

}  // namespace sonarcarve::gui
