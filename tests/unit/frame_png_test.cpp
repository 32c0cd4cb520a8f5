#include <gtest/gtest.h>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/frame_png.h"
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
