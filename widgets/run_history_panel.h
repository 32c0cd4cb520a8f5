// RunHistoryPanel: the runs of the session, newest last: when each started, its figures
// (frames, occupied voxels, surface points, seconds, F-score when the mission has a ground
// truth). Two runs selected are compared side by side (the parameters that differ, then the
// figures); "Go back" asks to restore one run's parameters; "Open report" opens one run's
// survey report (report.html) in the desktop's web browser. GUI thread only.
#pragma once

#include <QWidget>
#include <vector>

#include "session/run_record.h"

class QPushButton;
class QTableWidget;

namespace sonarcarve::widgets {

class RunHistoryPanel : public QWidget {
  Q_OBJECT
 public:
  explicit RunHistoryPanel(QWidget* parent = nullptr);
  void setRuns(const std::vector<RunRecord>& runs);
  int rowCount() const;
  /// Selects runs by their index (for tests and after a go-back).
  void selectRuns(const std::vector<int>& indices);
  std::vector<int> selectedRuns() const;
  /// The selected run's report.html when exactly one run with a report on disk is selected.
  QString selectedReport() const;
  /// Two runs side by side, as an HTML table: the parameters that differ, then the figures.
  static QString comparison(const RunRecord& a, int a_index, const RunRecord& b, int b_index);

 signals:
  /// The user asked to return to run `index`'s parameters.
  void goBackRequested(int index);

 private:
  void updateButtons();
  void compareSelected();
  QTableWidget* table_ = nullptr;
  QPushButton* compare_ = nullptr;
  QPushButton* go_back_ = nullptr;
  QPushButton* open_report_ = nullptr;
  std::vector<RunRecord> runs_;
};

}  // namespace sonarcarve::widgets
