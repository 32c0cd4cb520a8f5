#include "params_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include "common/angles.h"

namespace sonarcarve::widgets {
namespace {

QDoubleSpinBox* number(double lo, double hi, double step, int decimals, const QString& suffix,
                       const QString& tip) {
  auto* box = new QDoubleSpinBox;
  box->setRange(lo, hi);
  box->setSingleStep(step);
  box->setDecimals(decimals);
  box->setSuffix(suffix);
  box->setToolTip(tip);
  box->setKeyboardTracking(false);
  return box;
}

QSpinBox* integer(int lo, int hi, const QString& tip) {
  auto* box = new QSpinBox;
  box->setRange(lo, hi);
  box->setToolTip(tip);
  box->setKeyboardTracking(false);
  return box;
}

}  // namespace

ParamsPanel::ParamsPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);

  auto* detector = new QGroupBox(tr("Denoising"), this);
  auto* df = new QFormLayout(detector);
  detector_mode_ = new QComboBox;
  detector_mode_->addItems({"auto", "none", "ztest", "cfar", "probability"});
  detector_mode_->setToolTip(
      tr("auto: Z-test with a noise model, none without; cfar needs no noise model"));
  df->addRow(tr("Detector"), detector_mode_);
  z_ = number(0.1, 20.0, 0.25, 2, tr(" σ"),
              tr("Z-test: keep pixels this many standard "
                 "deviations above the empty-water mean"));
  df->addRow(tr("Z threshold"), z_);
  cfar_pfa_ = number(0.0001, 0.5, 0.01, 4, "", tr("CFAR false-alarm probability per cell"));
  df->addRow(tr("CFAR Pfa"), cfar_pfa_);
  smoothing_ = integer(1, 15, tr("Box filter side before the test (odd; 1 = none)"));
  smoothing_->setSingleStep(2);
  df->addRow(tr("Smoothing"), smoothing_);
  auto* model_row = new QHBoxLayout;
  noise_model_ = new QLineEdit;
  noise_model_->setPlaceholderText(tr("none (learn with sonarcarve-cli noise-model)"));
  auto* browse = new QToolButton;
  browse->setText("…");
  model_row->addWidget(noise_model_);
  model_row->addWidget(browse);
  df->addRow(tr("Noise model"), model_row);
  layout->addWidget(detector);

  auto* carving = new QGroupBox(tr("Carving"), this);
  auto* cf = new QFormLayout(carving);
  threshold_ = number(0.0, 65535.0, 10.0, 1, "", tr("Pixels at or below this are empty water"));
  cf->addRow(tr("Intensity threshold"), threshold_);
  voxel_size_cm_ = number(0.5, 50.0, 0.5, 1, tr(" cm"), tr("Edge of a map voxel"));
  cf->addRow(tr("Voxel size"), voxel_size_cm_);
  elevation_step_deg_ =
      number(0.01, 5.0, 0.05, 2, tr("°"), tr("Step along each pixel's elevation arc"));
  cf->addRow(tr("Elevation step"), elevation_step_deg_);
  aperture_deg_ = number(0.0, 90.0, 1.0, 1, tr("°"), tr("Vertical aperture; 0 = the sonar's own"));
  aperture_deg_->setSpecialValueText(tr("sonar's own"));
  cf->addRow(tr("Vertical aperture"), aperture_deg_);
  range_min_m_ = number(0.0, 500.0, 0.1, 2, tr(" m"), tr("Nearest range used"));
  cf->addRow(tr("Range min"), range_min_m_);
  range_max_m_ = number(0.0, 500.0, 0.5, 2, tr(" m"), tr("Farthest range used; 0 = the sonar's"));
  range_max_m_->setSpecialValueText(tr("sonar's own"));
  cf->addRow(tr("Range max"), range_max_m_);
  layout->addWidget(carving);

  auto* frames = new QGroupBox(tr("Frames"), this);
  auto* ff = new QFormLayout(frames);
  first_frame_ = integer(0, 10000000, tr("First frame used"));
  ff->addRow(tr("First"), first_frame_);
  last_frame_ = integer(-1, 10000000, tr("One past the last frame used; -1 = to the end"));
  last_frame_->setSpecialValueText(tr("end"));
  ff->addRow(tr("Last (exclusive)"), last_frame_);
  stride_ = integer(1, 1000, tr("Use every n-th frame"));
  ff->addRow(tr("Stride"), stride_);
  layout->addWidget(frames);

  auto* surface = new QGroupBox(tr("Surface"), this);
  auto* sf = new QFormLayout(surface);
  min_views_ = integer(1, 1000, tr("A surface voxel must be the first return in this many views"));
  sf->addRow(tr("Min views"), min_views_);
  mesh_ = new QCheckBox(tr("Build a mesh"));
  sf->addRow(mesh_);
  layout->addWidget(surface);
  layout->addStretch(1);

  setParams(ReconstructionParams{});
  settle_.setSingleShot(true);
  settle_.setInterval(kSettle_ms);
  connect(&settle_, &QTimer::timeout, this, &ParamsPanel::paramsEdited);
  connect(browse, &QToolButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Noise model"), QString(),
                                                      tr("Noise models (*.yaml *.yml)"));
    if (!file.isEmpty()) {
      noise_model_->setText(file);
      edited();
    }
  });
  connect(detector_mode_, &QComboBox::currentIndexChanged, this, &ParamsPanel::edited);
  connect(noise_model_, &QLineEdit::editingFinished, this, &ParamsPanel::edited);
  for (auto* box : {z_, cfar_pfa_, threshold_, voxel_size_cm_, elevation_step_deg_, aperture_deg_,
                    range_min_m_, range_max_m_}) {
    connect(box, &QDoubleSpinBox::valueChanged, this, &ParamsPanel::edited);
  }
  for (auto* box : {smoothing_, first_frame_, last_frame_, stride_, min_views_}) {
    connect(box, &QSpinBox::valueChanged, this, &ParamsPanel::edited);
  }
  connect(mesh_, &QCheckBox::toggled, this, &ParamsPanel::edited);
}

