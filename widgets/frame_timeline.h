// FrameTimeline: the frame slider with step back, play/pause and step forward, and a label
// with the frame number and its time. Playing advances at `kPlayInterval_ms` per frame and
// stops at the last frame. GUI thread only.
#pragma once

#include <QTimer>
#include <QWidget>
#include <vector>

class QLabel;
class QSlider;
class QToolButton;

namespace sonarcarve::widgets {

class FrameTimeline : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kPlayInterval_ms = 100;

  explicit FrameTimeline(QWidget* parent = nullptr);
  /// Frame times in seconds; an empty list disables the timeline.
  void setFrameTimes(std::vector<double> times_s);
  int currentFrame() const;
  bool playing() const { return play_timer_.isActive(); }
  /// What the label says: "frame 1 of 24 (index 0)   t = 100.00 s".
  QString labelText() const;

 public slots:
  void setCurrentFrame(int index);
  void stepForward();
  void stepBack();
  void setPlaying(bool on);

 signals:
  void currentFrameChanged(int index);

 private:
  void updateLabel();

  std::vector<double> times_s_;
  QSlider* slider_ = nullptr;
  QToolButton* back_ = nullptr;
  QToolButton* play_ = nullptr;
  QToolButton* forward_ = nullptr;
  QLabel* label_ = nullptr;
  QTimer play_timer_;
};

}  // namespace sonarcarve::widgets
