// PNG through libpng against OpenCV's own codec as the second tool: what one writes the
// other reads to the same pixels, in every form frames and pictures take.
#include <gtest/gtest.h>

#include <zlib.h>

#include <chrono>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "common/error.h"
#include "io/files/png_codec.h"
#include "support/png_bombs.h"
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

TEST(PngCodec, TheTestsInflationBombIsAValidStream) {
  // One MiB of zeros behind a header of 512 x 511: all of it inflates, checksum included.
  const std::string png = test::inflationBombPng(512, 511, 1);
  ASSERT_EQ(png.substr(37, 4), "IDAT");
  const std::string idat = png.substr(41, png.size() - 41 - 12 - 4);
  std::vector<unsigned char> out((std::size_t{1} << 20) + 1);
  uLongf size = static_cast<uLongf>(out.size());
  ASSERT_EQ(uncompress(out.data(), &size, reinterpret_cast<const Bytef*>(idat.data()),
                       static_cast<uLong>(idat.size())),
            Z_OK);
  EXPECT_EQ(size, uLongf{1} << 20);
}

TEST(PngCodec, ImageDataInflatingPastTheDeclaredSizeIsRefusedWithoutInflatingIt) {
  // 650 x 500 16-bit pixels declared (650 rows of a filter byte and 1000 bytes), 16 GiB of
  // image data in 17 MB: inflating it all would take seconds and libpng did.
  const std::string bomb = test::inflationBombPng(650, 500, 16384);
  const auto start = std::chrono::steady_clock::now();
  test::expectError([&] { decodeGreyPng(bomb, "bomb.png"); },
                    {"bomb.png", "goes on past the 650650 bytes", "650 x 500"});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  // A short bomb (40 MiB in 41 kB) is inflated to its end by libpng, which then says so.
  test::expectError([&] { decodeGreyPng(test::inflationBombPng(650, 500, 40), "short.png"); },
                    {"short.png", "goes on past the 650650 bytes"});
  // A stream that ends where the image does still decodes.
  const cv::Mat image = randomImage(CV_16UC1, 9);
  EXPECT_TRUE(samePixels(decodeGreyPng(encodePng(image, "frame"), "frame.png"), image));
}

}  // namespace
}  // namespace sonarcarve