void ParamsPanel::setParams(const ReconstructionParams& p) {
  base_ = p;
  const QSignalBlocker blockers[] = {
      QSignalBlocker(detector_mode_), QSignalBlocker(z_),
      QSignalBlocker(cfar_pfa_),      QSignalBlocker(smoothing_),
      QSignalBlocker(noise_model_),   QSignalBlocker(threshold_),
      QSignalBlocker(voxel_size_cm_), QSignalBlocker(elevation_step_deg_),
      QSignalBlocker(aperture_deg_),  QSignalBlocker(range_min_m_),
      QSignalBlocker(range_max_m_),   QSignalBlocker(first_frame_),
      QSignalBlocker(last_frame_),    QSignalBlocker(stride_),
      QSignalBlocker(min_views_),     QSignalBlocker(mesh_)};
  detector_mode_->setCurrentText(QString::fromStdString(p.detector.mode));
  z_->setValue(p.detector.z);
  cfar_pfa_->setValue(p.detector.cfar_pfa);
  smoothing_->setValue(p.detector.smoothing);
  noise_model_->setText(QString::fromStdString(p.noise_model));
  threshold_->setValue(p.carve.intensity_threshold);
  voxel_size_cm_->setValue(p.carve.voxel_size_m * 100.0);
  elevation_step_deg_->setValue(radToDeg(p.carve.elevation_step_rad));
  aperture_deg_->setValue(radToDeg(p.vertical_aperture_rad));
  range_min_m_->setValue(p.carve.range_min_m);
  range_max_m_->setValue(p.carve.range_max_m);
  first_frame_->setValue(static_cast<int>(p.first_frame));
  last_frame_->setValue(static_cast<int>(p.last_frame));
  stride_->setValue(static_cast<int>(p.stride));
  min_views_->setValue(static_cast<int>(p.min_views));
  mesh_->setChecked(p.mesh_enabled);
  updateEnabled();
}

ReconstructionParams ParamsPanel::params() const {
  ReconstructionParams p = base_;
  p.detector.mode = detector_mode_->currentText().toStdString();
  p.detector.z = z_->value();
  p.detector.cfar_pfa = cfar_pfa_->value();
  p.detector.smoothing = smoothing_->value();
  p.noise_model = noise_model_->text().trimmed().toStdString();
  p.carve.intensity_threshold = threshold_->value();
  p.carve.voxel_size_m = voxel_size_cm_->value() / 100.0;
  p.carve.elevation_step_rad = degToRad(elevation_step_deg_->value());
  p.vertical_aperture_rad = degToRad(aperture_deg_->value());
  p.carve.range_min_m = range_min_m_->value();
  p.carve.range_max_m = range_max_m_->value();
  p.first_frame = static_cast<std::size_t>(first_frame_->value());
  p.last_frame = last_frame_->value();
  p.stride = static_cast<std::size_t>(stride_->value());
  p.min_views = static_cast<std::uint32_t>(min_views_->value());
  p.mesh_enabled = mesh_->isChecked();
  return p;
}

void ParamsPanel::edited() {
  updateEnabled();
  settle_.start();
}

void ParamsPanel::updateEnabled() {
  const QString mode = detector_mode_->currentText();
  const bool model = !noise_model_->text().trimmed().isEmpty();
  z_->setEnabled(mode == "ztest" || (mode == "auto" && model));
  cfar_pfa_->setEnabled(mode == "cfar");
  smoothing_->setEnabled(mode != "none" && !(mode == "auto" && !model));
}

}  // namespace sonarcarve::widgets
