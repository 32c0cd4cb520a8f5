// FanView: a polar sonar frame drawn as its fan in true geometry: the sonar at the bottom
// centre, range upwards, port on the left, each beam at its own bearing from the sonar's
// (possibly non-uniform) bearing table. Range rings and bearing lines are labelled; hovering
// shows range, bearing and intensity under the mouse. GUI thread only.
#pragma once

#include <QImage>
#include <QWidget>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "colour_maps.h"
#include "sonar/sonar_model.h"

namespace sonarcarve::widgets {

/// What lies under a point of the fan.
struct FanSample {
  double range_m = 0.0;
  double bearing_rad = 0.0;
  int row = 0;  ///< range bin
  int col = 0;  ///< beam
  float value = 0.0f;
};

class FanView : public QWidget {
  Q_OBJECT
 public:
  explicit FanView(QString title, QWidget* parent = nullptr);

  void setSonar(const SonarModel& sonar);
  /// `image`: CV_32F polar image of the sonar's size (rows = range bins, cols = beams);
  /// intensities are shown linearly from `low` to `high`.
  void setFrame(const cv::Mat& image, float low, float high);
  void clearFrame();
  void setColourMap(ColourMap map);
  /// The sample under widget point `p`, if `p` lies on the fan.
  std::optional<FanSample> sampleAt(QPointF p) const;
  /// Widget point of polar coordinates (inverse of sampleAt's geometry).
  QPointF pointOf(double range_m, double bearing_rad) const;
  QSize sizeHint() const override { return {420, 320}; }

 signals:
  void hovered(const QString& readout);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  void layoutFan();
  void renderFan();
  void drawGrid(class QPainter& painter) const;

  QString title_;
  std::optional<SonarModel> sonar_;
  cv::Mat image_;
  float low_ = 0.0f;
  float high_ = 1.0f;
  ColourMap colour_map_ = ColourMap::Copper;
  // Geometry for the current size: apex, pixels per metre, and for each widget pixel the
  // index of the polar pixel it shows (-1 outside the fan).
  QPointF apex_;
  double px_per_m_ = 1.0;
  std::vector<int> lookup_;
  QImage fan_;
  QImage grid_;  ///< rings, bearing lines and labels, transparent elsewhere
  QString readout_;
};

}  // namespace sonarcarve::widgets
