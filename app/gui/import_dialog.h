// ImportDialog: the choices of a vendor-log import (sonarcarve-cli import): the log, its
// navigation CSV with the column mapping, the sonar's mounting, the time offset between them,
// an aperture override and the mission folder to write. GUI thread only.
#pragma once

#include <QDialog>

#include "io/import.h"

class QDoubleSpinBox;
class QFormLayout;
class QLineEdit;

namespace sonarcarve::gui {

class ImportDialog : public QDialog {
  Q_OBJECT
 public:
  explicit ImportDialog(const QString& log, QWidget* parent = nullptr);
  /// The request as filled in; throws Error if the navigation mapping cannot be read.
  ImportRequest request() const;

 private:
  QLineEdit* pathRow(const QString& label, const QString& filter, bool folder, bool save);

  QFormLayout* form_ = nullptr;
  QLineEdit* log_ = nullptr;
  QLineEdit* nav_ = nullptr;
  QLineEdit* nav_map_ = nullptr;
  QLineEdit* mounting_ = nullptr;
  QLineEdit* out_ = nullptr;
  QDoubleSpinBox* offset_s_ = nullptr;
  QDoubleSpinBox* aperture_deg_ = nullptr;
};

}  // namespace sonarcarve::gui
