#include "scale_bar.h"

#include <QPainter>
#include <cmath>

namespace sonarcarve::widgets {
namespace {

constexpr int kPadding = 6;
constexpr int kTick = 5;

}  // namespace

ScaleBar::ScaleBar(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_TransparentForMouseEvents);
  resize(sizeHint());
  hide();
}

double ScaleBar::roundLength(double metres) {
  if (!(metres > 0.0) || !std::isfinite(metres)) {
    return 0.0;
  }
  const double decade = std::pow(10.0, std::floor(std::log10(metres)));
  for (double step : {5.0, 2.0, 1.0}) {
    // A little slack: 0.5 / 0.1 is 4.999999... in floating point.
    if (step * decade <= metres * (1.0 + 1e-9)) {
      return step * decade;
    }
  }
  return decade;
}

void ScaleBar::setMetresPerPixel(double metres) {
  if (metres == metres_per_pixel_) {
    return;  // called at every render of the 3D view: no repaint for nothing
  }
  metres_per_pixel_ = metres;
  length_m_ = roundLength(metres * kMaxBarPixels);
  setVisible(length_m_ > 0.0);
  update();
}

int ScaleBar::barPixels() const {
  return metres_per_pixel_ > 0.0 ? static_cast<int>(std::lround(length_m_ / metres_per_pixel_)) : 0;
}

QString ScaleBar::text() const {
  if (length_m_ >= 1.0) {
    return QStringLiteral("%1 m").arg(length_m_, 0, 'g', 6);
  }
  if (length_m_ >= 0.01) {
    return QStringLiteral("%1 cm").arg(std::round(length_m_ * 1e4) / 1e2, 0, 'g', 6);
  }
  return QStringLiteral("%1 mm").arg(std::round(length_m_ * 1e6) / 1e3, 0, 'g', 6);
}

QSize ScaleBar::sizeHint() const {
  return {kMaxBarPixels + 2 * kPadding, fontMetrics().height() + kTick + 3 * kPadding};
}

void ScaleBar::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(20, 24, 30, 200));
  painter.setPen(QPen(QColor(230, 230, 230), 2));
  const int bar = barPixels();
  const int y = height() - kPadding - 1;
  painter.drawLine(kPadding, y, kPadding + bar, y);
  painter.drawLine(kPadding, y, kPadding, y - kTick);
  painter.drawLine(kPadding + bar, y, kPadding + bar, y - kTick);
  painter.drawText(QRect(kPadding, kPadding, kMaxBarPixels, fontMetrics().height()), Qt::AlignLeft,
                   text());
}

}  // namespace sonarcarve::widgets
