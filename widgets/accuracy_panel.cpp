#include "accuracy_panel.h"

#include <QLabel>
#include <QVBoxLayout>

namespace sonarcarve::widgets {
namespace {

QString percent(double fraction) {
  return QStringLiteral("%1 %").arg(100.0 * fraction, 0, 'f', 1);
}

QString centimetres(double metres) {
  return QStringLiteral("%1 cm").arg(100.0 * metres, 0, 'f', 2);
}

}  // namespace

AccuracyPanel::AccuracyPanel(QWidget* parent) : QWidget(parent), label_(new QLabel) {
  label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(label_);
  layout->addStretch(1);
  showNoGroundTruth();
}

void AccuracyPanel::showNoGroundTruth() {
  label_->setText(tr("No ground truth: accuracy needs ground_truth.ply in the mission's folder."));
}

void AccuracyPanel::showPending() {
  label_->setText(tr("The run is measured against the ground truth when it ends."));
}

void AccuracyPanel::showEvaluating() {
  label_->setText(tr("Measuring the run against the ground truth…"));
}

void AccuracyPanel::showResult(const EvaluationResult& r) {
  const QString tau = QString::number(100.0 * r.tau_m, 'g', 3);
  QStringList lines;
  lines << tr("F-score at %1 cm: %2").arg(tau).arg(r.fscore, 0, 'f', 3)
        << tr("median error: %1").arg(centimetres(r.accuracy_median_m))
        << tr("90th percentile error: %1").arg(centimetres(r.accuracy_p90_m))
        << tr("precision (points within %1 cm): %2").arg(tau, percent(r.precision))
        << tr("completeness (truth within %1 cm): %2").arg(tau, percent(r.completeness));
  if (r.reference_points_horizontal > 0) {
    lines << tr("  on horizontal faces: %1 of %2 points")
                 .arg(percent(r.completeness_horizontal))
                 .arg(r.reference_points_horizontal);
  }
  if (r.reference_points_other > 0) {
    lines << tr("  on other faces: %1 of %2 points")
                 .arg(percent(r.completeness_other))
                 .arg(r.reference_points_other);
  }
  lines << tr("surface points: %1, reference points: %2")
               .arg(r.reconstructed_points)
               .arg(r.reference_points);
  label_->setText(lines.join('\n'));
}

QString AccuracyPanel::text() const {
  return label_->text();
}

}  // namespace sonarcarve::widgets
