#include "import_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QToolButton>

#include "io/mission/nav_import.h"

namespace sonarcarve::gui {

ImportDialog::ImportDialog(const QString& log, QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Import a sonar log"));
  form_ = new QFormLayout(this);
  auto* intro = new QLabel(
      tr("Oculus logs (ViewPoint .oculus recordings or raw ping messages) become a mission "
         "folder. Without navigation the vehicle is taken as stationary at the origin."));
  intro->setWordWrap(true);
  form_->addRow(intro);
  log_ = pathRow(tr("Sonar log"), tr("Oculus logs (*.oculus *.raw *.bin);;All files (*)"), false,
                 false);
  log_->setText(log);
  nav_ = pathRow(tr("Navigation CSV"), tr("CSV (*.csv *.txt);;All files (*)"), false, false);
  nav_map_ = pathRow(tr("Column mapping YAML"), tr("YAML (*.yaml *.yml)"), false, false);
  nav_map_->setPlaceholderText(tr("columns named as in our nav.csv"));
  mounting_ = pathRow(tr("Mounting YAML"), tr("YAML (*.yaml *.yml)"), false, false);
  mounting_->setPlaceholderText(tr("sonar at the vehicle origin, looking forward"));
  offset_s_ = new QDoubleSpinBox;
  offset_s_->setRange(-1e9, 1e9);
  offset_s_->setDecimals(3);
  offset_s_->setSuffix(tr(" s"));
  offset_s_->setToolTip(tr("Added to the log's times to put them on the navigation clock"));
  form_->addRow(tr("Time offset"), offset_s_);
  aperture_deg_ = new QDoubleSpinBox;
  aperture_deg_->setRange(0.0, 90.0);
  aperture_deg_->setSuffix(tr("°"));
  aperture_deg_->setSpecialValueText(tr("from the sonar's frequency"));
  form_->addRow(tr("Vertical aperture"), aperture_deg_);
  out_ = pathRow(tr("Mission folder"), QString(), true, true);
  if (!log.isEmpty()) {
    const QFileInfo info(log);
    out_->setText(info.dir().filePath(info.completeBaseName() + "-mission"));
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Import and open"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form_->addRow(buttons);
  resize(640, sizeHint().height());
}

QLineEdit* ImportDialog::pathRow(const QString& label, const QString& filter, bool folder,
                                 bool save) {
  auto* row = new QHBoxLayout;
  auto* edit = new QLineEdit;
  auto* browse = new QToolButton;
  browse->setText("…");
  row->addWidget(edit, 1);
  row->addWidget(browse);
  form_->addRow(label, row);
  connect(browse, &QToolButton::clicked, this, [this, edit, label, filter, folder, save] {
    const QString path = folder ? QFileDialog::getExistingDirectory(this, label)
                         : save ? QFileDialog::getSaveFileName(this, label, edit->text(), filter)
                                : QFileDialog::getOpenFileName(this, label, edit->text(), filter);
    if (!path.isEmpty()) {
      edit->setText(path);
    }
  });
  return edit;
}

ImportRequest ImportDialog::request() const {
  ImportRequest r;
  r.log = log_->text().trimmed().toStdString();
  r.out = out_->text().trimmed().toStdString();
  r.nav_csv = nav_->text().trimmed().toStdString();
  if (!nav_map_->text().trimmed().isEmpty()) {
    r.nav_mapping = readNavMapping(nav_map_->text().trimmed().toStdString());
  }
  r.mounting_yaml = mounting_->text().trimmed().toStdString();
  r.time_offset_s = offset_s_->value();
  if (aperture_deg_->value() > 0.0) {
    r.vertical_aperture_deg = aperture_deg_->value();
  }
  return r;
}

}  // namespace sonarcarve::gui
