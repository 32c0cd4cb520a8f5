// The workbench as an analyst drives it, under Xvfb: open the demo scene's mission, run to the
// end and get the CLI's map; pause, cancel and carry on; a parameter change supersedes the
// running job; a broken mission gives a message and the window stays usable; sessions and
// exports round-trip.
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTreeWidget>
#include <QtTest>
#include <functional>
#include <set>

#include "accuracy_panel.h"
#include "common/angles.h"
#include "eval/evaluator.h"
#include "frame_timeline.h"
#include "geometry/scene_io.h"
#include "gui_conventions.h"
#include "io/mesh/point_cloud_ply.h"
#include "main_window.h"
#include "map_view.h"
#include "occlusion/surface_points.h"
#include "params_panel.h"
#include "pipeline/reconstruction.h"
#include "run_choices_panel.h"
#include "run_history_panel.h"
#include "session/session_file.h"
#include "sim/demo_scenes.h"
#include "sim/simulation_run.h"
#include "support/cli_runner.h"
#include "support/test_support.h"
#include "vtk_gl_widget.h"

using sonarcarve::ReconstructionResult;
using sonarcarve::gui::MainWindow;
namespace fs = std::filesystem;

namespace {

using PointSet = std::set<std::tuple<float, float, float>>;

PointSet pointSet(const std::vector<Eigen::Vector3f>& points) {
  PointSet s;
  for (const auto& p : points) {
    s.insert({p.x(), p.y(), p.z()});
  }
  return s;
}

std::shared_ptr<const ReconstructionResult> waitForResult(MainWindow& window, int timeout_ms) {
  QSignalSpy finished(&window, &MainWindow::runFinished);
  if (!finished.wait(timeout_ms)) {
    return nullptr;
  }
  return finished.front().front().value<std::shared_ptr<const ReconstructionResult>>();
}

// The riser demo scene on the paper's clipped beam: `frames` frames, with `noise`, of the
// structure or of empty water, into `out`.
void simulateRiser(const fs::path& out, const sonarcarve::NoiseSpec& noise, bool empty_water,
                   int frames) {
  sonarcarve::SimulationRequest request{sonarcarve::makeDemoScene("riser"),
                                        "riser",
                                        sonarcarve::test::paperSonar(),
                                        sonarcarve::TrajectorySpec{},
                                        sonarcarve::test::clippedBeam(),
                                        noise,
                                        sonarcarve::NavErrorSpec{},
                                        empty_water,
                                        frames,
                                        out};
  sonarcarve::SilentProgress progress;
  sonarcarve::ThreadPool pool;
  sonarcarve::runSimulation(request, progress, pool);
}

}  // namespace

Q_DECLARE_METATYPE(std::shared_ptr<const sonarcarve::ReconstructionResult>)

class WorkbenchTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    qRegisterMetaType<std::shared_ptr<const ReconstructionResult>>();
    scratch_ = std::make_unique<sonarcarve::test::ScratchDir>();
    simulateRiser(mission(), sonarcarve::NoiseSpec::none(), false, 24);
  }

  // The demo scene's mission, run to the end: the map the GUI shows and the surface it exports
  // are the CLI's for the same parameters file.
  void runToTheEndEqualsTheCli() {
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    const auto result = waitForResult(window, 120000);
    QVERIFY(result);
    QCOMPARE(result->frames_used, std::size_t{24});
    window.mapView().flush();
    // What the view shows is the carved map, voxel for voxel.
    std::vector<Eigen::Vector3f> carved;
    result->map->forEachOccupied([&](const Eigen::Vector3i& v, float) {
      carved.push_back(result->map->voxelCentre(v).cast<float>());
    });
    QCOMPARE(window.mapView().mapPointCount(), carved.size());
    QVERIFY(pointSet(window.mapView().mapPoints()) == pointSet(carved));

    const fs::path params = scratch_->path() / "gui_params.yaml";
    const fs::path gui_points = scratch_->path() / "gui_surface.ply";
    QVERIFY(window.saveParams(QString::fromStdString(params.string())));
    QVERIFY(window.exportTo(MainWindow::Export::SurfacePly,
                            QString::fromStdString(gui_points.string())));
    const fs::path cli_out = scratch_->path() / "cli";
    const auto run = sonarcarve::test::runCli("reconstruct " + sonarcarve::test::quoted(mission()) +
                                              " --params " + sonarcarve::test::quoted(params) +
                                              " --out " + sonarcarve::test::quoted(cli_out));
    QVERIFY2(run.exit_code == 0, run.output.c_str());
    const auto cli = sonarcarve::readPointCloudPly(cli_out / "surface_points.ply");
    const auto gui = sonarcarve::readPointCloudPly(gui_points);
    QVERIFY(cli.positions.size() > 500);
    QCOMPARE(gui.positions.size(), cli.positions.size());
    QVERIFY(pointSet(gui.positions) == pointSet(cli.positions));
    QVERIFY(run.output.find("\"occupied_voxels\": " + std::to_string(carved.size())) !=
            std::string::npos);

    // The run's automatic choices: the same line in the log as the CLI prints, a row each in
    // the Choices panel, and a click on a row opens how it was derived.
    QVERIFY(result->choices.size() >= 4);
    for (const sonarcarve::RunChoice& choice : result->choices) {
      const std::string line = sonarcarve::choiceLine(choice);
      QVERIFY2(window.logText().contains(QString::fromStdString(line)), line.c_str());
      QVERIFY2(run.output.find(line) != std::string::npos, line.c_str());
    }
    auto& choices = window.choicesPanel();
    QCOMPARE(choices.rowCount(), static_cast<int>(result->choices.size()));
    auto* dock = qobject_cast<QDockWidget*>(choices.parentWidget());
    QVERIFY(dock);
    dock->raise();  // a tab beside Accuracy
    QTRY_VERIFY(choices.tree()->isVisible());
    QTreeWidgetItem* first = choices.tree()->topLevelItem(0);
    QVERIFY(!first->isExpanded());
    const QRect row = choices.tree()->visualItemRect(first);
    QTest::mouseClick(choices.tree()->viewport(), Qt::LeftButton, {}, row.center());
    QVERIFY(first->isExpanded());
    QCOMPARE(first->child(0)->text(2), QString::fromStdString(result->choices.front().detail));
  }

  // Pause holds the run mid-way; cancel stops it and the window carries on: a new run
  // finishes.
  void pauseAndCancelLeaveTheAppUsable() {
    MainWindow window;
    window.show();
    QSignalSpy progressed(&window.runner(), &sonarcarve::gui::ReconstructionRunner::progressed);
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    window.setPaused(true);
    QTest::qWait(300);
    QVERIFY(window.runner().running());
    const int reports = static_cast<int>(progressed.count());
    QTest::qWait(300);
    QCOMPARE(static_cast<int>(progressed.count()), reports);  // held while paused
    QVERIFY(window.mapView().caption().contains("provisional"));
    window.cancelRun();
    QVERIFY(!window.runner().running());
    QVERIFY(!window.lastResult());
    QVERIFY(window.mapView().caption().startsWith("Cancelled"));
    window.startRun();
    const auto result = waitForResult(window, 120000);
    QVERIFY(result);
    QVERIFY(!result->cancelled);
    QCOMPARE(result->frames_used, std::size_t{24});
    QVERIFY(window.mapView().caption().isEmpty());  // a finished result is the map itself
  }

  // Changing a parameter while a run is going cancels it and runs again with the new value:
  // only the new run's result arrives.
  void parameterChangeSupersedesTheRunningJob() {
    MainWindow window;
    window.show();
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    window.setPaused(true);  // the first run is certainly still going
    const int first_job = window.runner().currentJob();
    window.paramsPanel().voxelSize()->setValue(4.0);  // cm, as the user types it
    QVERIFY(QTest::qWaitFor([&] { return window.runner().currentJob() != first_job; }, 5000));
    QVERIFY(finished.wait(120000));
    QTest::qWait(200);
    QCOMPARE(finished.count(), 1);
    const auto result = window.lastResult();
    QVERIFY(result && result->map);
    QCOMPARE(result->map->voxelSize(), 0.04);
    QVERIFY(!result->cancelled);
  }

  void brokenMissionShowsAnErrorAndTheWindowStaysOpen() {
    MainWindow window;
    window.show();
    const fs::path broken = scratch_->path() / "broken";
    fs::create_directories(broken);
    sonarcarve::test::writeText(broken / "mission.yaml", "format: sonarcarve-mission\nversion: [");
    QVERIFY(!window.openMission(QString::fromStdString(broken.string())));
    auto* box = window.findChild<QMessageBox*>("errorMessage");
    QVERIFY(box);
    QVERIFY(box->isVisible());
    QVERIFY(box->text().contains("mission.yaml"));
    QVERIFY(window.logText().contains("mission.yaml"));
    box->accept();
    QVERIFY(!window.openMission(QString::fromStdString((scratch_->path() / "nowhere").string())));
    QVERIFY(window.isVisible());
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QVERIFY(waitForResult(window, 120000));
  }

  // Inputs of the bad-input catalogue (docs/reliability.md) through the workbench: a message
  // naming the file and what was expected, never a crash.
  void badInputsGiveAMessageNeverACrash() {
    MainWindow window;
    window.show();
    const fs::path bad_nav = sonarcarve::test::copyExampleMission(scratch_->path(), "bad-nav");
    fs::remove(bad_nav / "nav.csv");
    fs::create_directories(bad_nav / "nav.csv");
    QVERIFY(!window.openMission(QString::fromStdString(bad_nav.string())));
    auto* box = window.findChild<QMessageBox*>("errorMessage");
    QVERIFY(box && box->isVisible());
    QVERIFY2(box->text().contains("nav.csv: is a directory: expected a regular file"),
             qPrintable(box->text()));
    box->accept();
    // A ground truth whose face names a vertex that does not exist: VTK's filters read past
    // the points with it; the workbench says so and carries on without it.
    const fs::path bad_truth = sonarcarve::test::copyExampleMission(scratch_->path(), "bad-truth");
    sonarcarve::test::writeText(bad_truth / "ground_truth.ply",
                                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    QVERIFY(window.openMission(QString::fromStdString(bad_truth.string())));
    QVERIFY2(window.logText().contains("ground_truth.ply: face 0: vertex index 7 out of range"),
             qPrintable(window.logText()));
    QVERIFY(waitForResult(window, 120000));
    QVERIFY(window.isVisible());
  }

  // More of the catalogue's inputs (docs/reliability.md), as the workbench meets them: each
  // open fails with a dialog that names the file and what was expected, and the window stays.
  void catalogueInputsGiveADialogNamingTheFile() {
    MainWindow window;
    window.show();
    struct Case {
      std::string name;
      std::function<void(const fs::path&)> spoil;  // applied to a copy of the example mission
      bool session = false;                        // open <copy>/s.sonarcarve instead
      QStringList fragments;
    };
    const auto replace = [](const fs::path& file, const std::string& from, const std::string& to) {
      std::string text = sonarcarve::test::readText(file);
      text.replace(text.find(from), from.size(), to);
      sonarcarve::test::writeText(file, text);
    };
    const std::vector<Case> cases = {
        {"nan-nav",
         [&](const fs::path& m) { replace(m / "nav.csv", "99.75,0,0", "99.75,nan,0"); },
         false,
         {"nav.csv", "line 2"}},
        {"frame-outside",
         [&](const fs::path& m) {
           replace(m / "frames.csv", "frames/000000.png", "../000000.png");
         },
         false,
         {"frames.csv", "outside"}},
        {"empty-yaml",
         [](const fs::path& m) { sonarcarve::test::writeText(m / "mission.yaml", ""); },
         false,
         {"mission.yaml"}},
        {"binary-session",
         [](const fs::path& m) {
           sonarcarve::test::writeText(m / "s.sonarcarve",
                                       std::string("\x89PNG\r\n\x1a\n\0\0", 10));
         },
         true,
         {"s.sonarcarve"}},
        {"session-bad-params",
         [](const fs::path& m) {
           sonarcarve::test::writeText(m / "s.sonarcarve",
                                       "format: sonarcarve-session\nversion: 1\nmission: " +
                                           m.string() + "\nparams: {voxel_size_m: -1}\n");
         },
         true,
         {"s.sonarcarve", "voxel_size_m"}},
    };
    for (const Case& c : cases) {
      const fs::path m = sonarcarve::test::copyExampleMission(scratch_->path(), c.name);
      c.spoil(m);
      const QString target = QString::fromStdString((c.session ? m / "s.sonarcarve" : m).string());
      QVERIFY2(!(c.session ? window.openSession(target) : window.openMission(target)),
               c.name.c_str());
      QMessageBox* box = nullptr;  // the one shown now (an accepted one is deleted later)
      for (auto* b : window.findChildren<QMessageBox*>("errorMessage")) {
        box = b->isVisible() ? b : box;
      }
      QVERIFY2(box != nullptr, c.name.c_str());
      for (const QString& f : c.fragments) {
        QVERIFY2(box->text().contains(f), qPrintable(QString::fromStdString(c.name) + ": '" + f +
                                                     "' not in: " + box->text()));
      }
      box->accept();
      QVERIFY(window.isVisible());
    }
  }

  void sessionRestoresMissionParametersAndCamera() {
    const fs::path file = scratch_->path() / "s.sonarcarve";
    sonarcarve::widgets::CameraState camera;
    {
      MainWindow window;
      window.show();
      QVERIFY(window.openMission(QString::fromStdString(mission().string())));
      QVERIFY(waitForResult(window, 120000));
      auto p = window.paramsPanel().params();
      p.detector.z = 3.5;
      p.stride = 2;
      window.setParams(p);
      window.mapView().viewFromTop();
      camera = window.mapView().cameraState();
      QVERIFY(window.saveSession(QString::fromStdString(file.string())));
      window.runner().cancel();
    }
    MainWindow window;
    window.show();
    QVERIFY(window.openSession(QString::fromStdString(file.string())));
    QCOMPARE(window.paramsPanel().params().detector.z, 3.5);
    QCOMPARE(window.paramsPanel().params().stride, std::size_t{2});
    QVERIFY(window.mapView().cameraState().position.isApprox(camera.position, 1e-9));
    QVERIFY(window.mapView().cameraState().view_up.isApprox(camera.view_up, 1e-9));
    const auto result = waitForResult(window, 120000);
    QVERIFY(result);
    QCOMPARE(result->frames_used, std::size_t{12});  // stride 2 of 24
    // Exports of the restored run: a 3D view picture and the map, written in place.
    const fs::path png = scratch_->path() / "view.png";
    QVERIFY(window.exportTo(MainWindow::Export::ViewPng, QString::fromStdString(png.string())));
    QImage image(QString::fromStdString(png.string()));
    QVERIFY(!image.isNull());
    QVERIFY(image.width() > 100);
    const fs::path bt = scratch_->path() / "map.bt";
    QVERIFY(window.exportTo(MainWindow::Export::MapBt, QString::fromStdString(bt.string())));
    QVERIFY(fs::file_size(bt) > 100);
    // A failed export leaves the previous file as it was.
    const auto before = fs::file_size(bt);
    QVERIFY(!window.exportTo(
        MainWindow::Export::MapBt,
        QString::fromStdString((scratch_->path() / "no" / "dir" / "m.bt").string())));
    QCOMPARE(fs::file_size(bt), before);
  }

  // File > Open recording opens a recording file in place, as the command line does: the ARIS
  // fixture and a ROS 2 bag (one .mcap file), each with the frames and sonar it holds.
  void recordingsOpenInPlace() {
    MainWindow window;
    window.show();
    const fs::path aris = fs::path(SONARCARVE_TEST_DATA_DIR) / "aris" / "sample.aris";
    QVERIFY(window.openMission(QString::fromStdString(aris.string())));
    QCOMPARE(window.mission()->frames.size(), std::size_t{6});
    QCOMPARE(window.mission()->sonar.cols(), 48);
    QCOMPARE(window.mission()->sonar.rows(), 2000);
    const fs::path bag = scratch_->path() / "bag";
    const auto sim =
        sonarcarve::test::runCli("simulate --scene riser --max-frames 3 --format mcap --out " +
                                 sonarcarve::test::quoted(bag));
    QVERIFY2(sim.exit_code == 0, sim.output.c_str());
    QVERIFY(window.openMission(QString::fromStdString((bag / "mission.mcap").string())));
    QCOMPARE(window.mission()->frames.size(), std::size_t{3});
    QCOMPARE(window.mission()->sonar.cols(), 650);
  }

  // A vendor log is imported on a worker thread, then opened like any mission.
  void oculusLogIsImportedAndOpened() {
    MainWindow window;
    window.show();
    QSignalSpy imported(&window, &MainWindow::importFinished);
    sonarcarve::ImportRequest request;
    request.log = fs::path(SONARCARVE_TEST_DATA_DIR) / "oculus" / "one_ping_8bit.raw";
    request.out = scratch_->path() / "oculus-mission";
    window.importLog(request);
    QVERIFY(imported.wait(60000));
    QCOMPARE(imported.front().front().toBool(), true);
    QVERIFY(window.mission());
    QCOMPARE(window.mission()->frames.size(), std::size_t{1});
    QCOMPARE(window.mission()->sonar.cols(), 256);
    QCOMPARE(window.mission()->sonar.rows(), 703);
    QVERIFY(window.logText().contains("stationary"));
    // A file that is no Oculus log: a message, and the window carries on.
    const fs::path junk = scratch_->path() / "junk.raw";
    sonarcarve::test::writeText(junk, "not a sonar log");
    request.log = junk;
    request.out = scratch_->path() / "junk-mission";
    window.importLog(request);
    QVERIFY(imported.wait(60000));
    QCOMPARE(imported.back().front().toBool(), false);
    QVERIFY(window.logText().contains("junk.raw"));
    QCOMPARE(window.mission()->frames.size(), std::size_t{1});  // the open mission stays
  }

  // Keys drive the frames and the view; the Help menu lists every shortcut from the menus.
  void keysDriveTheFramesAndTheHelpListsThem() {
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QVERIFY(waitForResult(window, 120000));  // the run no longer moves the timeline
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.timeline().setCurrentFrame(3);
    QTest::keyClick(&window, Qt::Key_Right);
    QCOMPARE(window.timeline().currentFrame(), 4);
    QTest::keyClick(&window, Qt::Key_Left);
    QTest::keyClick(&window, Qt::Key_Left);
    QCOMPARE(window.timeline().currentFrame(), 2);
    QTest::keyClick(&window, Qt::Key_Space);
    QVERIFY(window.timeline().playing());
    QTest::keyClick(&window, Qt::Key_Space);
    QVERIFY(!window.timeline().playing());
    const QString shortcuts = sonarcarve::gui::shortcutList(*window.menuBar());
    for (const char* line : {"Frames > Play / pause: Space", "Frames > Next frame: Right",
                             "Run > Start: F5", "View > Fit (reset the view): Home",
                             "Help > User guide: F1", "File > Save session: Ctrl+S"}) {
      QVERIFY2(shortcuts.contains(line), qPrintable(shortcuts));
    }
  }

  // Play after Pause resumes the held run where it was; it does not start it again.
  void playAfterPauseResumes() {
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QSignalSpy carved(&window.runner(), &sonarcarve::gui::ReconstructionRunner::frameCarved);
    QVERIFY(carved.wait(60000));
    window.setPaused(true);
    QTest::qWait(200);
    const int job = window.runner().currentJob();
    const auto held = carved.count();
    window.playRun();  // the toolbar's Play (Run > Resume)
    QVERIFY(!window.runner().paused());
    QCOMPARE(window.runner().currentJob(), job);
    QVERIFY(waitForResult(window, 120000));
    // Resumed: the frames carved before the pause are not carved again.
    QCOMPARE(static_cast<std::size_t>(carved.count()), std::size_t{24});
    QVERIFY(held >= 1);
  }

  // A re-run (a parameter changed) keeps what the user set: the camera, the frame shown and
  // the layer chosen.
  void rerunKeepsTheCameraTheFrameAndTheLayer() {
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QVERIFY(waitForResult(window, 120000));
    QCOMPARE(window.mapView().layer(), sonarcarve::widgets::MapView::Layer::Surface);
    window.chooseLayer(sonarcarve::widgets::MapView::Layer::Mesh);
    sonarcarve::CameraState camera = window.mapView().cameraState();
    camera.position += Eigen::Vector3d(1.0, -2.0, 0.5);
    window.mapView().setCameraState(camera);
    window.timeline().setCurrentFrame(5);
    window.paramsPanel().voxelSize()->setValue(3.0);  // cm: a re-run
    QVERIFY(waitForResult(window, 120000));
    QCOMPARE(window.lastResult()->map->voxelSize(), 0.03);
    QCOMPARE(window.mapView().layer(), sonarcarve::widgets::MapView::Layer::Mesh);
    QVERIFY((window.mapView().cameraState().position - camera.position).norm() < 1e-9);
    QCOMPARE(window.timeline().currentFrame(), 5);
  }

  // A mission opened after another starts from its own last parameters or the defaults (the
  // noise model among them), and says so.
  void aSecondMissionStartsFromItsOwnParameters() {
    QSettings().remove("mission_params");
    MainWindow window;
    window.show();
    sonarcarve::ReconstructionParams tuned;
    tuned.carve.voxel_size_m = 0.035;
    window.setParams(tuned);  // the first mission opened takes the parameters as set
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QVERIFY(waitForResult(window, 120000));
    QCOMPARE(window.lastResult()->map->voxelSize(), 0.035);

    QVERIFY(
        window.openMission(QString::fromStdString(sonarcarve::test::exampleMission().string())));
    QCOMPARE(window.paramsPanel().params().carve.voxel_size_m,
             sonarcarve::ReconstructionParams{}.carve.voxel_size_m);
    QVERIFY(window.paramsPanel().params().noise_model.empty());
    QVERIFY(window.logText().contains("parameters: the defaults"));
    QVERIFY(waitForResult(window, 120000));

    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QCOMPARE(window.paramsPanel().params().carve.voxel_size_m, 0.035);
    QVERIFY(window.logText().contains("parameters: this mission's own"));
    QVERIFY(waitForResult(window, 120000));
  }

  // A mission that does not give its beams' width: the workbench reads it for the denoised
  // view from the frames a run reads, again only when those change, and never when the analyst
  // gives the width; the log says what it reads and what it found.
  void beamWidthIsReadOnlyWhenNobodyGivesIt() {
    const QString reading = "reading the beams' width";
    MainWindow window;
    window.show();
    sonarcarve::ReconstructionParams given;
    given.horizontal_beam_width_rad = sonarcarve::degToRad(0.4);
    window.setParams(given);
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QVERIFY(waitForResult(window, 120000));
    QVERIFY2(!window.logText().contains(reading), qPrintable(window.logText()));

    window.setParams(sonarcarve::ReconstructionParams{});  // the analyst clears the width
    QCOMPARE(window.logText().count(reading), 1);
    QVERIFY(window.logText().contains(reading + " from 24 of 24 frames"));
    QTRY_VERIFY_WITH_TIMEOUT(window.logText().contains("beams' width: "), 60000);
    QSignalSpy edited(&window.paramsPanel(), &sonarcarve::widgets::ParamsPanel::paramsEdited);
    window.paramsPanel().voxelSize()->setValue(4.0);  // the same frames: nothing to read again
    QVERIFY(edited.wait(5000));
    QCOMPARE(window.logText().count(reading), 1);
    sonarcarve::ReconstructionParams every_other;
    every_other.stride = 2;
    window.setParams(every_other);
    QVERIFY(window.logText().contains(reading + " from 12 of 12 frames"));
    window.setParams(given);
    window.setParams(every_other);  // given, then cleared again: the same frames, read already
    QCOMPARE(window.logText().count(reading), 2);
    QVERIFY(waitForResult(window, 120000));
  }

  // A noisy mission opened with no options: the run learns the noise from the mission's own
  // frames, and the denoised view runs the Z-test with that model instead of showing the
  // speckle as it is; after a change of smoothing the model no longer fits until a run learns
  // another.
  void denoisedViewUsesTheModelTheRunLearned() {
    const fs::path noisy = scratch_->path() / "noisy";
    simulateRiser(noisy, sonarcarve::NoiseSpec{}, false, 8);
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(noisy.string())));
    QVERIFY(window.denoisedViewDetector() == sonarcarve::DetectorMode::None);  // nothing learned
    const auto result = waitForResult(window, 120000);
    QVERIFY(result);
    QCOMPARE(QString::fromStdString(result->detector), QString("ztest"));
    QVERIFY(window.denoisedViewDetector() == sonarcarve::DetectorMode::ZTest);
    QVERIFY2(window.logText().contains("denoised view: the Z-test with the noise model the run "
                                       "learned"),
             qPrintable(window.logText()));
    sonarcarve::ReconstructionParams other_smoothing = window.paramsPanel().params();
    other_smoothing.detector.smoothing = 1;
    window.setParams(other_smoothing);
    QVERIFY(window.denoisedViewDetector() == sonarcarve::DetectorMode::None);
    // Back to the learned model's smoothing: the view takes it again.
    window.setParams(sonarcarve::ReconstructionParams{});
    QVERIFY(window.denoisedViewDetector() == sonarcarve::DetectorMode::ZTest);
    // Another mission: the model learned from this one's frames is not its.
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QVERIFY(window.denoisedViewDetector() == sonarcarve::DetectorMode::None);
    QVERIFY(waitForResult(window, 120000));
    QVERIFY(window.denoisedViewDetector() == sonarcarve::DetectorMode::None);  // noise-free
  }

  // File > Learn a noise model from empty water: learned on a worker, written, made the
  // parameters' noise model, and the open mission re-runs with the Z-test on it.
  void learnsANoiseModelFromEmptyWater() {
    const fs::path empty = scratch_->path() / "empty";
    simulateRiser(empty, sonarcarve::NoiseSpec{}, true, 8);
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    QVERIFY(waitForResult(window, 120000));
    QSignalSpy learned(&window, &MainWindow::noiseModelLearned);
    const fs::path model = scratch_->path() / "empty_noise.yaml";
    window.learnNoiseModel(QString::fromStdString(empty.string()),
                           QString::fromStdString(model.string()));
    QVERIFY(learned.wait(60000));
    QCOMPARE(learned.front().front().toBool(), true);
    QVERIFY(fs::is_regular_file(model));
    QCOMPARE(window.paramsPanel().params().noise_model, model.string());
    const auto result = waitForResult(window, 120000);
    QVERIFY(result);
    QCOMPARE(QString::fromStdString(result->detector), QString("ztest"));
    // A folder that is not a mission: a message naming it, nothing written.
    window.learnNoiseModel(QString::fromStdString(scratch_->path().string()),
                           QString::fromStdString((scratch_->path() / "none.yaml").string()));
    QVERIFY(learned.wait(60000));
    QCOMPARE(learned.back().front().toBool(), false);
    QVERIFY(!fs::exists(scratch_->path() / "none.yaml"));
  }

  // The 3D view's colour key names the quantity and its unit, with the values at its ends;
  // the axes triad shows north, east and down as the camera sees them.
  void legendTriadAndPickingTellWhatTheViewShows() {
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    const auto result = waitForResult(window, 120000);
    QVERIFY(result && !result->surface.empty());
    QVERIFY(window.mapView().legendText().startsWith("intensity (counts): 0 to "));
    window.setColourBy(sonarcarve::widgets::MapView::ColourBy::Depth);
    double shallow = 1e9, deep = -1e9;
    for (const auto& p : result->surface) {
      shallow = std::min(shallow, static_cast<double>(p.position_m.z()));
      deep = std::max(deep, static_cast<double>(p.position_m.z()));
    }
    const QString depth =
        QString("depth (m): %1 to %2").arg(shallow, 0, 'f', 2).arg(deep, 0, 'f', 2);
    QCOMPARE(window.mapView().legendText(), depth);
    window.setColourBy(sonarcarve::widgets::MapView::ColourBy::Error);
    QCOMPARE(window.mapView().legendText(), QString("error vs ground truth (cm): 0.00 to 10.00"));
    window.chooseLayer(sonarcarve::widgets::MapView::Layer::Mesh);
    QCOMPARE(window.mapView().legendText(),  // the mesh is coloured like the points
             QString("error vs ground truth (cm): 0.00 to 10.00"));

    // The axes triad: from the top, north is up and east right, down points away; from the
    // south, down is down and east right, north points away.
    const auto near = [](QPointF a, QPointF b) { return QLineF(a, b).length() < 1e-6; };
    window.mapView().viewFromTop();
    auto axes = window.mapView().axesOnScreen();
    QVERIFY(near(axes[0], {0, -1}) && near(axes[1], {1, 0}) && near(axes[2], {0, 0}));
    window.mapView().viewFromSide();
    axes = window.mapView().axesOnScreen();
    QVERIFY(near(axes[0], {0, 0}) && near(axes[1], {1, 0}) && near(axes[2], {0, 1}));

    // A click on a surface point picks it: its NED position and its value.
    window.chooseLayer(sonarcarve::widgets::MapView::Layer::Surface);
    window.setColourBy(sonarcarve::widgets::MapView::ColourBy::Intensity);
    window.mapView().viewFromTop();
    const Eigen::Vector3d target =
        result->surface[result->surface.size() / 2].position_m.cast<double>();
    const QPoint at = window.mapView().screenPositionOf(target);
    Eigen::Vector3d picked;
    const QString text = window.mapView().pickAt(at, &picked);
    QVERIFY2(text.startsWith("N ") && text.contains(" m, intensity "), qPrintable(text));
    // Seen from the top, the pick is the target's column: within the F-score's 5 cm.
    QVERIFY((picked.head<2>() - target.head<2>()).norm() < 0.05);
    auto* gl = window.mapView().findChild<sonarcarve::widgets::VtkGlWidget*>();
    QVERIFY(gl);
    QSignalSpy clicked(&window.mapView(), &sonarcarve::widgets::MapView::pointPicked);
    QTest::mouseClick(gl, Qt::LeftButton, {}, at);
    QCOMPARE(clicked.count(), 1);
    QCOMPARE(clicked.front().front().toString(), text);
    QVERIFY(window.logText().contains("picked N "));
    // A second pick measures from the first.
    const Eigen::Vector3d other = result->surface.front().position_m.cast<double>();
    const QPoint at_other = window.mapView().screenPositionOf(other);
    Eigen::Vector3d picked_other;
    QVERIFY(!window.mapView().pickAt(at_other, &picked_other).isEmpty());
    QTest::mouseClick(gl, Qt::LeftButton, {}, at_other);
    QCOMPARE(clicked.count(), 2);
    const QString distance =
        QString("%1 m from the previous pick").arg((picked_other - picked).norm(), 0, 'f', 3);
    QVERIFY2(window.logText().contains(distance), qPrintable(window.logText()));
  }

  // With a ground truth, a finished run is measured by core's evaluator off the GUI thread and
  // the accuracy panel shows its figures; without one the panel says so.
  void accuracyPanelShowsTheRunsFigures() {
    MainWindow window;
    window.show();
    QSignalSpy measured(&window, &MainWindow::accuracyMeasured);
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    const auto result = waitForResult(window, 120000);
    QVERIFY(result);
    QVERIFY(measured.wait(60000));
    sonarcarve::ThreadPool pool;
    const auto expected =
        sonarcarve::evaluate(sonarcarve::positionsOf(result->surface),
                             sonarcarve::loadSceneMesh(mission() / "ground_truth.ply"),
                             sonarcarve::readPointsPly(mission() / "visible_points.ply"), pool);
    QCOMPARE(measured.front().front().toDouble(), expected.fscore);
    const QString text = window.accuracyPanel().text();
    QVERIFY2(text.contains(QString("F-score at 5 cm: %1").arg(expected.fscore, 0, 'f', 3)),
             qPrintable(text));
    QVERIFY(text.contains(
        QString("median error: %1 cm").arg(100.0 * expected.accuracy_median_m, 0, 'f', 2)));
    QVERIFY(text.contains(
        QString("90th percentile error: %1 cm").arg(100.0 * expected.accuracy_p90_m, 0, 'f', 2)));
    QVERIFY(text.contains(QString("completeness (truth within 5 cm): %1 %")
                              .arg(100.0 * expected.completeness, 0, 'f', 1)));
    QVERIFY(text.contains(QString("precision (points within 5 cm): %1 %")
                              .arg(100.0 * expected.precision, 0, 'f', 1)));
    QVERIFY(window.runs().back().accuracy);
    QCOMPARE(window.runs().back().accuracy->fscore, expected.fscore);

    // The same mission without its ground truth: no figures, and the panel says why.
    const fs::path bare = scratch_->path() / "riser_no_truth";
    fs::copy(mission(), bare, fs::copy_options::recursive);
    fs::remove(bare / "ground_truth.ply");
    QVERIFY(window.openMission(QString::fromStdString(bare.string())));
    QVERIFY(waitForResult(window, 120000));
    QVERIFY(window.accuracyPanel().text().startsWith("No ground truth"));
    QVERIFY(!window.runs().back().accuracy);
  }

  // Each run is kept with its parameters and figures; two are compared by what differs; going
  // back restores one run's parameters and runs them again; the session keeps the history.
  void runHistoryComparesAndGoesBack() {
    MainWindow window;
    window.show();
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    const auto first = waitForResult(window, 120000);
    QVERIFY(first);
    auto params = window.paramsPanel().params();
    const double voxel = params.carve.voxel_size_m;
    params.carve.voxel_size_m = 1.5 * voxel;
    window.setParams(params);
    window.startRun();
    const auto second = waitForResult(window, 120000);
    QVERIFY(second);
    QCOMPARE(window.runs().size(), std::size_t{2});
    QCOMPARE(window.runHistoryPanel().rowCount(), 2);
    QCOMPARE(window.runs()[0].occupied_voxels, first->occupied_voxels);
    QCOMPARE(window.runs()[1].surface_points, second->surface.size());
    QCOMPARE(window.runs()[1].params.carve.voxel_size_m, 1.5 * voxel);

    const QString html =
        sonarcarve::widgets::RunHistoryPanel::comparison(window.runs()[0], 0, window.runs()[1], 1);
    QVERIFY(html.contains("voxel_size_m (m)"));
    QVERIFY(html.contains(QString::number(first->occupied_voxels)));
    QVERIFY(html.contains(QString::number(second->occupied_voxels)));
    QVERIFY(!html.contains("detector.z"));  // the same in both

    const fs::path file = scratch_->path() / "history.sonarcarve";
    QVERIFY(window.saveSession(QString::fromStdString(file.string())));
    QCOMPARE(sonarcarve::loadSession(file).runs.size(), std::size_t{2});

    window.runHistoryPanel().selectRuns({0});
    QPushButton* go_back = nullptr;
    for (auto* button : window.runHistoryPanel().findChildren<QPushButton*>()) {
      if (button->text().startsWith("Go back")) {
        go_back = button;
      }
    }
    QVERIFY(go_back && go_back->isEnabled());
    go_back->click();
    QCOMPARE(window.paramsPanel().params().carve.voxel_size_m, voxel);
    const auto third = waitForResult(window, 120000);
    QVERIFY(third);
    QCOMPARE(third->occupied_voxels, first->occupied_voxels);
    QCOMPARE(window.runs().size(), std::size_t{3});

    MainWindow reopened;
    QVERIFY(reopened.openSession(QString::fromStdString(file.string())));
    QVERIFY(waitForResult(reopened, 120000));
    QCOMPARE(reopened.runs().size(), std::size_t{3});  // the two saved and the one it ran
    QCOMPARE(reopened.runHistoryPanel().rowCount(), 3);
  }

  // The window keeps its last run (map, surface, mesh) until the next run starts, and then
  // nothing holds it any more: its memory is released (on a worker), not kept until quitting.
  void aRunIsReleasedWhenTheNextStarts() {
    MainWindow window;
    window.show();
    QSignalSpy measured(&window, &MainWindow::accuracyMeasured);
    QVERIFY(window.openMission(QString::fromStdString(mission().string())));
    std::weak_ptr<const ReconstructionResult> first = waitForResult(window, 120000);
    QVERIFY(!first.expired());  // the window's
    // Its surface and mesh layers were built on the runner's worker, not on the GUI thread
    // (which stalled 0.5 s and more on them: docs/benchmarks.md), and are drawn.
    sonarcarve::widgets::MapView& view = window.mapView();
    QCOMPARE(view.resultLayersBuiltHere(), std::size_t{0});
    QCOMPARE(view.layer(), sonarcarve::widgets::MapView::Layer::Surface);
    QCOMPARE(view.drawnPointCount(), first.lock()->surface.size());
    QVERIFY(measured.wait(60000));
    QCOMPARE(first.use_count(), 1L);  // the window's only
    window.startRun();
    // A worker frees it: wait for it.
    QTRY_VERIFY_WITH_TIMEOUT(first.expired(), 10000);
    std::weak_ptr<const ReconstructionResult> second = waitForResult(window, 120000);
    QVERIFY(!second.expired());
    QVERIFY(window.mapView().mapPointCount() > 0);
  }

  // What a save dialog returns gets the extension of what it saves, unless it has it.
  void saveDialogNamesGetTheirExtension() {
    using sonarcarve::gui::withSuffix;
    QCOMPARE(withSuffix("/data/riser", ".ply"), QString("/data/riser.ply"));
    QCOMPARE(withSuffix("/data/riser.PLY", ".ply"), QString("/data/riser.PLY"));
    QCOMPARE(withSuffix("/data/riser.v2", ".stl"), QString("/data/riser.v2.stl"));
    QCOMPARE(withSuffix("params.yml", ".yaml", {".yml"}), QString("params.yml"));
    QCOMPARE(withSuffix("", ".sonarcarve"), QString());  // a cancelled dialog stays cancelled
  }

  void cleanupTestCase() { scratch_.reset(); }

 private:
  fs::path mission() const { return scratch_->path() / "riser"; }
  std::unique_ptr<sonarcarve::test::ScratchDir> scratch_;
};

int main(int argc, char** argv) {
  sonarcarve::widgets::VtkGlWidget::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  WorkbenchTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "workbench_test.moc"
