#include "axes_triad.h"

#include <QPainter>
#include <cmath>

namespace sonarcarve::widgets {
namespace {

constexpr int kSide = 84;
constexpr double kLength = 28.0;

}  // namespace

AxesTriad::AxesTriad(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_TransparentForMouseEvents);
  resize(kSide, kSide);
}

void AxesTriad::setAxes(const std::array<QPointF, 3>& on_screen) {
  // Called at every render of the 3D view: a repaint only when the axes turned (each one is a
  // repaint of the whole window).
  if (on_screen == axes_) {
    return;
  }
  axes_ = on_screen;
  update();
}

void AxesTriad::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  const QPointF centre(kSide / 2.0, kSide / 2.0);
  static const std::array<QColor, 3> colours{QColor(235, 80, 70), QColor(90, 200, 90),
                                             QColor(90, 150, 245)};
  static const std::array<const char*, 3> names{"N", "E", "D"};
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    const QPointF tip = centre + kLength * axes_[i];
    painter.setPen(QPen(colours[i], 2.0));
    painter.drawLine(centre, tip);
    const QPointF label = centre + (kLength + 9.0) * axes_[i];
    painter.drawText(QRectF(label.x() - 6, label.y() - 8, 12, 16), Qt::AlignCenter, names[i]);
  }
}

}  // namespace sonarcarve::widgets
