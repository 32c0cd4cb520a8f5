// TrackView: the navigation track in plan (north up, east to the right, equal scales) and its
// depth against time (depth increasing downwards), with the vehicle's position at the current
// frame's time marked in both. GUI thread only.
#pragma once

#include <Eigen/Core>
#include <QWidget>
#include <vector>

namespace sonarcarve::widgets {

struct TrackPoint {
  double time_s = 0.0;
  Eigen::Vector3d position_m{0, 0, 0};  ///< world NED
};

class TrackView : public QWidget {
  Q_OBJECT
 public:
  explicit TrackView(QWidget* parent = nullptr);
  void setTrack(std::vector<TrackPoint> track);
  void setCurrentTime(double time_s);
  QSize sizeHint() const override { return {420, 200}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  void paintPlan(class QPainter& painter, const QRectF& area) const;
  void paintDepth(class QPainter& painter, const QRectF& area) const;
  TrackPoint at(double time_s) const;

  std::vector<TrackPoint> track_;
  double current_time_s_ = 0.0;
};

}  // namespace sonarcarve::widgets
