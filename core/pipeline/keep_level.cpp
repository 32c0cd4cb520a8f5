#include "pipeline/keep_level.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "common/error.h"

namespace sonarcarve {
namespace {

constexpr double kBrightQuantile = 0.9999;
// Each frame keeps its brightest 1 % of lit pixels: the union holds the brightest 0.01 % of
// all of them, whatever their spread over the frames.
constexpr double kKeptPerFrame = 0.01;

}  // namespace

std::string describeKeepLevel(const KeepLevel& level, double dynamic_range_db) {
  std::ostringstream line;
  line << "beam-aware carving: voxels kept above " << level.level << " " << level.unit
       << " on the beam's axis (";
  if (level.raised_to_a_count) {
    line << "raised to what a dark pixel bounds at the aperture's edge: the bright returns, "
         << level.bright_returns << " " << level.unit << ", are too faint for " << dynamic_range_db
         << " dB in whole counts)";
  } else {
    line << dynamic_range_db << " dB below the bright returns, " << level.bright_returns << ")";
  }
  return line.str();
}

RunChoice keepLevelChoice(const KeepLevel& level, double dynamic_range_db) {
  std::ostringstream value;
  value << dynamic_range_db << " dB under the brightest";
  RunChoice choice;
  choice.name = "beam-aware carving";
  choice.value = level.raised_to_a_count ? "raised to a dark pixel's level" : value.str();
  choice.reason = level.raised_to_a_count
                      ? "the returns are too faint for the dynamic range in whole counts, so "
                        "fainter pixels carve"
                      : "fainter pixels cannot place a return in elevation, so they carve";
  choice.detail = describeKeepLevel(level, dynamic_range_db);
  if (level.raised_to_a_count) {
    choice.action = "a higher gain when recording keeps fainter structure";
  }
  return choice;
}

KeepLevel measureKeepLevel(std::size_t count,
                           const std::function<std::optional<cv::Mat>(std::size_t)>& image,
                           double dynamic_range_db, Progress& progress) {
  KeepLevel result;
  std::vector<float> brightest;
  std::size_t lit_total = 0;
  for (std::size_t n = 0; n < count; ++n) {
    if (progress.cancelled()) {
      throw Cancelled();
    }
    const std::optional<cv::Mat> frame = image(n);
    if (!frame) {
      continue;
    }
    std::vector<float> lit;
    for (int r = 0; r < frame->rows; ++r) {
      const float* row = frame->ptr<float>(r);
      std::copy_if(row, row + frame->cols, std::back_inserter(lit),
                   [](float v) { return v > 0.0f; });
    }
    lit_total += lit.size();
    const auto keep = std::min(
        lit.size(),
        static_cast<std::size_t>(std::ceil(kKeptPerFrame * static_cast<double>(lit.size()))));
    const auto split = lit.begin() + static_cast<std::ptrdiff_t>(keep);
    std::nth_element(lit.begin(), split, lit.end(), std::greater<>());
    brightest.insert(brightest.end(), lit.begin(), split);
    ++result.frames;
    progress.report("keep level", n + 1, count);
  }
  if (brightest.empty()) {
    return result;
  }
  // Rank of the quantile counted from the brightest of all lit pixels.
  const auto rank =
      std::min(brightest.size() - 1,
               static_cast<std::size_t>((1.0 - kBrightQuantile) * static_cast<double>(lit_total)));
  std::nth_element(brightest.begin(), brightest.begin() + static_cast<std::ptrdiff_t>(rank),
                   brightest.end(), std::greater<>());
  result.bright_returns = brightest[rank];
  result.level = result.bright_returns * std::pow(10.0, -dynamic_range_db / 10.0);
  return result;
}

KeepLevel measureKeepLevel(const DenoisedFrames& source, const std::vector<PosedFrame>& frames,
                           double dynamic_range_db, Progress& progress, std::size_t max_frames) {
  const std::size_t count = std::min(max_frames, frames.size());
  return measureKeepLevel(
      count,
      [&](std::size_t n) -> std::optional<cv::Mat> {
        const std::size_t pick = count == 1 ? 0 : n * (frames.size() - 1) / (count - 1);
        try {
          return source.load(frames[pick].index).image;
        } catch (const Error&) {
          return std::nullopt;  // the carving stage reports it
        }
      },
      dynamic_range_db, progress);
}

}  // namespace sonarcarve
