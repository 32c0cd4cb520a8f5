// AxesTriad: the world's north, east and down axes as the 3D view's camera shows them, drawn
// over its corner (N red, E green, D blue, as x, y, z). GUI thread only.
#pragma once

#include <QPointF>
#include <QWidget>
#include <array>

namespace sonarcarve::widgets {

class AxesTriad : public QWidget {
  Q_OBJECT
 public:
  explicit AxesTriad(QWidget* parent = nullptr);
  /// Each axis's unit vector on the screen (x right, y down; shorter when it points at or away
  /// from the viewer), in the order north, east, down.
  void setAxes(const std::array<QPointF, 3>& on_screen);
  const std::array<QPointF, 3>& axes() const { return axes_; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  std::array<QPointF, 3> axes_{};
};

}  // namespace sonarcarve::widgets
