#include <gtest/gtest.h>

#include "frame_image.h"

namespace sonarcarve::widgets {
namespace {

TEST(PolarImageToQImage, NearestRangeIsAtTheBottomAndPortOnTheLeft) {
  cv::Mat image(3, 4, CV_32F, cv::Scalar(0.0f));
  image.at<float>(0, 0) = 100.0f;  // nearest bin, most port beam
  const QImage q = polarImageToQImage(image, 0.0f, 100.0f, ColourMap::Grey);
  ASSERT_EQ(q.width(), 4);
  ASSERT_EQ(q.height(), 3);
  EXPECT_EQ(q.pixel(0, 2), qRgb(255, 255, 255));
  EXPECT_EQ(q.pixel(0, 0), qRgb(0, 0, 0));
  EXPECT_EQ(q.pixel(3, 2), qRgb(0, 0, 0));
}

TEST(PolarImageToQImage, ColoursRiseWithIntensityAndClampOutsideTheWindow) {
  cv::Mat image(1, 5, CV_32F);
  const float values[] = {-50.0f, 10.0f, 50.0f, 90.0f, 500.0f};
  for (int c = 0; c < 5; ++c) {
    image.at<float>(0, c) = values[c];
  }
  for (ColourMap map : {ColourMap::Grey, ColourMap::Copper}) {
    const QImage q = polarImageToQImage(image, 0.0f, 100.0f, map);
    EXPECT_EQ(q.pixel(0, 0), qRgb(0, 0, 0));
    for (int c = 1; c < 5; ++c) {
      EXPECT_GT(qGray(q.pixel(c, 0)), qGray(q.pixel(c - 1, 0))) << c;
    }
    const QImage saturated = polarImageToQImage(image, 0.0f, 90.0f, map);
    EXPECT_EQ(saturated.pixel(3, 0), saturated.pixel(4, 0));
  }
}

}  // namespace
}  // namespace sonarcarve::widgets
