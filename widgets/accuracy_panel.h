// AccuracyPanel: a run's accuracy against the mission's ground truth, as core's evaluator
// measured it: F-score, median and 90th-percentile error, precision, completeness (all, and
// on horizontal and other faces). Says so when the mission has no ground truth, and while the
// figures are being computed. GUI thread only.
#pragma once

#include <QWidget>

#include "eval/evaluator.h"

class QLabel;

namespace sonarcarve::widgets {

class AccuracyPanel : public QWidget {
  Q_OBJECT
 public:
  explicit AccuracyPanel(QWidget* parent = nullptr);
  void showNoGroundTruth();
  /// A ground truth exists: the figures come when the run ends.
  void showPending();
  void showEvaluating();
  void showResult(const EvaluationResult& result);
  /// What the panel says, one line per figure, for tests and the log.
  QString text() const;

 private:
  QLabel* label_ = nullptr;
};

}  // namespace sonarcarve::widgets
