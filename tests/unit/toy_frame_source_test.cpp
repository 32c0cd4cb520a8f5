// A toy frame source added the way docs/architecture.md says: this one file and its
// registration line. Its recordings are text files starting "TOYSONAR N": N frames of a tiny
// sonar, each lit at 2 m, taken by a vehicle that sinks 5 cm per second. openMission() picks
// the reader by content, and the whole pipeline runs on it without conversion.
#include <gtest/gtest.h>

#include <fstream>

#include "common/angles.h"
#include "common/error.h"
#include "io/frame_source.h"
#include "pipeline/reconstruction.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

SonarModel toySonar() {
  return SonarModel("toy", RangeBins{1.0, 0.04, 50}, BearingTable::uniform(degToRad(20), 20),
                    degToRad(10));
}

class ToySource final : public FrameSource {
 public:
  explicit ToySource(std::size_t frames) : frames_(frames) {}
  std::string kind() const override { return "toy recording"; }
  std::size_t size() const override { return frames_; }
  Frame load(std::size_t index) const override {
    const SonarModel sonar = toySonar();
    Frame frame{static_cast<double>(index), sonar.id(),
                cv::Mat(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f))};
    frame.image.row(*sonar.range().binOf(2.01)).setTo(100.0f);
    return frame;
  }

 private:
  std::size_t frames_;
};

bool isToyRecording(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string magic;
  return static_cast<bool>(in >> magic) && magic == "TOYSONAR";
}

Mission openToyRecording(const std::filesystem::path& path, const OpenOptions& options) {
  std::ifstream in(path);
  std::string magic;
  std::size_t frames = 0;
  if (!(in >> magic >> frames) || frames == 0) {
    throw Error(path.string(), "line 1", "expected TOYSONAR and a frame count");
  }
  std::vector<NavSample> samples(2);
  samples[1].time_s = static_cast<double>(frames);
  samples[1].position_m.z() = 0.05 * static_cast<double>(frames);
  Mission mission{path,
                  path.stem().string(),
                  toySonar(),
                  Mounting{},
                  NavTrack(samples),
                  {},
                  "",
                  "",
                  std::make_shared<ToySource>(frames),
                  {},
                  {}};
  for (std::size_t i = 0; i < frames; ++i) {
    mission.frames.push_back({static_cast<double>(i), "toy", "frame " + std::to_string(i), 0});
  }
  applyOpenOptions(mission, options);
  return mission;
}

// The registration line.
[[maybe_unused]] const bool registered =
    registerFrameSourceReader({"toy", isToyRecording, openToyRecording});

TEST(ToyFrameSource, IsPickedByContentAndCarvedByThePipeline) {
  const test::ScratchDir dir;
  const auto file = dir.path() / "dive.whatever";
  std::ofstream(file) << "TOYSONAR 12\n";
  const Mission mission = openMission(file);
  EXPECT_EQ(mission.source->kind(), "toy recording");
  ASSERT_EQ(mission.frames.size(), 12u);

  ReconstructionParams params;
  params.mesh_enabled = false;
  params.min_views = 3;
  SilentProgress progress;
  ThreadPool pool(2);
  const ReconstructionResult result = Pipeline(mission, params, pool).run(progress);
  EXPECT_EQ(result.frames_used, 12u);
  ASSERT_FALSE(result.surface.empty());
  // Every surface point lies on a lit arc: 2 m (one 4 cm bin, plus a voxel's half diagonal)
  // from a sonar position on the vertical track.
  for (const SurfacePoint& p : result.surface) {
    const double horizontal = std::hypot(p.position_m.x(), p.position_m.y());
    EXPECT_LT(std::abs(horizontal - 2.0),
              0.04 + 0.02 * std::sqrt(3.0) + 2.0 * (1 - std::cos(degToRad(5))))
        << p.position_m.transpose();
  }
}

TEST(ToyFrameSource, TheRegistryListsItAndRefusesUnknownContent) {
  const auto names = frameSourceReaderNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "toy"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "mission folder"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "oculus"), names.end());
  const test::ScratchDir dir;
  const auto file = dir.path() / "notes.txt";
  std::ofstream(file) << "no sonar here\n";
  EXPECT_THROW(openMission(file), Error);
  EXPECT_THROW(openMission(dir.path() / "missing"), Error);
}

}  // namespace
}  // namespace sonarcarve
