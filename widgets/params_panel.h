// ParamsPanel: the reconstruction parameters an analyst tunes (detector and its threshold,
// carving, frame selection, surface extraction), filling the same ReconstructionParams struct
// the CLI reads from YAML. Edits are reported once the user pauses (`kSettle_ms`), so that
// dragging a spin box re-runs the reconstruction once, not at every step. GUI thread only.
#pragma once

#include <QTimer>
#include <QWidget>

#include "pipeline/reconstruction_params.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace sonarcarve::widgets {

class ParamsPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kSettle_ms = 350;

  explicit ParamsPanel(QWidget* parent = nullptr);
  /// Shows `params` without emitting paramsEdited.
  void setParams(const ReconstructionParams& params);
  /// The shown values on top of the last params set (keeps what the panel does not show,
  /// such as the region of interest and the mesh settings).
  ReconstructionParams params() const;

  // The editors, for tests and for keyboard users' buddies.
  QComboBox* detectorMode() const { return detector_mode_; }
  QDoubleSpinBox* voxelSize() const { return voxel_size_cm_; }
  QDoubleSpinBox* zThreshold() const { return z_; }

 signals:
  /// The user changed a value and paused.
  void paramsEdited();

 private:
  void edited();
  void updateEnabled();

  ReconstructionParams base_;
  QTimer settle_;
  QComboBox* detector_mode_ = nullptr;
  QDoubleSpinBox* z_ = nullptr;
  QDoubleSpinBox* cfar_pfa_ = nullptr;
  QSpinBox* smoothing_ = nullptr;
  QLineEdit* noise_model_ = nullptr;
  QDoubleSpinBox* threshold_ = nullptr;
  QDoubleSpinBox* voxel_size_cm_ = nullptr;
  QDoubleSpinBox* elevation_step_deg_ = nullptr;
  QDoubleSpinBox* aperture_deg_ = nullptr;
  QDoubleSpinBox* range_min_m_ = nullptr;
  QDoubleSpinBox* range_max_m_ = nullptr;
  QSpinBox* first_frame_ = nullptr;
  QSpinBox* last_frame_ = nullptr;
  QSpinBox* stride_ = nullptr;
  QSpinBox* min_views_ = nullptr;
  QCheckBox* mesh_ = nullptr;
};

}  // namespace sonarcarve::widgets
