#include <gtest/gtest.h>

#include <chrono>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/frame_png.h"
#include "support/png_bombs.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::ScratchDir;

cv::Mat rampImage(int rows, int cols) {
  cv::Mat image(rows, cols, CV_32F);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      image.at<float>(r, c) = static_cast<float>((r * 997 + c * 131) % 65536);
    }
  }
  return image;
}

TEST(FramePng, SixteenBitRoundTripIsLossless) {
  ScratchDir dir;
  const cv::Mat image = rampImage(37, 53);
  writeFileAtomically(dir.path() / "f.png", encodeFramePng(image, "f"));
  const cv::Mat back = readFramePng(dir.path() / "f.png");
  ASSERT_EQ(back.type(), CV_32F);
  EXPECT_EQ(cv::norm(image, back, cv::NORM_INF), 0.0);
}

TEST(FramePng, RoundsToTheNearestCountAndRejectsUnstorableValues) {
  cv::Mat image(2, 2, CV_32F, cv::Scalar(10.4f));
  image.at<float>(1, 1) = 10.6f;
  ScratchDir dir;
  writeFileAtomically(dir.path() / "f.png", encodeFramePng(image, "f"));
  const cv::Mat back = readFramePng(dir.path() / "f.png");
  EXPECT_EQ(back.at<float>(0, 0), 10.0f);
  EXPECT_EQ(back.at<float>(1, 1), 11.0f);
  for (float bad : {NAN, -1.0f, 70000.0f}) {
    image.at<float>(0, 1) = bad;
    EXPECT_THROW(encodeFramePng(image, "f"), Error) << bad;
  }
}

TEST(FramePng, TruncatedEmptyCorruptAndMissingFilesGetClearErrors) {
  ScratchDir dir;
  const std::string good = encodeFramePng(rampImage(64, 64), "f");
  const auto expectError = [&](const std::string& bytes, const std::string& fragment) {
    const auto path = dir.path() / "bad.png";
    test::writeText(path, bytes);
    try {
      readFramePng(path);
      ADD_FAILURE() << "no error for " << fragment;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("bad.png"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectError("", "empty file");
  expectError(good.substr(0, good.size() / 2), "truncated PNG");
  expectError(good.substr(0, 20), "truncated PNG");
  expectError("GIF89a not a png at all", "bad signature");
  std::string flipped = good;
  for (std::size_t i = 60; i < 90; ++i) {
    flipped[i] = static_cast<char>(flipped[i] ^ 0x5a);  // inside the image data
  }
  expectError(flipped, "corrupt PNG");
  EXPECT_THROW(readFramePng(dir.path() / "missing.png"), Error);
}

TEST(FramePng, AnotherSizeThanTheSonarsIsRefusedBeforeDecoding) {
  ScratchDir dir;
  writeFileAtomically(dir.path() / "f.png", encodeFramePng(rampImage(100, 64), "f"));
  test::expectError(
      [&] {
        readFramePng(dir.path() / "f.png", FrameShape{200, 64});
      },
      {"f.png: byte 16: image is 100 x 64 (rows x cols), expected 200 range bins x "
       "64 beams"});
  EXPECT_EQ(readFramePng(dir.path() / "f.png", FrameShape{100, 64}).rows, 100);
}

TEST(FramePng, AFileLargerThanItsFrameCanBeIsRefusedUnread) {
  ScratchDir dir;
  const auto path = dir.path() / "f.png";
  test::writeSparseFile(path, std::uint64_t{20} << 30);
  const auto start = std::chrono::steady_clock::now();
  test::expectError(
      [&] {
        readFramePng(path, FrameShape{200, 64});
      },
      {"f.png: is 21474836480 bytes, more than the 1100176 bytes"});
  test::expectError([&] { readFramePng(path); }, {"f.png: is 21474836480 bytes"});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST(FramePng, AnInflationBombOfTheRightSizeIsRefused) {
  ScratchDir dir;
  // 600 MiB of image data in 0.6 MB, under the 2.3 MB a 650 x 500 frame may take.
  writeFileAtomically(dir.path() / "f.png", test::inflationBombPng(650, 500, 600));
  test::expectError(
      [&] {
        readFramePng(dir.path() / "f.png", FrameShape{650, 500});
      },
      {"f.png", "goes on past the 650650 bytes"});
}

TEST(AtomicFile, AFailedWriteLeavesThePreviousContentAndNoTemporaryFile) {
  ScratchDir dir;
  const auto target = dir.path() / "deliverable";
  std::filesystem::create_directories(target / "occupied");  // rename onto it must fail
  EXPECT_THROW(writeFileAtomically(target, "new"), Error);
  EXPECT_TRUE(std::filesystem::is_directory(target / "occupied"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            1);
  const auto file = dir.path() / "file.txt";
  writeFileAtomically(file, "old");
  writeFileAtomically(file, "new");
  EXPECT_EQ(test::readText(file), "new");
}

}  // namespace
}  // namespace sonarcarve
