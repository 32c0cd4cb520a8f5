// The 2D widgets on Qt's offscreen platform (no OpenGL involved): the fan's geometry and
// hover read-out, the timeline, the parameter panel.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTest>
#include <QWidget>
#include <cmath>

#include "axes_triad.h"
#include "colour_legend.h"
#include "colour_maps.h"
#include "common/angles.h"
#include "fan_view.h"
#include "frame_timeline.h"
#include "params_panel.h"
#include "pipeline/param_schema.h"
#include "scale_bar.h"
#include "support/test_support.h"

namespace sonarcarve::widgets {
namespace {

class Widgets : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (QApplication::instance() == nullptr) {
      qputenv("QT_QPA_PLATFORM", "offscreen");
      static int argc = 1;
      static char name[] = "widgets_test";
      static char* argv[] = {name, nullptr};
      new QApplication(argc, argv);
    }
  }
};

void checkFanGeometry(const SonarModel& sonar) {
  FanView view("raw");
  view.resize(640, 420);
  view.setSonar(sonar);
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F);
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      image.at<float>(r, c) = static_cast<float>(r * 1000 + c);
    }
  }
  view.setFrame(image, 0.0f, 1000.0f);
  const double r_max = sonar.range().maxRange();
  for (double range : {0.3 * r_max, 0.5 * r_max, 0.9 * r_max}) {
    for (double bearing_deg : {-25.0, -3.0, 0.0, 7.5, 28.0}) {
      const auto s = view.sampleAt(view.pointOf(range, degToRad(bearing_deg)));
      ASSERT_TRUE(s) << range << " m " << bearing_deg << " deg";
      // Within what one screen pixel spans at this scale, plus the bin and beam widths.
      const double px_m = r_max / 400.0;
      EXPECT_NEAR(s->range_m, range, px_m);
      EXPECT_NEAR(s->bearing_rad, degToRad(bearing_deg), px_m / range);
      EXPECT_EQ(s->row, sonar.range().binOf(s->range_m).value());
      EXPECT_EQ(s->col, sonar.bearings().beamOf(s->bearing_rad).value());
      EXPECT_EQ(s->value, static_cast<float>(s->row * 1000 + s->col));
    }
  }
  // Beyond the last bin and outside the field of view there is nothing.
  EXPECT_FALSE(view.sampleAt(view.pointOf(r_max * 1.02, 0.0)));
  EXPECT_FALSE(view.sampleAt(view.pointOf(0.5 * r_max, sonar.bearings().rightEdge() + 0.05)));
}

TEST_F(Widgets, FanShowsEachPixelAtItsRangeAndBearing) {
  checkFanGeometry(test::paperSonar());
}

TEST_F(Widgets, FanUsesTheSonarsOwnNonUniformBearingTable) {
  checkFanGeometry(test::nonUniformSonar());
}

TEST_F(Widgets, TimelineStepsAndPlaysToTheLastFrame) {
  FrameTimeline timeline;
  QSignalSpy changed(&timeline, &FrameTimeline::currentFrameChanged);
  timeline.setFrameTimes({0.0, 0.5, 1.0, 1.5});
  EXPECT_TRUE(timeline.labelText().startsWith("frame 1 of 4 (index 0)"))
      << timeline.labelText().toStdString();
  timeline.stepForward();
  EXPECT_EQ(timeline.currentFrame(), 1);
  EXPECT_TRUE(timeline.labelText().startsWith("frame 2 of 4 (index 1)   t = 0.50 s"));
  timeline.stepBack();
  timeline.stepBack();  // stays at the first frame
  EXPECT_EQ(timeline.currentFrame(), 0);
  timeline.setPlaying(true);
  EXPECT_TRUE(QTest::qWaitFor([&] { return !timeline.playing(); }, 5000));
  EXPECT_EQ(timeline.currentFrame(), 3);
  EXPECT_EQ(changed.count(), 5);  // 1, 0, then 1, 2, 3 while playing
}

TEST_F(Widgets, ParamsPanelFillsTheCliParamsAndReportsAnEditOnceSettled) {
  ParamsPanel panel;
  ReconstructionParams p;
  p.detector.mode = DetectorMode::Cfar;
  p.carve.voxel_size_m = 0.03;
  p.vertical_aperture_rad = degToRad(14.0);
  p.carve.range_max_m = 8.5;
  p.first_frame = 3;
  p.last_frame = 40;
  p.stride = 2;
  p.min_views = 6;
  p.carve.region = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 5));
  QSignalSpy edited(&panel, &ParamsPanel::paramsEdited);
  panel.setParams(p);
  const ReconstructionParams back = panel.params();
  EXPECT_EQ(back.toYaml(), p.toYaml());  // the region, which the panel does not show, is kept
  EXPECT_EQ(edited.count(), 0);
  panel.voxelSize()->setValue(2.5);
  panel.voxelSize()->setValue(3.5);
  panel.zThreshold()->setValue(2.5);
  EXPECT_TRUE(edited.wait(5000));
  QTest::qWait(ParamsPanel::kSettle_ms * 2);
  EXPECT_EQ(edited.count(), 1);
  EXPECT_DOUBLE_EQ(panel.params().carve.voxel_size_m, 0.035);
  EXPECT_DOUBLE_EQ(panel.params().detector.z, 2.5);
}

