// ScaleBar: a bar of a round length in metres (1, 2 or 5 times a power of ten) drawn over the
// 3D view's corner, as long on the screen as that length at the camera's focal point (in
// perspective, nearer things are larger). GUI thread only.
#pragma once

#include <QWidget>

namespace sonarcarve::widgets {

class ScaleBar : public QWidget {
  Q_OBJECT
 public:
  /// The bar is at most this long on the screen, and at least 2/5 of it.
  static constexpr int kMaxBarPixels = 120;

  explicit ScaleBar(QWidget* parent = nullptr);
  /// The scale: metres one screen pixel spans. Not positive or not finite: hidden.
  void setMetresPerPixel(double metres);
  double metresPerPixel() const { return metres_per_pixel_; }
  /// The bar's length in metres, and on the screen.
  double lengthMetres() const { return length_m_; }
  int barPixels() const;
  /// "50 cm", "2 m", "5 mm".
  QString text() const;
  /// The largest 1, 2 or 5 times a power of ten not above `metres` (0 for none).
  static double roundLength(double metres);
  QSize sizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  double metres_per_pixel_ = 0.0;
  double length_m_ = 0.0;
};

}  // namespace sonarcarve::widgets
