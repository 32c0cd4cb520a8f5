// sonarcarve: the workbench GUI.
//   sonarcarve [MISSION | SESSION.sonarcarve] [--params P.yaml] [--noise-model N.yaml]
//              [--screenshot FILE.png] [--quit-when-done] [--frame N] [--colour-by MODE]
//              [--view-points N] [--show map|surface|mesh]
// With --screenshot the window is captured once the first reconstruction has finished
// (for the README and the user guide); --quit-when-done then exits with the run's status.
#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QTimer>
#include <iostream>
#include <string_view>

#include "allocator.h"
#include "desktop_integration.h"
#include "frame_timeline.h"
#include "main_window.h"
#include "map_view.h"
#include "params_panel.h"
#include "session/session_file.h"
#include "vtk_gl_widget.h"

namespace {

// The workbench's command line, declared once for the help and for a run.
struct GuiOptions {
  QCommandLineOption params{{"p", "params"}, "Reconstruction parameters YAML", "file"};
  QCommandLineOption noise{{"n", "noise-model"}, "Noise model for the Z-test", "file"};
  QCommandLineOption screenshot{
      "screenshot",
      "Save a PNG of the window once the first run finishes (and, with a ground truth, its "
      "accuracy is measured)",
      "file"};
  QCommandLineOption quit{"quit-when-done",
                          "Exit once the first run finishes (as --screenshot has it)"};
  QCommandLineOption frame{"frame", "Frame to show once the first run finishes", "index"};
  QCommandLineOption colour{"colour-by", "intensity | depth | error", "mode"};
  QCommandLineOption view_points{
      "view-points",
      QString("Most points of the carved map the 3D view holds (default %1): past it, the "
              "blocks changed longest ago are held coarser")
          .arg(sonarcarve::widgets::MapLod::kDefaultMaxPoints),
      "count"};
  QCommandLineOption show{
      "show",
      "3D view's layer once the first run finishes: map | surface | mesh (default: surface)",
      "layer"};

  explicit GuiOptions(QCommandLineParser& parser) {
    parser.setApplicationDescription(
        "SonarCarve workbench: 3D maps of underwater structures from 2D imaging sonar");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("mission", "Mission folder or session file (.sonarcarve) to open");
    parser.addOptions({params, noise, screenshot, quit, frame, colour, view_points, show});
  }
};

void nameApplication() {
  QCoreApplication::setApplicationName("SonarCarve");
  QCoreApplication::setOrganizationName("SonarCarve");
  QCoreApplication::setApplicationVersion(SONARCARVE_VERSION);
}

// --help and --version need no display: they are answered before any window system starts.
bool asksOnlyForHelpOrVersion(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "-?" || arg == "-v" ||
        arg == "--version") {
      return true;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (asksOnlyForHelpOrVersion(argc, argv)) {
    const QCoreApplication app(argc, argv);
    nameApplication();
    QCommandLineParser parser;
    const GuiOptions options(parser);
    parser.process(QCoreApplication::arguments());  // prints the help or version and exits
    return 0;
  }
  sonarcarve::gui::tuneAllocatorForLatency();
  sonarcarve::widgets::VtkGlWidget::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  nameApplication();
  sonarcarve::gui::setUpDesktopIntegration();

  QCommandLineParser parser;
  const GuiOptions options(parser);
  const auto& [params, noise, screenshot, quit, frame, colour, view_points, show] = options;
  parser.process(app);

  sonarcarve::gui::MainWindow window;
  if (parser.isSet(view_points)) {
    bool ok = false;
    const qulonglong budget = parser.value(view_points).toULongLong(&ok);
    if (!ok || budget == 0) {
      std::cerr << "sonarcarve: --view-points: expected a whole number of points, at least 1, "
                   "not \""
                << parser.value(view_points).toStdString() << "\"\n";
      return 2;
    }
    window.mapView().setMapPointBudget(budget);
  }
  if (parser.isSet(show)) {
    const QStringList layers{"map", "surface", "mesh"};  // MapView::Layer's order
    const auto layer = layers.indexOf(parser.value(show));
    if (layer < 0) {
      std::cerr << "sonarcarve: --show: expected map, surface or mesh, not \""
                << parser.value(show).toStdString() << "\"\n";
      return 2;
    }
    window.chooseLayer(static_cast<sonarcarve::widgets::MapView::Layer>(layer));
  }
  if (parser.isSet(params) && !window.loadParams(parser.value(params))) {
    std::cerr << "sonarcarve: cannot load " << parser.value(params).toStdString() << "\n";
  }
  if (parser.isSet(noise)) {
    sonarcarve::ReconstructionParams p = window.paramsPanel().params();
    p.noise_model = QFileInfo(parser.value(noise)).absoluteFilePath().toStdString();
    window.setParams(p);
  }
  window.show();

  int status = 0;
  const bool quit_when_done = parser.isSet(quit);
  const QString shot = parser.value(screenshot);
  if (parser.isSet(colour)) {
    window.setColourBy(
        sonarcarve::widgets::MapView::colourByNamed(parser.value(colour).toStdString()));
  }
  const auto done = [&](bool ok) {
    status = ok ? 0 : 1;
    if (parser.isSet(frame)) {
      window.timeline().setCurrentFrame(parser.value(frame).toInt());
    }
    if (!shot.isEmpty()) {
      // Let the last redraw reach the screen before capturing.
      QTimer::singleShot(600, &window, [&window, shot, quit_when_done, &status] {
        if (!window.grab().save(shot)) {
          std::cerr << "sonarcarve: cannot write " << shot.toStdString() << "\n";
          status = 1;
        }
        if (quit_when_done) {
          QApplication::exit(status);
        }
      });
    } else if (quit_when_done) {
      QApplication::exit(status);
    }
  };
  // With a ground truth the picture waits for the accuracy panel's figures (measured on a
  // worker after the run), at most a minute.
  bool finished = false;
  const auto finish = [&] {
    if (!finished) {
      finished = true;
      done(true);
    }
  };
  QObject::connect(
      &window, &sonarcarve::gui::MainWindow::runFinished, &window,
      [&] {
        if (!window.errorColouringAvailable()) {
          finish();
          return;
        }
        QObject::connect(&window, &sonarcarve::gui::MainWindow::accuracyMeasured, &window, finish,
                         Qt::SingleShotConnection);
        QTimer::singleShot(60000, &window, finish);
      },
      Qt::SingleShotConnection);
  QObject::connect(
      &window, &sonarcarve::gui::MainWindow::runFailed, &window, [&] { done(false); },
      Qt::SingleShotConnection);

  const QStringList args = parser.positionalArguments();
  if (!args.isEmpty()) {
    const QString path = args.front();
    const bool opened =
        path.endsWith(".sonarcarve") || sonarcarve::looksLikeSessionFile(path.toStdString())
            ? window.openSession(path)
            : window.openMission(path);
    if (!opened && quit_when_done) {
      return 1;
    }
  }
  const int code = app.exec();
  return code != 0 ? code : status;
}
