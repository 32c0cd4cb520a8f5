#include "track_view.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>

namespace sonarcarve::widgets {
namespace {

const QColor kTrack(240, 210, 70);
const QColor kNow(255, 90, 70);
const QColor kText(200, 205, 212);

void frame(QPainter& painter, const QRectF& area, const QString& title) {
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QColor(70, 78, 90));
  painter.drawRect(area);
  painter.setPen(kText);
  painter.drawText(area.adjusted(4, 2, -4, -2), Qt::AlignTop | Qt::AlignLeft, title);
}

}  // namespace

TrackView::TrackView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(240, 120);
}

void TrackView::setTrack(std::vector<TrackPoint> track) {
  track_ = std::move(track);
  update();
}

void TrackView::setCurrentTime(double time_s) {
  current_time_s_ = time_s;
  update();
}

TrackPoint TrackView::at(double time_s) const {
  const auto it = std::lower_bound(track_.begin(), track_.end(), time_s,
                                   [](const TrackPoint& p, double t) { return p.time_s < t; });
  if (it == track_.begin()) {
    return track_.front();
  }
  if (it == track_.end()) {
    return track_.back();
  }
  const TrackPoint& a = *(it - 1);
  const TrackPoint& b = *it;
  const double u = (time_s - a.time_s) / std::max(1e-12, b.time_s - a.time_s);
  return {time_s, a.position_m + u * (b.position_m - a.position_m)};
}

void TrackView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(24, 27, 32));
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setFont(QFont(painter.font().family(), 8));
  if (track_.empty()) {
    painter.setPen(kText);
    painter.drawText(rect(), Qt::AlignCenter, tr("No navigation"));
    return;
  }
  const QRectF all = QRectF(rect()).adjusted(4, 4, -4, -4);
  const double split = all.width() * 0.42;
  paintPlan(painter, QRectF(all.left(), all.top(), split - 4, all.height()));
  paintDepth(painter,
             QRectF(all.left() + split + 4, all.top(), all.width() - split - 4, all.height()));
}

void TrackView::paintPlan(QPainter& painter, const QRectF& area) const {
  frame(painter, area, tr("plan (N up)"));
  Eigen::Vector2d lo(1e300, 1e300);
  Eigen::Vector2d hi(-1e300, -1e300);
  for (const TrackPoint& p : track_) {
    const Eigen::Vector2d ne = p.position_m.head<2>();
    lo = lo.cwiseMin(ne);
    hi = hi.cwiseMax(ne);
  }
  const Eigen::Vector2d centre = (lo + hi) / 2.0;
  const double span = std::max(1.0, std::max(hi.x() - lo.x(), hi.y() - lo.y()) * 1.2);
  const QRectF inner = area.adjusted(8, 18, -8, -8);
  const double scale = std::min(inner.width(), inner.height()) / span;
  const auto toScreen = [&](const Eigen::Vector3d& p) {
    return inner.center() + QPointF((p.y() - centre.y()) * scale, -(p.x() - centre.x()) * scale);
  };
  QPainterPath path(toScreen(track_.front().position_m));
  for (const TrackPoint& p : track_) {
    path.lineTo(toScreen(p.position_m));
  }
  painter.setPen(QPen(kTrack, 1.5));
  painter.drawPath(path);
  painter.setPen(kText);
  painter.drawText(area.adjusted(4, 2, -4, -2), Qt::AlignBottom | Qt::AlignRight,
                   tr("%1 m across").arg(span, 0, 'g', 3));
  painter.setBrush(kNow);
  painter.setPen(Qt::NoPen);
  painter.drawEllipse(toScreen(at(current_time_s_).position_m), 4, 4);
}

void TrackView::paintDepth(QPainter& painter, const QRectF& area) const {
  frame(painter, area, tr("depth (m) vs time (s)"));
  double d_lo = 1e300;
  double d_hi = -1e300;
  for (const TrackPoint& p : track_) {
    d_lo = std::min(d_lo, p.position_m.z());
    d_hi = std::max(d_hi, p.position_m.z());
  }
  if (d_hi - d_lo < 0.5) {
    d_lo -= 0.25;
    d_hi += 0.25;
  }
  const double t0 = track_.front().time_s;
  const double t1 = std::max(t0 + 1e-9, track_.back().time_s);
  const QRectF inner = area.adjusted(40, 18, -8, -16);
  const auto toScreen = [&](double t, double d) {
    return QPointF(inner.left() + (t - t0) / (t1 - t0) * inner.width(),
                   inner.top() + (d - d_lo) / (d_hi - d_lo) * inner.height());
  };
  painter.setPen(kText);
  painter.drawText(QRectF(area.left(), inner.top() - 6, 36, 12), Qt::AlignRight,
                   QString::number(d_lo, 'f', 1));
  painter.drawText(QRectF(area.left(), inner.bottom() - 6, 36, 12), Qt::AlignRight,
                   QString::number(d_hi, 'f', 1));
  painter.drawText(QRectF(inner.left(), inner.bottom() + 2, 60, 12), Qt::AlignLeft,
                   QString::number(t0, 'f', 0));
  painter.drawText(QRectF(inner.right() - 60, inner.bottom() + 2, 60, 12), Qt::AlignRight,
                   QString::number(t1, 'f', 0));
  QPainterPath path(toScreen(track_.front().time_s, track_.front().position_m.z()));
  for (const TrackPoint& p : track_) {
    path.lineTo(toScreen(p.time_s, p.position_m.z()));
  }
  painter.setPen(QPen(kTrack, 1.5));
  painter.drawPath(path);
  const TrackPoint now = at(current_time_s_);
  painter.setPen(QPen(kNow, 1.0, Qt::DashLine));
  const QPointF marker = toScreen(current_time_s_, now.position_m.z());
  painter.drawLine(QPointF(marker.x(), inner.top()), QPointF(marker.x(), inner.bottom()));
  painter.setBrush(kNow);
  painter.setPen(Qt::NoPen);
  painter.drawEllipse(marker, 4, 4);
}

}  // namespace sonarcarve::widgets
