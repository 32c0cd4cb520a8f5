#include "run_choices_panel.h"

#include <QHeaderView>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace sonarcarve::widgets {

RunChoicesPanel::RunChoicesPanel(QWidget* parent) : QWidget(parent), tree_(new QTreeWidget) {
  tree_->setObjectName("runChoices");
  tree_->setColumnCount(3);
  tree_->setHeaderLabels({tr("Choice"), tr("Value"), tr("Why")});
  tree_->setWordWrap(true);
  tree_->setRootIsDecorated(true);
  tree_->header()->setStretchLastSection(true);
  tree_->setToolTip(
      tr("What the run decided by itself. Click a row for how it was derived and "
         "what you could do."));
  // One click opens a choice's detail (expanding by double-click is Qt's default).
  connect(tree_, &QTreeWidget::itemClicked, this, [](QTreeWidgetItem* item) {
    if (item->childCount() > 0) {
      item->setExpanded(!item->isExpanded());
    }
  });
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(tree_);
}

void RunChoicesPanel::setChoices(const std::vector<RunChoice>& choices) {
  tree_->clear();
  for (const RunChoice& choice : choices) {
    auto* row = new QTreeWidgetItem(
        tree_, {QString::fromStdString(choice.name), QString::fromStdString(choice.value),
                QString::fromStdString(choice.reason)});
    if (choice.warning) {
      row->setIcon(0, style()->standardIcon(QStyle::SP_MessageBoxWarning));
    }
    const auto line = [row](const QString& label, const std::string& text) {
      auto* child = new QTreeWidgetItem(row, {label, QString(), QString::fromStdString(text)});
      child->setFirstColumnSpanned(false);
      child->setToolTip(2, QString::fromStdString(text));
    };
    line(tr("how"), choice.detail);
    if (!choice.action.empty()) {
      line(tr("what to do"), choice.action);
    }
    row->setToolTip(2, QString::fromStdString(choice.reason));
  }
  tree_->resizeColumnToContents(0);
  tree_->resizeColumnToContents(1);
}

void RunChoicesPanel::clear() {
  tree_->clear();
}

int RunChoicesPanel::rowCount() const {
  return tree_->topLevelItemCount();
}

}  // namespace sonarcarve::widgets