TEST_F(Widgets, ParamsPanelHasAnEditorForEveryParameterOfTheSchema) {
  ParamsPanel panel;
  for (const ParamSpec& spec : paramSchema()) {
    EXPECT_NE(panel.editor(spec.key), nullptr) << spec.key;
  }
  // The usual entries show; the others after "More parameters".
  EXPECT_TRUE(panel.zThreshold()->isVisibleTo(&panel));
  EXPECT_FALSE(panel.editor("mesh.decimate")->isVisibleTo(&panel));
  panel.moreParameters()->setChecked(true);
  EXPECT_TRUE(panel.editor("mesh.decimate")->isVisibleTo(&panel));
  auto* decimate = qobject_cast<QDoubleSpinBox*>(panel.editor("mesh.decimate"));
  ASSERT_NE(decimate, nullptr);
  decimate->setValue(0.5);
  EXPECT_DOUBLE_EQ(panel.params().mesh.decimate, 0.5);
  // Entries that do not apply are greyed out: CFAR's without the CFAR detector. The default
  // detector (auto) runs the Z-test with a model learned from the mission when none is given,
  // so its threshold and smoothing can be tuned; without a detector neither applies.
  EXPECT_EQ(panel.params().detector.mode, DetectorMode::Auto);
  EXPECT_TRUE(panel.params().noise_model.empty());
  EXPECT_FALSE(panel.editor("detector.cfar_pfa")->isEnabled());
  EXPECT_TRUE(panel.zThreshold()->isEnabled());
  EXPECT_TRUE(panel.editor("detector.smoothing")->isEnabled());
  panel.detectorMode()->setCurrentText("none");
  EXPECT_FALSE(panel.zThreshold()->isEnabled());
  EXPECT_FALSE(panel.editor("detector.smoothing")->isEnabled());
  panel.detectorMode()->setCurrentText("cfar");
  EXPECT_TRUE(panel.editor("detector.cfar_pfa")->isEnabled());
  EXPECT_FALSE(panel.zThreshold()->isEnabled());
  EXPECT_EQ(panel.params().detector.mode, DetectorMode::Cfar);
}

// Counts the paint events a widget receives.
class PaintCounter : public QObject {
 public:
  explicit PaintCounter(QWidget& widget) { widget.installEventFilter(this); }
  int count = 0;

 protected:
  bool eventFilter(QObject*, QEvent* event) override {
    count += event->type() == QEvent::Paint ? 1 : 0;
    return false;
  }
};

// The 3D view's overlays are set at every render of the view; setting what they already show
// must not repaint them (with the OpenGL view in the window, each repaint composes the whole
// window: tens of milliseconds with software OpenGL). A change does repaint them.
TEST_F(Widgets, OverlaysRepaintOnlyWhenWhatTheyShowChanges) {
  QWidget host;
  host.resize(400, 300);
  auto* triad = new AxesTriad(&host);
  auto* bar = new ScaleBar(&host);
  auto* legend = new ColourLegend(&host);
  const std::array<QPointF, 3> axes{QPointF(0, -1), QPointF(1, 0), QPointF(0, 0)};
  triad->setAxes(axes);
  bar->setMetresPerPixel(0.004);
  legend->setScale("depth (m)", 1.0, 2.0, viridisColours());
  host.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&host));
  QTest::qWait(50);
  PaintCounter triad_paints(*triad);
  PaintCounter bar_paints(*bar);
  PaintCounter legend_paints(*legend);
  triad->setAxes(axes);
  bar->setMetresPerPixel(0.004);
  legend->setScale("depth (m)", 1.0, 2.0, viridisColours());
  QTest::qWait(50);
  EXPECT_EQ(triad_paints.count, 0);
  EXPECT_EQ(bar_paints.count, 0);
  EXPECT_EQ(legend_paints.count, 0);
  triad->setAxes({QPointF(1, 0), QPointF(0, 1), QPointF(0, 0)});
  bar->setMetresPerPixel(0.01);
  legend->setScale("depth (m)", 1.0, 3.0, viridisColours());
  EXPECT_TRUE(QTest::qWaitFor([&] { return triad_paints.count > 0; }, 2000));
  EXPECT_TRUE(QTest::qWaitFor([&] { return bar_paints.count > 0; }, 2000));
  EXPECT_TRUE(QTest::qWaitFor([&] { return legend_paints.count > 0; }, 2000));
}

}  // namespace
}  // namespace sonarcarve::widgets
