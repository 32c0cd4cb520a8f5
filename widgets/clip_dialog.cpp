#include "clip_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

namespace sonarcarve::widgets {
namespace {

QDoubleSpinBox* metres(double value) {
  auto* spin = new QDoubleSpinBox;
  spin->setRange(-1e5, 1e5);
  spin->setDecimals(3);
  spin->setSingleStep(0.05);
  spin->setSuffix(" m");
  spin->setValue(value);
  return spin;
}

}  // namespace

ClipDialog::ClipDialog(const ViewClip& current, const Eigen::AlignedBox3d& data_bounds,
                       QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Clip box and cross-section"));
  const Eigen::AlignedBox3d bounds =
      data_bounds.isEmpty() ? Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones())
                            : data_bounds;
  const Eigen::AlignedBox3d box = current.box.value_or(bounds);

  box_ = new QGroupBox(tr("Draw only what lies in the box (world NED)"));
  box_->setCheckable(true);
  box_->setChecked(current.box.has_value());
  auto* grid = new QGridLayout(box_);
  grid->addWidget(new QLabel(tr("min")), 0, 1);
  grid->addWidget(new QLabel(tr("max")), 0, 2);
  const char* names[3] = {QT_TR_NOOP("north"), QT_TR_NOOP("east"), QT_TR_NOOP("down")};
  for (int axis = 0; axis < 3; ++axis) {
    min_[axis] = metres(box.min()[axis]);
    max_[axis] = metres(box.max()[axis]);
    min_[axis]->setObjectName(QStringLiteral("min_%1").arg(axis));
    max_[axis]->setObjectName(QStringLiteral("max_%1").arg(axis));
    grid->addWidget(new QLabel(tr(names[axis])), axis + 1, 0);
    grid->addWidget(min_[axis], axis + 1, 1);
    grid->addWidget(max_[axis], axis + 1, 2);
  }

  section_ = new QGroupBox(tr("Cross-section: a slab across one axis"));
  section_->setCheckable(true);
  section_->setChecked(current.section.has_value());
  const ViewClip::Section section =
      current.section.value_or(ViewClip::Section{ViewClip::Axis::North, bounds.center().x(), 0.1});
  auto* form = new QFormLayout(section_);
  axis_ = new QComboBox;
  axis_->addItems({tr("north"), tr("east"), tr("down")});
  axis_->setCurrentIndex(static_cast<int>(section.axis));
  position_ = metres(section.position_m);
  thickness_ = metres(section.thickness_m);
  thickness_->setRange(0.001, 1e4);
  form->addRow(tr("across"), axis_);
  form->addRow(tr("at"), position_);
  form->addRow(tr("thickness"), thickness_);
  // A new axis starts at the middle of the data along it.
  connect(axis_, &QComboBox::activated, this,
          [this, bounds](int axis) { position_->setValue(bounds.center()[axis]); });

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(box_);
  layout->addWidget(section_);
  layout->addWidget(buttons);
}

ViewClip ClipDialog::clip() const {
  ViewClip clip;
  if (box_->isChecked()) {
    Eigen::AlignedBox3d box;
    for (int axis = 0; axis < 3; ++axis) {
      box.min()[axis] = std::min(min_[axis]->value(), max_[axis]->value());
      box.max()[axis] = std::max(min_[axis]->value(), max_[axis]->value());
    }
    clip.box = box;
  }
  if (section_->isChecked()) {
    clip.section = ViewClip::Section{static_cast<ViewClip::Axis>(axis_->currentIndex()),
                                     position_->value(), thickness_->value()};
  }
  return clip;
}

}  // namespace sonarcarve::widgets
