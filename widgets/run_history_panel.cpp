#include "run_history_panel.h"

#include <QDesktopServices>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>
#include <algorithm>

#include "pipeline/param_diff.h"

namespace sonarcarve::widgets {
namespace {

QString fscoreOf(const RunRecord& run) {
  return run.accuracy ? QString::number(run.accuracy->fscore, 'f', 3) : QStringLiteral("-");
}

// The figures of a run, by name, in the order both the table and the comparison show them.
std::vector<std::pair<QString, QString>> figuresOf(const RunRecord& run) {
  std::vector<std::pair<QString, QString>> figures{
      {QObject::tr("frames"), QString::number(run.frames)},
      {QObject::tr("occupied voxels"), QString::number(run.occupied_voxels)},
      {QObject::tr("surface points"), QString::number(run.surface_points)},
      {QObject::tr("mesh triangles"), QString::number(run.mesh_triangles)},
      {QObject::tr("time (s)"), QString::number(run.seconds, 'f', 1)},
  };
  if (run.accuracy) {
    const RunAccuracy& a = *run.accuracy;
    figures.insert(figures.end(),
                   {{QObject::tr("F-score at 5 cm"), fscoreOf(run)},
                    {QObject::tr("median error (cm)"), QString::number(100 * a.median_m, 'f', 2)},
                    {QObject::tr("90th pct. error (cm)"), QString::number(100 * a.p90_m, 'f', 2)},
                    {QObject::tr("precision"), QString::number(a.precision, 'f', 3)},
                    {QObject::tr("completeness"), QString::number(a.completeness, 'f', 3)}});
  }
  return figures;
}

QString row(const QString& name, const QString& a, const QString& b) {
  const bool same = a == b;
  return QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
      .arg(name.toHtmlEscaped(), same ? a.toHtmlEscaped() : "<b>" + a.toHtmlEscaped() + "</b>",
           same ? b.toHtmlEscaped() : "<b>" + b.toHtmlEscaped() + "</b>");
}

}  // namespace

RunHistoryPanel::RunHistoryPanel(QWidget* parent) : QWidget(parent) {
  table_ = new QTableWidget(0, 6);
  table_->setHorizontalHeaderLabels(
      {tr("started"), tr("frames"), tr("voxels"), tr("surface points"), tr("s"), tr("F@5cm")});
  table_->verticalHeader()->setVisible(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  compare_ = new QPushButton(tr("Compare"));
  compare_->setToolTip(tr("Select two runs to see their differing parameters and figures"));
  go_back_ = new QPushButton(tr("Go back to this run"));
  go_back_->setToolTip(tr("Restore the selected run's parameters and run them again"));
  open_report_ = new QPushButton(tr("Open report"));
  open_report_->setToolTip(
      tr("Open the selected run's survey report (report.html) in the web browser"));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(compare_);
  buttons->addWidget(go_back_);
  buttons->addWidget(open_report_);
  buttons->addStretch(1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(table_, 1);
  layout->addLayout(buttons);
  connect(table_, &QTableWidget::itemSelectionChanged, this, &RunHistoryPanel::updateButtons);
  connect(compare_, &QPushButton::clicked, this, &RunHistoryPanel::compareSelected);
  connect(go_back_, &QPushButton::clicked, this, [this] {
    const auto selected = selectedRuns();
    if (selected.size() == 1) {
      emit goBackRequested(selected.front());
    }
  });
  connect(open_report_, &QPushButton::clicked, this, [this] {
    const QString report = selectedReport();
    if (!report.isEmpty()) {
      QDesktopServices::openUrl(QUrl::fromLocalFile(report));
    }
  });
  updateButtons();
}

QString RunHistoryPanel::selectedReport() const {
  const auto selected = selectedRuns();
  if (selected.size() != 1) {
    return {};
  }
  const QString report =
      QString::fromStdString(runs_[static_cast<std::size_t>(selected.front())].report);
  return !report.isEmpty() && QFileInfo(report).isFile() ? report : QString();
}

void RunHistoryPanel::setRuns(const std::vector<RunRecord>& runs) {
  const auto selected = selectedRuns();
  runs_ = runs;
  table_->setRowCount(static_cast<int>(runs.size()));
  for (int i = 0; i < table_->rowCount(); ++i) {
    const RunRecord& run = runs_[static_cast<std::size_t>(i)];
    const QStringList cells{
        QString::fromStdString(run.started),  QString::number(run.frames),
        QString::number(run.occupied_voxels), QString::number(run.surface_points),
        QString::number(run.seconds, 'f', 1), fscoreOf(run)};
    for (int c = 0; c < cells.size(); ++c) {
      table_->setItem(i, c, new QTableWidgetItem(cells[c]));
    }
  }
  selectRuns(selected);
  updateButtons();
}

int RunHistoryPanel::rowCount() const {
  return table_->rowCount();
}

void RunHistoryPanel::selectRuns(const std::vector<int>& indices) {
  table_->clearSelection();
  for (int i : indices) {
    if (i >= 0 && i < table_->rowCount()) {
      table_->selectionModel()->select(table_->model()->index(i, 0),
                                       QItemSelectionModel::Select | QItemSelectionModel::Rows);
    }
  }
}

std::vector<int> RunHistoryPanel::selectedRuns() const {
  std::vector<int> rows;
  for (const QModelIndex& index : table_->selectionModel()->selectedRows()) {
    rows.push_back(index.row());
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

void RunHistoryPanel::updateButtons() {
  const auto selected = selectedRuns();
  compare_->setEnabled(selected.size() == 2);
  go_back_->setEnabled(selected.size() == 1);
  open_report_->setEnabled(!selectedReport().isEmpty());
}

QString RunHistoryPanel::comparison(const RunRecord& a, int a_index, const RunRecord& b,
                                    int b_index) {
  QString html = QStringLiteral(
                     "<table border='1' cellpadding='3'><tr><th></th><th>%1</th>"
                     "<th>%2</th></tr>")
                     .arg(tr("run %1").arg(a_index + 1), tr("run %1").arg(b_index + 1));
  html += row(tr("started"), QString::fromStdString(a.started), QString::fromStdString(b.started));
  const auto differences = differingParams(a.params, b.params);
  html += QStringLiteral("<tr><th colspan='3'>%1</th></tr>")
              .arg(differences.empty() ? tr("same parameters") : tr("parameters that differ"));
  for (const ParamDifference& d : differences) {
    const QString unit = d.unit.empty() ? QString() : QStringLiteral(" (%1)").arg(d.unit.c_str());
    html += row(QString::fromStdString(d.key) + unit, QString::fromStdString(d.a),
                QString::fromStdString(d.b));
  }
  html += QStringLiteral("<tr><th colspan='3'>%1</th></tr>").arg(tr("figures"));
  auto fa = figuresOf(a);
  auto fb = figuresOf(b);
  for (const auto& [name, value] : fa) {
    const auto other =
        std::find_if(fb.begin(), fb.end(), [&](const auto& f) { return f.first == name; });
    html += row(name, value, other != fb.end() ? other->second : QStringLiteral("-"));
  }
  return html + QStringLiteral("</table>");
}

void RunHistoryPanel::compareSelected() {
  const auto selected = selectedRuns();
  if (selected.size() != 2) {
    return;
  }
  const auto a = static_cast<std::size_t>(selected[0]);
  const auto b = static_cast<std::size_t>(selected[1]);
  auto* dialog = new QDialog(this);
  dialog->setObjectName("runComparison");
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->setWindowTitle(tr("Runs %1 and %2").arg(a + 1).arg(b + 1));
  auto* text = new QTextBrowser;
  text->setHtml(comparison(runs_[a], selected[0], runs_[b], selected[1]));
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(close, &QDialogButtonBox::rejected, dialog, &QDialog::close);
  auto* layout = new QVBoxLayout(dialog);
  layout->addWidget(text);
  layout->addWidget(close);
  dialog->resize(520, 420);
  dialog->open();
}

}  // namespace sonarcarve::widgets
