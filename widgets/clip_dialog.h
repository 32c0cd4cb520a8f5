// ClipDialog: asks for the 3D view's clip: a box by its north, east and down limits, and a
// cross-section (a slab across N, E or D at a position, of a thickness). Each part can be
// turned off. Starts from the clip in force, or from the data's bounds. GUI thread only.
#pragma once

#include <QDialog>

#include "view_clip.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;

namespace sonarcarve::widgets {

class ClipDialog : public QDialog {
  Q_OBJECT
 public:
  ClipDialog(const ViewClip& current, const Eigen::AlignedBox3d& data_bounds,
             QWidget* parent = nullptr);
  ViewClip clip() const;

 private:
  QGroupBox* box_ = nullptr;
  QGroupBox* section_ = nullptr;
  QDoubleSpinBox* min_[3] = {};
  QDoubleSpinBox* max_[3] = {};
  QComboBox* axis_ = nullptr;
  QDoubleSpinBox* position_ = nullptr;
  QDoubleSpinBox* thickness_ = nullptr;
};

}  // namespace sonarcarve::widgets
