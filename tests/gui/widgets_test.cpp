// The 2D widgets on Qt's offscreen platform (no OpenGL involved): the fan's geometry and
// hover read-out, the timeline, the parameter panel.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTest>
#include <cmath>

#include "common/angles.h"
#include "fan_view.h"
#include "frame_timeline.h"
#include "params_panel.h"
#include "pipeline/param_schema.h"
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
  // Entries that do not apply are greyed out: CFAR's without the CFAR detector.
  EXPECT_FALSE(panel.editor("detector.cfar_pfa")->isEnabled());
  panel.detectorMode()->setCurrentText("cfar");
  EXPECT_TRUE(panel.editor("detector.cfar_pfa")->isEnabled());
  EXPECT_EQ(panel.params().detector.mode, DetectorMode::Cfar);
}

}  // namespace
}  // namespace sonarcarve::widgets
