#include "fan_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "common/angles.h"

namespace sonarcarve::widgets {
namespace {

constexpr int kMarginSide = 34;
constexpr int kMarginTop = 22;
constexpr int kMarginBottom = 10;

// A round ring spacing giving about five rings.
double ringStep(double max_range_m) {
  for (double step : {0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0}) {
    if (max_range_m / step <= 6.0) {
      return step;
    }
  }
  return 100.0;
}

}  // namespace

FanView::FanView(QString title, QWidget* parent) : QWidget(parent), title_(std::move(title)) {
  setMouseTracking(true);
  setMinimumSize(240, 180);
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void FanView::setSonar(const SonarModel& sonar) {
  sonar_ = sonar;
  image_.release();
  layoutFan();
  update();
}

void FanView::setFrame(const cv::Mat& image, float low, float high) {
  image_ = image;
  low_ = low;
  high_ = high > low ? high : low + 1.0f;
  renderFan();
  update();
}

void FanView::clearFrame() {
  image_.release();
  renderFan();
  update();
}

void FanView::setColourMap(ColourMap map) {
  colour_map_ = map;
  renderFan();
  update();
}

void FanView::resizeEvent(QResizeEvent*) {
  layoutFan();
}

void FanView::layoutFan() {
  lookup_.clear();
  grid_ = QImage();
  if (!sonar_) {
    return;
  }
  const double r_max = sonar_->range().maxRange();
  const double half_width =
      r_max * std::max(std::sin(std::min(M_PI / 2, std::abs(sonar_->bearings().leftEdge()))),
                       std::sin(std::min(M_PI / 2, std::abs(sonar_->bearings().rightEdge()))));
  const double usable_w = std::max(10, width() - 2 * kMarginSide);
  const double usable_h = std::max(10, height() - kMarginTop - kMarginBottom);
  px_per_m_ = std::min(usable_w / (2.0 * half_width), usable_h / r_max);
  apex_ = QPointF(width() / 2.0, height() - kMarginBottom);
  lookup_.assign(static_cast<std::size_t>(width()) * static_cast<std::size_t>(height()), -1);
  for (int y = 0; y < height(); ++y) {
    for (int x = 0; x < width(); ++x) {
      if (auto s = sampleAt(QPointF(x + 0.5, y + 0.5))) {
        lookup_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width()) +
                static_cast<std::size_t>(x)] = s->row * sonar_->cols() + s->col;
      }
    }
  }
  renderFan();
}

std::optional<FanSample> FanView::sampleAt(QPointF p) const {
  if (!sonar_) {
    return std::nullopt;
  }
  const double east = (p.x() - apex_.x()) / px_per_m_;
  const double forward = (apex_.y() - p.y()) / px_per_m_;
  FanSample s;
  s.range_m = std::hypot(east, forward);
  s.bearing_rad = std::atan2(east, forward);
  const auto row = sonar_->range().binOf(s.range_m);
  const auto col = sonar_->bearings().beamOf(s.bearing_rad);
  if (!row || !col) {
    return std::nullopt;
  }
  s.row = *row;
  s.col = *col;
  if (!image_.empty()) {
    s.value = image_.at<float>(s.row, s.col);
  }
  return s;
}

QPointF FanView::pointOf(double range_m, double bearing_rad) const {
  return apex_ + QPointF(std::sin(bearing_rad), -std::cos(bearing_rad)) * range_m * px_per_m_;
}

void FanView::renderFan() {
  fan_ = QImage(size(), QImage::Format_RGB32);
  fan_.fill(QColor(24, 27, 32));
  if (!sonar_ || lookup_.size() != static_cast<std::size_t>(width() * height())) {
    return;
  }
  const bool have_image =
      !image_.empty() && image_.rows == sonar_->rows() && image_.cols == sonar_->cols();
  const ColourTable& colours = coloursOf(colour_map_);
  const float scale = 255.0f / (high_ - low_);
  const auto* polar = have_image ? image_.ptr<float>(0) : nullptr;
  for (int y = 0; y < height(); ++y) {
    auto* line = reinterpret_cast<QRgb*>(fan_.scanLine(y));
    const int* index = lookup_.data() + static_cast<std::ptrdiff_t>(y) * width();
    for (int x = 0; x < width(); ++x) {
      if (index[x] < 0) {
        continue;
      }
      const float v = have_image ? (polar[index[x]] - low_) * scale : 0.0f;
      const Rgb& c = colours[static_cast<std::size_t>(std::clamp(v, 0.0f, 255.0f))];
      line[x] = qRgb(c[0], c[1], c[2]);
    }
  }
}

