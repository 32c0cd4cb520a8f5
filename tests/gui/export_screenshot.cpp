// The user guide's pictures of the export dialog, made from the program itself under Xvfb:
// sonarcarve_export_screenshot MISSION OUT_DIR (a mission with a CRS: latitude/longitude
// navigation, or crs: in its mission.yaml). After its run, the export dialog set for a LAS
// point cloud in the mission's CRS:
//   export_dialog.png          the dialog alone
//   export_dialog_screen.png   the whole screen: the workbench with the dialog over it
//   export_dialog_refused.png  the dialog with EPSG:4326 typed in: refused, and why
// Not a test: it asserts nothing; look at the pictures.
#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QScreen>
#include <QSignalSpy>
#include <QTest>
#include <cstdio>

#include "export_dialog.h"
#include "main_window.h"
#include "vtk_gl_widget.h"

namespace {

void saved(const QPixmap& picture, const QString& file) {
  if (!picture.save(file)) {
    std::fprintf(stderr, "cannot write %s\n", qPrintable(file));
  } else {
    std::printf("%s\n", qPrintable(file));
  }
}

}  // namespace

int main(int argc, char** argv) {
  sonarcarve::widgets::VtkGlWidget::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MISSION OUT_DIR\n", argv[0]);
    return 2;
  }
  const QString out = QString(argv[2]) + "/";
  sonarcarve::gui::MainWindow window;
  window.resize(1280, 800);
  window.show();
  QSignalSpy finished(&window, &sonarcarve::gui::MainWindow::runFinished);
  if (!window.openMission(argv[1]) || !finished.wait(300000)) {
    std::fprintf(stderr, "the run did not finish\n");
    return 1;
  }
  sonarcarve::gui::ExportDialog* dialog = window.openExportDialog();
  if (dialog == nullptr) {
    return 1;
  }
  dialog->formatBox()->setCurrentIndex(4);  // LAS 1.4
  QTest::qWait(600);                        // the last redraw reaches the screen
  saved(dialog->grab(), out + "export_dialog.png");
  saved(QGuiApplication::primaryScreen()->grabWindow(0), out + "export_dialog_screen.png");
  dialog->crsEdit()->setText("EPSG:4326");
  QTest::qWait(300);
  saved(dialog->grab(), out + "export_dialog_refused.png");
  return 0;
}
