// The workbench's export dialog (issue 43) as an analyst drives it, under Xvfb: a mission whose
// navigation is in UTM 31N eastings and northings exports its run as LAS 1.4 in another zone and
// as a GeoTIFF seabed grid in its own CRS, each the very file `sonarcarve-cli export` writes of
// the same run; the dialog refuses a geographic CRS (EPSG:4326) naming why; a mission without
// a CRS says so and offers none; a failed export names the file and keeps the previous one.
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QtTest>
#include <nlohmann/json.hpp>
#include <sstream>

#include "export_dialog.h"
#include "main_window.h"
#include "pipeline/reconstruction.h"
#include "support/cli_runner.h"
#include "support/las_read_back.h"
#include "support/test_support.h"

using sonarcarve::ReconstructionResult;
using sonarcarve::gui::ExportDialog;
using sonarcarve::gui::MainWindow;
using sonarcarve::test::quoted;
using sonarcarve::test::runCli;
namespace fs = std::filesystem;

Q_DECLARE_METATYPE(std::shared_ptr<const sonarcarve::ReconstructionResult>)

namespace {

// The dialog's format list, in its order.
enum Format { MeshPly, MeshStl, MeshObj, PointsPly, Las, GeoTiff };

// Where the grid mission lies on UTM 31N: 60 km east of its central meridian.
constexpr double kEasting_m = 560000.0;
constexpr double kNorthing_m = 4760000.0;

// The simulated mission `ned` with its navigation as UTM 31N easting and northing.
void writeGridTwin(const fs::path& ned, const fs::path& grid) {
  sonarcarve::test::copyMissionWithoutTruth(ned, grid);
  std::istringstream in(sonarcarve::test::readText(ned / "nav.csv"));
  std::string line;
  std::getline(in, line);
  QCOMPARE(line, std::string("time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg"));
  std::ostringstream out;
  out.precision(17);
  out << "time_s,northing_m,easting_m,down_m,roll_deg,pitch_deg,yaw_deg\n";
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string time, north, east, rest;
    std::getline(row, time, ',');
    std::getline(row, north, ',');
    std::getline(row, east, ',');
    std::getline(row, rest);
    out << time << ',' << kNorthing_m + std::stod(north) << ',' << kEasting_m + std::stod(east)
        << ',' << rest << '\n';
  }
  sonarcarve::test::writeText(grid / "nav.csv", out.str());
  sonarcarve::test::writeText(
      grid / "mission.yaml",
      sonarcarve::test::readText(ned / "mission.yaml") + "crs: EPSG:32631\n");
}

std::shared_ptr<const ReconstructionResult> runToTheEnd(MainWindow& window, const fs::path& m) {
  QSignalSpy finished(&window, &MainWindow::runFinished);
  if (!window.openMission(QString::fromStdString(m.string())) || !finished.wait(120000)) {
    return nullptr;
  }
  return finished.front().front().value<std::shared_ptr<const ReconstructionResult>>();
}

// Fills the dialog and presses Export; true when the export reports success.
bool exportThrough(ExportDialog& dialog, MainWindow& window, Format format, const fs::path& file,
                   const QString& crs) {
  dialog.formatBox()->setCurrentIndex(format);
  dialog.fileEdit()->setText(QString::fromStdString(file.string()));
  dialog.crsEdit()->setText(crs);
  if (!dialog.exportButton()->isEnabled()) {
    qWarning() << "refused:" << dialog.problem();
    return false;
  }
  QSignalSpy done(&window, &MainWindow::exportFinished);
  QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
  return done.wait(60000) && done.front().front().toBool();
}

std::string gdalInfoJson(const fs::path& tif) {
  const auto run = sonarcarve::test::runShell("gdalinfo -json -stats " + quoted(tif) + " 2>&1");
  return run.exit_code == 0 ? run.output : std::string();
}

}  // namespace

class ExportDialogTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    qRegisterMetaType<std::shared_ptr<const ReconstructionResult>>();
    scratch_ = std::make_unique<sonarcarve::test::ScratchDir>();
    const auto sim =
        runCli("simulate --scene riser --noise none --max-frames 16 --out " + quoted(path("ned")));
    QVERIFY2(sim.exit_code == 0, sim.output.c_str());
    writeGridTwin(path("ned"), path("grid"));
  }

  // LAS in UTM 32N and the seabed grid in the mission's UTM 31N, through the dialog: the files
  // `sonarcarve-cli export` writes of the same run, byte for byte, with the CRS and the points
  // read back by the tests' own LAS reader and by GDAL.
  void exportsLasAndGeoTiffInACrs() {
    MainWindow window;
    window.show();
    const auto result = runToTheEnd(window, path("grid"));
    QVERIFY(result);
    QVERIFY(result->surface.size() > 500);
    const fs::path params = path("gui_params.yaml");
    QVERIFY(window.saveParams(QString::fromStdString(params.string())));
    const auto rec = runCli("reconstruct " + quoted(path("grid")) + " --params " + quoted(params) +
                            " --out " + quoted(path("cli")));
    QVERIFY2(rec.exit_code == 0, rec.output.c_str());

    ExportDialog* dialog = window.openExportDialog();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QCOMPARE(dialog->crsEdit()->text(), QString("EPSG:32631"));  // the mission's
    QVERIFY(dialog->crsCheck()->isEnabled() && dialog->crsCheck()->isChecked());
    QVERIFY(exportThrough(*dialog, window, Las, path("gui.las"), "EPSG:32632"));
    const auto cli_las = runCli("export " + quoted(path("cli")) + " --format las --crs EPSG:32632" +
                                " --out " + quoted(path("cli.las")));
    QVERIFY2(cli_las.exit_code == 0, cli_las.output.c_str());
    QVERIFY(sonarcarve::test::readText(path("gui.las")) ==
            sonarcarve::test::readText(path("cli.las")));
    const auto las = sonarcarve::test::readLasBack(path("gui.las"));
    QCOMPARE(las.count, static_cast<std::uint64_t>(result->surface.size()));
    QVERIFY2(las.wkt.find("UTM zone 32N") != std::string::npos, las.wkt.c_str());
    // 3.7 deg E lies some 430 km west of zone 32's central meridian (9 deg E).
    QVERIFY(las.min.x() > 50000.0 && las.max.x() < 150000.0);
    QVERIFY(window.logText().contains("world coordinates in EPSG:32632"));

    dialog = window.openExportDialog();
    QVERIFY(dialog);
    dialog->cellBox()->setValue(0.5);
    QVERIFY(exportThrough(*dialog, window, GeoTiff, path("gui.tif"), "EPSG:32631"));
    const auto cli_tif =
        runCli("export " + quoted(path("cli")) + " --cell 0.5 --out " + quoted(path("cli.tif")));
    QVERIFY2(cli_tif.exit_code == 0, cli_tif.output.c_str());
    QVERIFY(sonarcarve::test::readText(path("gui.tif")) ==
            sonarcarve::test::readText(path("cli.tif")));
    const std::string info = gdalInfoJson(path("gui.tif"));
    QVERIFY2(!info.empty(), "gdalinfo -json -stats failed");
    const auto json = nlohmann::json::parse(info);
    QVERIFY(json["coordinateSystem"]["wkt"].get<std::string>().find("UTM zone 31N") !=
            std::string::npos);
    QCOMPARE(json["geoTransform"][1].get<double>(), 0.5);
    const double west = json["geoTransform"][0].get<double>();
    QVERIFY(std::abs(west - kEasting_m) < 20.0);  // the riser stands near the grid offset
    const auto& band = json["bands"][0];
    QVERIFY(band["maximum"].get<double>() < 0.0);  // heights up: the seabed is below the surface
  }

  // EPSG:4326 is refused in the dialog, naming the CRS and why, with Export off; a projected
  // CRS is taken again; STL, float32, is refused with a CRS.
  void refusesAGeographicCrs() {
    MainWindow window;
    window.show();
    QVERIFY(runToTheEnd(window, path("grid")));
    ExportDialog* dialog = window.openExportDialog();
    QVERIFY(dialog);
    dialog->formatBox()->setCurrentIndex(Las);
    dialog->crsEdit()->setText("EPSG:4326");
    QVERIFY(!dialog->exportButton()->isEnabled());
    QVERIFY2(dialog->problem().contains("Target CRS: 'EPSG:4326' (WGS 84) is not a projected CRS"),
             qPrintable(dialog->problem()));
    auto* crs_note = dialog->findChild<QLabel*>("crsNote");
    QVERIFY(crs_note && crs_note->isVisible());
    QCOMPARE(crs_note->text(), dialog->problem());  // under the CRS it is about
    dialog->crsEdit()->setText("EPSG:32631");
    QVERIFY(dialog->exportButton()->isEnabled());
    QCOMPARE(crs_note->text(),
             QString("WGS 84 / UTM zone 31N: x easting, y northing, z up, metres"));
    dialog->formatBox()->setCurrentIndex(MeshStl);
    QVERIFY(!dialog->exportButton()->isEnabled());
    QVERIFY2(dialog->problem().contains("STL holds float32"), qPrintable(dialog->problem()));
    QCOMPARE(dialog->findChild<QLabel*>("exportProblem")->text(), dialog->problem());
    dialog->crsCheck()->setChecked(false);
    QVERIFY(dialog->exportButton()->isEnabled());
    dialog->reject();
  }

  // A mission without a CRS: the CRS field is off with the reason; LAS is local, with no CRS.
  void aMissionWithoutACrsSaysSo() {
    MainWindow window;
    window.show();
    QVERIFY(runToTheEnd(window, path("ned")));
    ExportDialog* dialog = window.openExportDialog();
    QVERIFY(dialog);
    QVERIFY(!dialog->crsCheck()->isEnabled());
    QVERIFY(!dialog->crsEdit()->isEnabled());
    bool explained = false;
    for (const QLabel* label : dialog->findChildren<QLabel*>()) {
      explained = explained || label->text().startsWith("This mission has no CRS");
    }
    QVERIFY(explained);
    QVERIFY(exportThrough(*dialog, window, Las, path("local.las"), QString()));
    const auto las = sonarcarve::test::readLasBack(path("local.las"));
    QVERIFY(las.wkt.empty());
    QVERIFY(las.count > 500);
  }

  // A failed export (a run without a mesh asked for one) says which file and why, and the file
  // there before is as it was.
  void aFailureNamesTheFileAndKeepsThePrevious() {
    MainWindow window;
    window.show();
    sonarcarve::ReconstructionParams params;
    params.mesh_enabled = false;
    window.setParams(params);
    QVERIFY(runToTheEnd(window, path("ned")));
    const fs::path kept = path("kept.ply");
    sonarcarve::test::writeText(kept, "the previous deliverable\n");
    ExportDialog* dialog = window.openExportDialog();
    QVERIFY(dialog);
    QCOMPARE(dialog->formatBox()->currentIndex(), static_cast<int>(PointsPly));  // no mesh
    dialog->reject();
    sonarcarve::DeliverableRequest request;
    request.options.format = "ply";
    QSignalSpy done(&window, &MainWindow::exportFinished);
    window.exportDeliverable(request, QString::fromStdString(kept.string()));
    QVERIFY(done.wait(60000));
    QCOMPARE(done.front().front().toBool(), false);
    QCOMPARE(sonarcarve::test::readText(kept), std::string("the previous deliverable\n"));
    auto* box = window.findChild<QMessageBox*>("errorMessage");
    QVERIFY(box);
    QVERIFY2(box->text().contains(QString::fromStdString(kept.string())) &&
                 box->text().contains("no mesh"),
             qPrintable(box->text()));
  }

 private:
  fs::path path(const std::string& name) const { return scratch_->path() / name; }
  std::unique_ptr<sonarcarve::test::ScratchDir> scratch_;
};

QTEST_MAIN(ExportDialogTest)
#include "export_dialog_test.moc"
