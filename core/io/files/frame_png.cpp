#include "io/files/frame_png.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/input_file.h"
#include "io/files/png_codec.h"

namespace sonarcarve {
namespace {
constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr unsigned char kPngEnd[8] = {'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};

std::uint32_t bigEndian32(const std::vector<unsigned char>& bytes, std::size_t at) {
  return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
         (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
}

// The image size from the IHDR chunk (bytes 16 to 23), checked before the decoder allocates.
void requireFrameSize(const std::vector<unsigned char>& bytes, const std::string& file,
                      const std::optional<FrameShape>& expected) {
  constexpr std::size_t kIhdrEnd = 24;
  if (bytes.size() < kIhdrEnd || std::string(bytes.begin() + 12, bytes.begin() + 16) != "IHDR") {
    throw Error(file, "byte 12", "corrupt PNG: expected the IHDR chunk first");
  }
  const std::uint32_t width = bigEndian32(bytes, 16);
  const std::uint32_t height = bigEndian32(bytes, 20);
  if (width > static_cast<std::uint32_t>(kMaxBeams) ||
      height > static_cast<std::uint32_t>(kMaxRangeBins) ||
      std::int64_t{width} * height > kMaxFramePixels) {
    throw Error(file, "byte 16",
                "image is " + std::to_string(height) + " x " + std::to_string(width) +
                    " (rows x cols): expected at most " + std::to_string(kMaxRangeBins) +
                    " range bins x " + std::to_string(kMaxBeams) + " beams and " +
                    std::to_string(kMaxFramePixels) + " pixels");
  }
  if (expected && (height != static_cast<std::uint32_t>(expected->rows) ||
                   width != static_cast<std::uint32_t>(expected->cols))) {
    throw Error(file, "byte 16",
                "image is " + std::to_string(height) + " x " + std::to_string(width) +
                    " (rows x cols), expected " + std::to_string(expected->rows) +
                    " range bins x " + std::to_string(expected->cols) +
                    " beams (the sonar's): not decoded");
  }
}

}  // namespace

cv::Mat wholeCounts(const cv::Mat& image, const std::string& what) {
  if (image.empty() || image.type() != CV_32F) {
    throw Error(what, "", "expected a non-empty single-channel float image");
  }
  cv::Mat counts(image.size(), CV_16U);
  for (int r = 0; r < image.rows; ++r) {
    const float* in = image.ptr<float>(r);
    auto* out = counts.ptr<std::uint16_t>(r);
    for (int c = 0; c < image.cols; ++c) {
      const float v = in[c];
      if (!(v >= 0.0f && v <= 65535.0f)) {
        throw Error(what, "pixel (" + std::to_string(r) + ", " + std::to_string(c) + ")",
                    "intensity " + std::to_string(v) + " is NaN or outside 0..65535");
      }
      out[c] = static_cast<std::uint16_t>(std::lround(v));
    }
  }
  return counts;
}

std::string encodeFramePng(const cv::Mat& image, const std::string& what) {
  return encodePng(wholeCounts(image, what), what);
}

cv::Mat readFramePng(const std::filesystem::path& path, std::optional<FrameShape> expected) {
  const std::string file = path.string();
  const std::uint64_t max_bytes = expected ? maxFramePngBytes(expected->rows, expected->cols)
                                           : maxFramePngBytes(kMaxRangeBins, kMaxBeams);
  const std::string content = readInputFile(path, "a 16-bit PNG frame image", max_bytes);
  const std::vector<unsigned char> bytes(content.begin(), content.end());
  if (bytes.empty()) {
    throw Error(file, "byte 0", "empty file: expected a PNG image");
  }
  if (bytes.size() < sizeof(kPngSignature) ||
      !std::equal(std::begin(kPngSignature), std::end(kPngSignature), bytes.begin())) {
    throw Error(file, "byte 0", "not a PNG image (bad signature)");
  }
  // libpng decodes a cut-off file as far as it goes; a complete PNG ends with its IEND chunk.
  if (bytes.size() < 16 || !std::equal(std::begin(kPngEnd), std::end(kPngEnd), bytes.end() - 8)) {
    throw Error(file, bytePlace(bytes.size()),
                "truncated PNG: expected the IEND chunk at the end of the file");
  }
  requireFrameSize(bytes, file, expected);
  const cv::Mat decoded = decodeGreyPng(content, file);
  cv::Mat image;
  decoded.convertTo(image, CV_32F);
  return image;
}

}  // namespace sonarcarve
