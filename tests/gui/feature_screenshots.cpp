// The user guide's pictures of the workbench's inspection tools, made from the program itself
// under Xvfb: sonarcarve_feature_screenshots MISSION OUT_DIR (a mission with its ground truth,
// e.g. the riser demo). Each picture is the whole window with one tool in use:
//   inspect_legend_scale_triad.png   surface coloured by depth, colour key, scale bar, triad
//   inspect_provisional.png          a run paused mid-way: provisional voxels translucent
//   inspect_pick_distance.png        two picks: the second's position and the distance
//   inspect_clip_box.png             the map clipped to a box
//   inspect_cross_section.png        a 10 cm horizontal slice, seen from the top
//   inspect_accuracy.png             the accuracy panel after a run
//   inspect_mesh_error.png           the mesh coloured by its error against the truth
//   inspect_run_history.png          the run history dock after two runs
//   inspect_run_comparison.png       two runs compared side by side
// Not a test: it asserts nothing; look at the pictures.
#include <QApplication>
#include <QDialog>
#include <QDockWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <cstdio>

#include "main_window.h"
#include "map_view.h"
#include "params_panel.h"
#include "run_history_panel.h"
#include "vtk_gl_widget.h"

namespace {

using sonarcarve::gui::MainWindow;
using sonarcarve::widgets::MapView;
using sonarcarve::widgets::ViewClip;

void save(QWidget& widget, const QString& file) {
  QTest::qWait(400);  // the last redraw reaches the screen
  if (!widget.grab().save(file)) {
    std::fprintf(stderr, "cannot write %s\n", qPrintable(file));
  } else {
    std::printf("%s\n", qPrintable(file));
  }
}

bool waitForRun(MainWindow& window) {
  QSignalSpy finished(&window, &MainWindow::runFinished);
  return finished.wait(300000);
}

}  // namespace

int main(int argc, char** argv) {
  sonarcarve::widgets::VtkGlWidget::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MISSION OUT_DIR\n", argv[0]);
    return 2;
  }
  const QString mission = argv[1];
  const QString out = QString(argv[2]) + "/";
  MainWindow window;
  window.resize(1280, 800);
  window.show();
  MapView& view = window.mapView();

  // Mid-run: pause the first run once about half the frames are carved. Only the first: left
  // connected, it paused the second run at the same frame and nothing resumed it (the tool
  // then waited 5 minutes for the second run's accuracy and gave up).
  QMetaObject::Connection pause_midway;
  pause_midway =
      QObject::connect(&window.runner(), &sonarcarve::gui::ReconstructionRunner::frameCarved,
                       &window, [&window, &pause_midway](int, qulonglong index) {
                         if (index == 45 && !window.runner().paused()) {
                           QObject::disconnect(pause_midway);
                           window.setPaused(true);
                         }
                       });
  QSignalSpy measured(&window, &MainWindow::accuracyMeasured);
  if (!window.openMission(mission)) {
    return 1;
  }
  for (int i = 0; i < 600 && !window.runner().paused(); ++i) {
    QTest::qWait(100);
  }
  view.flush();
  save(window, out + "inspect_provisional.png");
  window.setPaused(false);
  if (!waitForRun(window) || !measured.wait(120000)) {
    std::fprintf(stderr, "the first run did not finish\n");
    return 1;
  }
  save(window, out + "inspect_accuracy.png");

  window.chooseLayer(MapView::Layer::Surface);
  window.setColourBy(MapView::ColourBy::Depth);
  view.viewFromSide();
  save(window, out + "inspect_legend_scale_triad.png");

  // Two picks on the surface: the second gives the distance from the first.
  const auto result = window.lastResult();
  auto* gl = view.findChild<sonarcarve::widgets::VtkGlWidget*>();
  const auto& surface = result->surface;
  for (std::size_t i : {surface.size() / 5, 4 * surface.size() / 5}) {
    QTest::mouseClick(gl, Qt::LeftButton, {},
                      view.screenPositionOf(surface[i].position_m.cast<double>()));
  }
  save(window, out + "inspect_pick_distance.png");

  const Eigen::AlignedBox3d bounds = view.dataBounds();
  ViewClip clip;
  clip.box = bounds;
  clip.box->min().z() = bounds.center().z() - 0.15 * bounds.sizes().z();
  clip.box->max().z() = bounds.center().z() + 0.15 * bounds.sizes().z();
  clip.box->max().y() = bounds.center().y();
  view.setClip(clip);
  save(window, out + "inspect_clip_box.png");

  ViewClip section;
  section.section = ViewClip::Section{ViewClip::Axis::Down, bounds.center().z(), 0.1};
  view.setClip(section);
  window.setColourBy(MapView::ColourBy::Intensity);
  view.viewFromTop();
  save(window, out + "inspect_cross_section.png");
  view.setClip(ViewClip{});

  view.viewFromSide();
  window.chooseLayer(MapView::Layer::Mesh);
  window.setColourBy(MapView::ColourBy::Error);
  save(window, out + "inspect_mesh_error.png");

  // A second run with larger voxels, then both compared.
  auto params = window.paramsPanel().params();
  params.carve.voxel_size_m *= 1.5;
  window.setParams(params);
  window.startRun();
  for (int i = 0; i < 3000 && !(window.runs().size() >= 2 && window.runs().back().accuracy); ++i) {
    QTest::qWait(100);
  }
  if (window.runs().size() < 2) {
    std::fprintf(stderr, "the second run did not finish\n");
    return 1;
  }
  window.runHistoryPanel().selectRuns({0, 1});
  auto* compare = window.runHistoryPanel().findChild<QPushButton*>();
  compare->click();
  QTest::qWait(300);
  auto* dialog = window.findChild<QDialog*>("runComparison");
  // The history is a tab behind the accuracy panel: bring it to the front.
  if (auto* history = window.findChild<QDockWidget*>("history")) {
    history->raise();
  }
  save(window, out + "inspect_run_history.png");
  if (dialog != nullptr) {
    save(*dialog, out + "inspect_run_comparison.png");
    dialog->close();
  }
  return 0;
}