void FanView::drawGrid(QPainter& painter) const {
  const double r_max = sonar_->range().maxRange();
  const double left = sonar_->bearings().leftEdge();
  const double right = sonar_->bearings().rightEdge();
  painter.setPen(QPen(QColor(120, 200, 255, 110), 1.0));
  painter.setFont(QFont(painter.font().family(), 8));
  const double step = ringStep(r_max);
  for (double r = step; r <= r_max + 1e-9; r += step) {
    const double rad = r * px_per_m_;
    const QRectF box(apex_.x() - rad, apex_.y() - rad, 2 * rad, 2 * rad);
    // Qt's angles: degrees counter-clockwise from 3 o'clock; bearing 0 is 12 o'clock.
    painter.drawArc(box, static_cast<int>((90.0 - radToDeg(right)) * 16),
                    static_cast<int>(radToDeg(right - left) * 16));
    const QPointF at = pointOf(r, left);
    painter.drawText(at + QPointF(-30, 4), QString::number(r, 'g', 3) + " m");
  }
  const double bearing_step = degToRad(radToDeg(right - left) > 90.0 ? 30.0 : 15.0);
  for (double b = std::ceil(left / bearing_step) * bearing_step; b <= right + 1e-9;
       b += bearing_step) {
    painter.drawLine(apex_, pointOf(r_max, b));
    const QPointF at = pointOf(r_max, b) + QPointF(std::sin(b), -std::cos(b)) * 9.0;
    const QString label = QString::number(radToDeg(b), 'f', 0) + QChar(0x00B0);
    painter.drawText(QRectF(at.x() - 20, at.y() - 8, 40, 16), Qt::AlignCenter, label);
  }
  painter.drawLine(apex_, pointOf(r_max, left));
  painter.drawLine(apex_, pointOf(r_max, right));
}

void FanView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.drawImage(0, 0, fan_);
  // The grid is drawn once per size and sonar, not at every frame of a run.
  if (sonar_ && grid_.size() != size()) {
    grid_ = QImage(size(), QImage::Format_ARGB32_Premultiplied);
    grid_.fill(Qt::transparent);
    QPainter grid_painter(&grid_);
    grid_painter.setRenderHint(QPainter::Antialiasing);
    drawGrid(grid_painter);
  }
  if (sonar_) {
    painter.drawImage(0, 0, grid_);
  }
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setPen(QColor(230, 230, 230));
  painter.setFont(QFont(painter.font().family(), 9, QFont::Bold));
  painter.drawText(rect().adjusted(6, 4, -6, -4), Qt::AlignTop | Qt::AlignRight, title_);
  if (!readout_.isEmpty()) {
    painter.setFont(QFont(painter.font().family(), 9));
    painter.drawText(rect().adjusted(6, 4, -6, -4), Qt::AlignTop | Qt::AlignLeft, readout_);
  }
  if (!sonar_) {
    painter.drawText(rect(), Qt::AlignCenter, tr("No mission open"));
  }
}

void FanView::mouseMoveEvent(QMouseEvent* event) {
  const auto s = sampleAt(event->position());
  readout_ = s ? QString("range %1 m  bearing %2%3  intensity %4")
                     .arg(s->range_m, 0, 'f', 2)
                     .arg(radToDeg(s->bearing_rad), 0, 'f', 1)
                     .arg(QChar(0x00B0))
                     .arg(static_cast<double>(s->value), 0, 'f', 0)
               : QString();
  emit hovered(readout_);
  update();
}

void FanView::leaveEvent(QEvent*) {
  readout_.clear();
  update();
}

}  // namespace sonarcarve::widgets
