// ParamsPanel: the reconstruction parameters an analyst tunes, filling the same
// ReconstructionParams struct the CLI reads from YAML. Its group boxes and editors are built
// from the parameter schema (pipeline/param_schema.h): the entries analysts tune are shown,
// the rest under "More parameters". Edits are reported once the user pauses (`kSettle_ms`), so
// that dragging a spin box re-runs the reconstruction once, not at every step. GUI thread only.
#pragma once

#include <QTimer>
#include <QWidget>
#include <memory>
#include <string_view>
#include <vector>

#include "pipeline/reconstruction_params.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;

namespace sonarcarve::widgets {

class ParamEditor;

class ParamsPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kSettle_ms = 350;

  explicit ParamsPanel(QWidget* parent = nullptr);
  ~ParamsPanel() override;
  /// Shows `params` without emitting paramsEdited.
  void setParams(const ReconstructionParams& params);
  /// The values the user changed on top of the last params set: a value not edited keeps its
  /// exact value, whatever the editor's decimals.
  ReconstructionParams params() const;

  /// The editor of a schema entry by its YAML key ("detector.z"), for tests and buddies.
  QWidget* editor(std::string_view key) const;
  QComboBox* detectorMode() const;
  QDoubleSpinBox* voxelSize() const;  ///< in cm
  QDoubleSpinBox* zThreshold() const;
  /// Shows the entries not shown by default.
  QCheckBox* moreParameters() const { return more_; }

 signals:
  /// The user changed a value and paused.
  void paramsEdited();

 private:
  struct Row {
    std::unique_ptr<ParamEditor> editor;
    QFormLayout* form = nullptr;
    std::string shown;  ///< the value setParams showed, as text, to tell edits apart
  };

  void edited();
  void updateEnabled();
  void showAdvanced(bool show);

  ReconstructionParams base_;
  QTimer settle_;
  std::vector<Row> rows_;  // one per schema entry, in schema order
  std::vector<QGroupBox*> groups_;
  QCheckBox* more_ = nullptr;
  bool showing_ = false;  // setParams is filling the editors: not an edit
};

}  // namespace sonarcarve::widgets
