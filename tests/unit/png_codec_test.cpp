// PNG through libpng against OpenCV's own codec as the second tool: what one writes the
// other reads to the same pixels, in every form frames and pictures take.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <random>

#include "common/error.h"
#include "io/files/png_codec.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

cv::Mat randomImage(int type, unsigned seed) {
  cv::Mat image(37, 53, type);  // odd sizes: no row is a multiple of anything
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, type == CV_16UC1 ? 65536 : 256);
  return image;
}

bool samePixels(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

TEST(PngCodec, WhatItWritesOpenCvReadsToTheSamePixels) {
  for (const int type : {CV_8UC1, CV_16UC1, CV_8UC3}) {
    const cv::Mat image = randomImage(type, 3);
    const std::string png = encodePng(image, "picture");
    const cv::Mat read =
        cv::imdecode(std::vector<unsigned char>(png.begin(), png.end()), cv::IMREAD_UNCHANGED);
    EXPECT_TRUE(samePixels(read, image)) << "type " << type;
  }
}

TEST(PngCodec, ReadsGreyPngsOpenCvWritesAtEveryDepth) {
  for (const int type : {CV_8UC1, CV_16UC1}) {
    const cv::Mat image = randomImage(type, 5);
    for (const int level : {0, 1, 9}) {
      std::vector<unsigned char> png;
      ASSERT_TRUE(cv::imencode(".png", image, png, {cv::IMWRITE_PNG_COMPRESSION, level}));
      const cv::Mat read = decodeGreyPng(std::string(png.begin(), png.end()), "frame.png");
      EXPECT_TRUE(samePixels(read, image)) << "type " << type << " level " << level;
    }
  }
  // A two-level picture OpenCV stores at 1 bit per pixel comes back as 0 and 255.
  cv::Mat binary = randomImage(CV_8UC1, 7) > 128;
  std::vector<unsigned char> png;
  ASSERT_TRUE(cv::imencode(".png", binary, png, {cv::IMWRITE_PNG_BILEVEL, 1}));
  const cv::Mat read = decodeGreyPng(std::string(png.begin(), png.end()), "mask.png");
  EXPECT_TRUE(samePixels(read, binary));
}

TEST(PngCodec, ColourCutAndCorruptStreamsAreRefusedNamingTheFile) {
  const std::string colour = encodePng(randomImage(CV_8UC3, 1), "picture");
  test::expectError([&] { decodeGreyPng(colour, "colour.png"); },
                    {"colour.png", "single-channel", "colour"});
  const std::string grey = encodePng(randomImage(CV_16UC1, 2), "frame");
  test::expectError([&] { decodeGreyPng(grey.substr(0, grey.size() / 2), "cut.png"); },
                    {"cut.png", "corrupt PNG", "ends"});
  std::string flipped = grey;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x5A);
  test::expectError([&] { decodeGreyPng(flipped, "flipped.png"); }, {"flipped.png", "corrupt PNG"});
  test::expectError([&] { decodeGreyPng("", "empty.png"); }, {"empty.png", "corrupt PNG"});
  test::expectError([&] { encodePng(cv::Mat(4, 4, CV_32FC1), "floats"); }, {"floats", "PNG"});
}

}  // namespace
}  // namespace sonarcarve
