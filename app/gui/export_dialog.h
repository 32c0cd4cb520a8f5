// ExportDialog: a deliverable of the last finished run with the choices `sonarcarve-cli export`
// offers (core/mesh/deliverable.h): the format (mesh as PLY, STL or OBJ; the surface points as
// PLY or LAS 1.4; the seabed's elevation grid as GeoTIFF with its cell), the file, the frame,
// a target CRS checked as the CLI checks it (ExportOptions::validate: projected, metres) and
// pre-filled with the mission's, and world coordinates (the mission origin added back). What
// the choices cannot give is said under them and keeps Export off. GUI thread only.
#pragma once

#include <Eigen/Core>
#include <QDialog>
#include <QString>
#include <string>

#include "mesh/deliverable.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace sonarcarve::gui {

/// What the dialog needs to know of the mission the run was made of.
struct ExportPlace {
  std::string crs;  ///< the mission's projected CRS (its grid); empty: none
  Eigen::Vector3d origin_ned_m = Eigen::Vector3d::Zero();  ///< the run is local to it
  bool has_mesh = true;  ///< the run made a mesh (else only the points' formats are offered)
  QString file_stem;     ///< the file proposed, without its suffix (empty: none)
};

class ExportDialog : public QDialog {
  Q_OBJECT
 public:
  ExportDialog(const ExportPlace& place, QWidget* parent = nullptr);
  /// The deliverable as chosen, the mission's origin and CRS filled in.
  DeliverableRequest request() const;
  QString file() const;
  /// Why the choices cannot be exported, in the CLI's words (empty: they can).
  QString problem() const { return problem_; }

  // The controls, for tests.
  QComboBox* formatBox() const { return format_; }
  QLineEdit* fileEdit() const { return file_; }
  QDoubleSpinBox* cellBox() const { return cell_; }
  QCheckBox* crsCheck() const { return use_crs_; }
  QLineEdit* crsEdit() const { return crs_; }
  QCheckBox* addOriginCheck() const { return add_origin_; }
  QPushButton* exportButton() const { return export_; }

 private:
  void formatChosen();
  void update();
  void browse();

  ExportPlace place_;
  QComboBox* format_ = nullptr;
  QLineEdit* file_ = nullptr;
  QComboBox* frame_ = nullptr;
  QDoubleSpinBox* cell_ = nullptr;
  QCheckBox* use_crs_ = nullptr;
  QLineEdit* crs_ = nullptr;
  QLabel* crs_note_ = nullptr;
  QCheckBox* add_origin_ = nullptr;
  QLabel* problem_label_ = nullptr;
  QPushButton* export_ = nullptr;
  QString problem_;
};

}  // namespace sonarcarve::gui
