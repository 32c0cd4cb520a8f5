// RunChoicesPanel: the automatic choices of the last run (pipeline/run_choice.h), one row each:
// what was decided, its value and the reason in an analyst's words; a warning is marked.
// Clicking a row opens it: how it was derived (for an expert) and what the analyst could do.
// GUI thread only.
#pragma once

#include <QWidget>
#include <vector>

#include "pipeline/run_choice.h"

class QTreeWidget;

namespace sonarcarve::widgets {

class RunChoicesPanel : public QWidget {
  Q_OBJECT
 public:
  explicit RunChoicesPanel(QWidget* parent = nullptr);
  void setChoices(const std::vector<RunChoice>& choices);
  void clear();
  /// Rows shown (one per choice).
  int rowCount() const;
  /// The tree, for tests that click a row.
  QTreeWidget* tree() const { return tree_; }

 private:
  QTreeWidget* tree_ = nullptr;
};

}  // namespace sonarcarve::widgets
