#include "params_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QVBoxLayout>
#include <algorithm>

#include "param_editors.h"
#include "pipeline/param_schema.h"

namespace sonarcarve::widgets {

ParamsPanel::ParamsPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  for (const ParamSpec& spec : paramSchema()) {
    const QString group =
        QString::fromUtf8(spec.gui.group.data(), static_cast<qsizetype>(spec.gui.group.size()));
    auto found = std::find_if(groups_.begin(), groups_.end(),
                              [&](QGroupBox* box) { return box->title() == group; });
    if (found == groups_.end()) {
      auto* box = new QGroupBox(group, this);
      new QFormLayout(box);
      layout->addWidget(box);
      found = groups_.insert(groups_.end(), box);
    }
    auto* form = static_cast<QFormLayout*>((*found)->layout());
    Row row{makeParamEditor(spec, *found), form, {}};
    if (spec.type() == ParamType::Bool) {
      form->addRow(row.editor->widget());  // the check box carries its label
    } else {
      form->addRow(
          QString::fromUtf8(spec.gui.label.data(), static_cast<qsizetype>(spec.gui.label.size())),
          row.editor->widget());
    }
    row.editor->onChange([this] { edited(); });
    rows_.push_back(std::move(row));
  }
  more_ = new QCheckBox(tr("More parameters"), this);
  more_->setToolTip(tr("Show every parameter of the YAML file, not only the usual ones"));
  layout->addWidget(more_);
  layout->addStretch(1);
  connect(more_, &QCheckBox::toggled, this, &ParamsPanel::showAdvanced);
  showAdvanced(false);

  setParams(ReconstructionParams{});
  settle_.setSingleShot(true);
  settle_.setInterval(kSettle_ms);
  connect(&settle_, &QTimer::timeout, this, &ParamsPanel::paramsEdited);
}

ParamsPanel::~ParamsPanel() = default;

void ParamsPanel::setParams(const ReconstructionParams& p) {
  base_ = p;
  showing_ = true;
  for (Row& row : rows_) {
    const ParamSpec& spec = row.editor->spec();
    row.editor->show(spec.get(p));
    // What the editor shows after its rounding and clamping: a value read back equal to this
    // was not edited.
    const auto shown = row.editor->value();
    row.shown = shown ? formatParam(spec, *shown) : "";
  }
  showing_ = false;
  updateEnabled();
}

ReconstructionParams ParamsPanel::params() const {
  ReconstructionParams p = base_;
  for (const Row& row : rows_) {
    const ParamSpec& spec = row.editor->spec();
    const auto value = row.editor->value();
    if (value && formatParam(spec, *value) != row.shown) {
      spec.set(p, *value);
    }
  }
  return p;
}

QWidget* ParamsPanel::editor(std::string_view key) const {
  for (const Row& row : rows_) {
    if (row.editor->spec().key == key) {
      return row.editor->widget();
    }
  }
  return nullptr;
}

QComboBox* ParamsPanel::detectorMode() const {
  return qobject_cast<QComboBox*>(editor("detector.mode"));
}

QDoubleSpinBox* ParamsPanel::voxelSize() const {
  return qobject_cast<QDoubleSpinBox*>(editor("voxel_size_m"));
}

QDoubleSpinBox* ParamsPanel::zThreshold() const {
  return qobject_cast<QDoubleSpinBox*>(editor("detector.z"));
}

void ParamsPanel::edited() {
  if (showing_) {
    return;
  }
  updateEnabled();
  settle_.start();
}

void ParamsPanel::updateEnabled() {
  const ReconstructionParams p = params();
  for (const Row& row : rows_) {
    const ParamSpec& spec = row.editor->spec();
    row.editor->widget()->setEnabled(spec.applies == nullptr || spec.applies(p));
  }
}

void ParamsPanel::showAdvanced(bool show) {
  for (const Row& row : rows_) {
    row.form->setRowVisible(row.editor->widget(), show || !row.editor->spec().gui.advanced);
  }
  for (QGroupBox* box : groups_) {
    const bool any = std::any_of(rows_.begin(), rows_.end(), [&](const Row& row) {
      return row.editor->widget()->parentWidget() == box &&
             (show || !row.editor->spec().gui.advanced);
    });
    box->setVisible(any);
  }
}

}  // namespace sonarcarve::widgets
