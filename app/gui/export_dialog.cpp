#include "export_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardItemModel>
#include <QToolButton>
#include <array>
#include <optional>

#include "common/error.h"
#include "geo/crs.h"
#include "gui_conventions.h"
#include "sonar/mission_origin.h"

namespace sonarcarve::gui {
namespace {

struct FormatChoice {
  const char* label;
  const char* format;  // ExportOptions::format
  bool points;         // DeliverableRequest::points
  const char* suffix;
  const char* kind;  // the file dialog's filter name
};

constexpr std::array<FormatChoice, 6> kFormats{{
    {QT_TRANSLATE_NOOP("ExportDialog", "Mesh (PLY)"), "ply", false, ".ply", "PLY"},
    {QT_TRANSLATE_NOOP("ExportDialog", "Mesh (STL)"), "stl", false, ".stl", "STL"},
    {QT_TRANSLATE_NOOP("ExportDialog", "Mesh (OBJ)"), "obj", false, ".obj", "Wavefront OBJ"},
    {QT_TRANSLATE_NOOP("ExportDialog", "Surface points (PLY)"), "ply", true, ".ply", "PLY"},
    {QT_TRANSLATE_NOOP("ExportDialog", "Point cloud (LAS 1.4)"), "las", true, ".las", "LAS"},
    {QT_TRANSLATE_NOOP("ExportDialog", "Seabed elevation grid (GeoTIFF)"), "geotiff", true, ".tif",
     "GeoTIFF"},
}};

// LAS and GeoTIFF hold x east, y north, z up, in the mission's CRS when it has one.
constexpr int kFirstPointsFormat = 3;

bool zUp(const FormatChoice& f) {
  const std::string format = f.format;
  return format == "las" || format == "geotiff";
}

constexpr const char* kRefusalStyle = "color: #b00020";

// A label for notes of up to `lines` lines: room kept for them, so that the dialog does not
// clip a note that appears or grows.
QLabel* notes(int lines) {
  auto* label = new QLabel;
  label->setWordWrap(true);
  label->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  label->setMinimumHeight(lines * label->fontMetrics().lineSpacing());
  return label;
}

// An export's refusal in the dialog's words: the field it concerns, then why.
QString describeRefusal(const Error& e) {
  const QString why = QString::fromStdString(e.message());
  return e.place() == "crs" ? ExportDialog::tr("Target CRS: %1").arg(why) : why;
}

}  // namespace

ExportDialog::ExportDialog(const ExportPlace& place, QWidget* parent)
    : QDialog(parent), place_(place) {
  setWindowTitle(tr("Export the map"));
  auto* form = new QFormLayout(this);
  auto* intro =
      new QLabel(tr("A deliverable of the last finished run, as sonarcarve-cli export writes it."));
  intro->setWordWrap(true);
  form->addRow(intro);

  format_ = new QComboBox;
  for (const FormatChoice& f : kFormats) {
    format_->addItem(tr(f.label));
    if (!f.points && !place.has_mesh) {
      auto* item = qobject_cast<QStandardItemModel*>(format_->model())->item(format_->count() - 1);
      item->setEnabled(false);
      item->setToolTip(tr("The run made no mesh (Build a mesh is off)"));
    }
  }
  if (!place.has_mesh) {
    format_->setCurrentIndex(kFirstPointsFormat);
  }
  form->addRow(tr("Format"), format_);

  auto* file_row = new QHBoxLayout;
  file_ = new QLineEdit;
  auto* browse = new QToolButton;
  browse->setText("…");
  file_row->addWidget(file_, 1);
  file_row->addWidget(browse);
  form->addRow(tr("File"), file_row);
  connect(browse, &QToolButton::clicked, this, &ExportDialog::browse);

  cell_ = new QDoubleSpinBox;
  cell_->setRange(0.01, 100.0);
  cell_->setDecimals(2);
  cell_->setSingleStep(0.05);
  cell_->setValue(DeliverableRequest{}.cell_m);
  cell_->setSuffix(tr(" m"));
  cell_->setToolTip(tr("Edge of the seabed grid's square cells (GeoTIFF only)"));
  form->addRow(tr("Grid cell"), cell_);

  frame_ = new QComboBox;
  frame_->addItems(
      {tr("north, east, down (as inside)"), tr("Z up: x east, y north, z up (for CAD tools)")});
  form->addRow(tr("Frame"), frame_);

  auto* crs_row = new QHBoxLayout;
  use_crs_ = new QCheckBox(tr("in the projected CRS"));
  crs_ = new QLineEdit(QString::fromStdString(place.crs));
  crs_->setPlaceholderText(tr("EPSG:32631 or a PROJ string"));
  crs_row->addWidget(use_crs_);
  crs_row->addWidget(crs_, 1);
  form->addRow(tr("Coordinates"), crs_row);
  crs_note_ = notes(2);
  crs_note_->setObjectName("crsNote");
  form->addRow(QString(), crs_note_);
  add_origin_ =
      new QCheckBox(tr("World coordinates: add back the mission origin (north east down %1 m)")
                        .arg(QString::fromStdString(nedText(place.origin_ned_m))));
  form->addRow(QString(), add_origin_);
  use_crs_->setChecked(!place.crs.empty());

  problem_label_ = notes(2);
  problem_label_->setObjectName("exportProblem");
  problem_label_->setStyleSheet(kRefusalStyle);
  form->addRow(problem_label_);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  export_ = buttons->button(QDialogButtonBox::Ok);
  export_->setText(tr("Export"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);

  connect(format_, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChosen);
  connect(file_, &QLineEdit::textChanged, this, &ExportDialog::update);
  connect(frame_, &QComboBox::currentIndexChanged, this, &ExportDialog::update);
  connect(use_crs_, &QCheckBox::toggled, this, &ExportDialog::update);
  connect(crs_, &QLineEdit::textChanged, this, &ExportDialog::update);
  connect(add_origin_, &QCheckBox::toggled, this, &ExportDialog::update);
  if (!place.file_stem.isEmpty()) {
    file_->setText(place.file_stem +
                   kFormats[static_cast<std::size_t>(format_->currentIndex())].suffix);
  }
  resize(680, sizeHint().height());
  update();
}

void ExportDialog::formatChosen() {
  // The file follows the format: its suffix becomes the new format's.
  const QString path = file_->text().trimmed();
  if (!path.isEmpty()) {
    const QFileInfo info(path);
    const QString stem = info.path() == "." && !path.startsWith("./")
                             ? info.completeBaseName()
                             : info.dir().filePath(info.completeBaseName());
    file_->setText(stem + kFormats[static_cast<std::size_t>(format_->currentIndex())].suffix);
  }
  update();
}

void ExportDialog::browse() {
  const FormatChoice& f = kFormats[static_cast<std::size_t>(format_->currentIndex())];
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export"), file_->text(), QStringLiteral("%1 (*%2)").arg(f.kind, f.suffix));
  if (!path.isEmpty()) {
    file_->setText(withSuffix(path, f.suffix, {".tiff"}));
  }
}

void ExportDialog::update() {
  const FormatChoice& f = kFormats[static_cast<std::size_t>(format_->currentIndex())];
  const bool z_up = zUp(f);
  const bool has_crs = !place_.crs.empty();
  const bool in_crs = has_crs && use_crs_->isChecked();
  cell_->setEnabled(std::string(f.format) == "geotiff");
  frame_->setEnabled(!z_up && !in_crs);
  frame_->setToolTip(z_up     ? tr("LAS and GeoTIFF are always x east, y north, z up")
                     : in_crs ? tr("A CRS's coordinates are easting, northing, up")
                              : QString());
  use_crs_->setEnabled(has_crs);
  crs_->setEnabled(in_crs);
  // World coordinates: what a CRS gives already, and LAS and GeoTIFF in the mission's CRS.
  const bool world_already = in_crs || (z_up && has_crs);
  add_origin_->setEnabled(!world_already && !place_.origin_ned_m.isZero());
  add_origin_->setToolTip(world_already ? tr("The coordinates are in a CRS: world already")
                          : place_.origin_ned_m.isZero()
                              ? tr("The mission origin is zero: local coordinates are world ones")
                              : QString());
  const std::string crs = crs_->text().trimmed().toStdString();
  const std::optional<std::string> crs_problem =
      in_crs ? gridCrsProblem(crs) : std::optional<std::string>();
  if (!has_crs) {
    crs_note_->setText(
        tr("This mission has no CRS: its navigation is north and east in metres without one, "
           "so exports are local to its origin. Navigation in latitude and longitude, or crs: "
           "in its mission.yaml, gives it one."));
  } else if (in_crs) {
    crs_note_->setText(crs_problem ? tr("Target CRS: %1").arg(QString::fromStdString(*crs_problem))
                                   : tr("%1: x easting, y northing, z up, metres")
                                         .arg(QString::fromStdString(crsName(crs))));
  } else {
    crs_note_->setText(
        z_up ? tr("In the mission's CRS, %1").arg(QString::fromStdString(crsName(place_.crs)))
             : tr("Local to the mission origin"));
  }
  problem_.clear();
  try {
    if (crs_problem) {
      throw Error("export", "crs", *crs_problem);  // an empty one too
    }
    request().options.validate();
  } catch (const Error& e) {
    problem_ = describeRefusal(e);
  }
  if (problem_.isEmpty() && file_->text().trimmed().isEmpty()) {
    problem_ = tr("Choose the file to write.");
  }
  crs_note_->setStyleSheet(crs_problem ? kRefusalStyle : "");
  problem_label_->setText(crs_problem ? QString() : problem_);  // a CRS's is said above
  export_->setEnabled(problem_.isEmpty());
}

DeliverableRequest ExportDialog::request() const {
  const FormatChoice& f = kFormats[static_cast<std::size_t>(format_->currentIndex())];
  DeliverableRequest r;
  r.points = f.points;
  r.cell_m = cell_->value();
  ExportOptions& o = r.options;
  o.format = f.format;
  o.frame = frame_->isEnabled() && frame_->currentIndex() == 1 ? "zup" : "ned";
  o.mission_origin_ned_m = place_.origin_ned_m;
  o.mission_crs = place_.crs;
  if (use_crs_->isEnabled() && use_crs_->isChecked()) {
    o.target_crs = crs_->text().trimmed().toStdString();
  }
  o.add_mission_origin = add_origin_->isEnabled() && add_origin_->isChecked();
  return r;
}

QString ExportDialog::file() const {
  return file_->text().trimmed();
}

}  // namespace sonarcarve::gui
