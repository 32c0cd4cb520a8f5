// ColourLegend: the key of the 3D view's colours, drawn over its corner: a bar of the colour
// table with the quantity, its unit and the values at both ends. GUI thread only.
#pragma once

#include <QWidget>

#include "colour_maps.h"

namespace sonarcarve::widgets {

class ColourLegend : public QWidget {
  Q_OBJECT
 public:
  explicit ColourLegend(QWidget* parent = nullptr);
  /// `title` names the quantity with its unit ("depth (m)"); `low` and `high` are the values
  /// at the table's ends, already in that unit.
  void setScale(const QString& title, double low, double high, const ColourTable& colours);
  /// "depth (m): 9.65 to 11.29", for tests and the status bar.
  QString text() const;
  QSize sizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QString title_;
  double low_ = 0.0;
  double high_ = 1.0;
  const ColourTable* colours_ = nullptr;
};

}  // namespace sonarcarve::widgets
