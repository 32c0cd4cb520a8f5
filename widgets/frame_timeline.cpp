#include "frame_timeline.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

namespace sonarcarve::widgets {

FrameTimeline::FrameTimeline(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 2, 4, 2);
  const auto button = [&](QStyle::StandardPixmap icon, const QString& tip) {
    auto* b = new QToolButton(this);
    b->setIcon(style()->standardIcon(icon));
    b->setToolTip(tip);
    b->setAutoRaise(true);
    layout->addWidget(b);
    return b;
  };
  back_ = button(QStyle::SP_MediaSkipBackward, tr("Previous frame"));
  play_ = button(QStyle::SP_MediaPlay, tr("Play / pause the frames"));
  play_->setCheckable(true);
  forward_ = button(QStyle::SP_MediaSkipForward, tr("Next frame"));
  slider_ = new QSlider(Qt::Horizontal, this);
  layout->addWidget(slider_, 1);
  label_ = new QLabel(this);
  // A fixed size: otherwise each new text re-lays out the whole window while a run plays.
  label_->setFixedSize(
      label_->fontMetrics().horizontalAdvance("frame 000000 / 000000   t = 000000.00 s"),
      label_->sizeHint().height());
  layout->addWidget(label_);

  connect(back_, &QToolButton::clicked, this, &FrameTimeline::stepBack);
  connect(forward_, &QToolButton::clicked, this, &FrameTimeline::stepForward);
  connect(play_, &QToolButton::toggled, this, &FrameTimeline::setPlaying);
  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    updateLabel();
    emit currentFrameChanged(v);
  });
  play_timer_.setInterval(kPlayInterval_ms);
  connect(&play_timer_, &QTimer::timeout, this, [this] {
    if (slider_->value() >= slider_->maximum()) {
      setPlaying(false);
    } else {
      stepForward();
    }
  });
  setFrameTimes({});
}

void FrameTimeline::setFrameTimes(std::vector<double> times_s) {
  setPlaying(false);
  times_s_ = std::move(times_s);
  const QSignalBlocker block(slider_);
  slider_->setRange(0, std::max(0, static_cast<int>(times_s_.size()) - 1));
  slider_->setValue(0);
  setEnabled(!times_s_.empty());
  updateLabel();
}

int FrameTimeline::currentFrame() const {
  return slider_->value();
}

void FrameTimeline::setCurrentFrame(int index) {
  slider_->setValue(index);
}
void FrameTimeline::stepForward() {
  slider_->setValue(slider_->value() + 1);
}
void FrameTimeline::stepBack() {
  slider_->setValue(slider_->value() - 1);
}

void FrameTimeline::setPlaying(bool on) {
  if (on && !times_s_.empty()) {
    if (slider_->value() >= slider_->maximum()) {
      slider_->setValue(0);
    }
    play_timer_.start();
  } else {
    play_timer_.stop();
  }
  const QSignalBlocker block(play_);
  play_->setChecked(play_timer_.isActive());
  play_->setIcon(
      style()->standardIcon(play_timer_.isActive() ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

QString FrameTimeline::labelText() const {
  return label_->text();
}

void FrameTimeline::updateLabel() {
  if (times_s_.empty()) {
    label_->setText(tr("no frames"));
    return;
  }
  const int i = slider_->value();
  // Counted from 1 for people, with the index that `frame --index` and sessions use.
  label_->setText(tr("frame %1 of %2 (index %3)   t = %4 s")
                      .arg(i + 1)
                      .arg(times_s_.size())
                      .arg(i)
                      .arg(times_s_[static_cast<std::size_t>(i)], 0, 'f', 2));
}

}  // namespace sonarcarve::widgets
