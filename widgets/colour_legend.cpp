#include "colour_legend.h"

#include <QPainter>
#include <cmath>

namespace sonarcarve::widgets {
namespace {

constexpr int kBarWidth = 180;
constexpr int kBarHeight = 10;
constexpr int kPadding = 6;

// Enough digits to tell the ends apart, no more.
QString number(double v, double span) {
  const int decimals = span >= 100.0 ? 0 : span >= 1.0 ? 2 : 3;
  return QString::number(v, 'f', decimals);
}

}  // namespace

ColourLegend::ColourLegend(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_TransparentForMouseEvents);
  resize(sizeHint());
}

void ColourLegend::setScale(const QString& title, double low, double high,
                            const ColourTable& colours) {
  if (title == title_ && low == low_ && high == high_ && &colours == colours_) {
    return;  // set at every redraw of the 3D view: no repaint for nothing
  }
  title_ = title;
  low_ = low;
  high_ = high;
  colours_ = &colours;
  update();
}

QString ColourLegend::text() const {
  const double span = std::abs(high_ - low_);
  return QStringLiteral("%1: %2 to %3").arg(title_, number(low_, span), number(high_, span));
}

QSize ColourLegend::sizeHint() const {
  const int line = fontMetrics().height();
  return {kBarWidth + 2 * kPadding, 2 * line + kBarHeight + 3 * kPadding};
}

void ColourLegend::paintEvent(QPaintEvent*) {
  if (colours_ == nullptr) {
    return;
  }
  QPainter painter(this);
  painter.fillRect(rect(), QColor(20, 24, 30, 200));
  const int line = fontMetrics().height();
  painter.setPen(QColor(230, 230, 230));
  painter.drawText(QRect(kPadding, kPadding, kBarWidth, line), Qt::AlignLeft, title_);
  const int bar_top = kPadding + line + kPadding / 2;
  for (int x = 0; x < kBarWidth; ++x) {
    const Rgb& c = (*colours_)[static_cast<std::size_t>(x * 255 / (kBarWidth - 1))];
    painter.fillRect(kPadding + x, bar_top, 1, kBarHeight, QColor(c[0], c[1], c[2]));
  }
  const double span = std::abs(high_ - low_);
  const QRect labels(kPadding, bar_top + kBarHeight + 2, kBarWidth, line);
  painter.drawText(labels, Qt::AlignLeft, number(low_, span));
  painter.drawText(labels, Qt::AlignRight, number(high_, span));
}

}  // namespace sonarcarve::widgets
