// The reconstruction pipeline on a small simulated mission: results, skipped frames,
// cancellation, map updates for viewers, parameters in YAML.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "common/error.h"
#include "denoise/noise_model.h"
#include "pipeline/reconstruction.h"
#include "sim/demo_scenes.h"
#include "sim/simulation_run.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

ReconstructionResult runPipeline(const Mission& mission, const ReconstructionParams& params,
                                 Progress& progress, ReconstructionObserver* observer = nullptr,
                                 std::size_t update_every = 1) {
  static ThreadPool pool(2);
  return sonarcarve::Pipeline(mission, params, pool).run(progress, observer, update_every);
}

class Pipeline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    TrajectorySpec trajectory;
    SimulationRequest request{
        makeDemoScene("riser"), "riser",        paperSonar(), trajectory, test::clippedBeam(),
        NoiseSpec::none(),      NavErrorSpec{}, false,        24,         dir_->path() / "riser"};
    SilentProgress progress;
    ThreadPool pool;
    runSimulation(request, progress, pool);
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::filesystem::path mission() { return dir_->path() / "riser"; }
  static test::ScratchDir* dir_;
};
test::ScratchDir* Pipeline::dir_ = nullptr;

// Cancels once `reports` progress reports of stage `stage` have arrived.
class CancelAfter : public Progress {
 public:
  explicit CancelAfter(std::size_t reports, std::string stage = "carve")
      : left_(reports), stage_(std::move(stage)) {}
  void report(const std::string& stage, std::size_t, std::size_t) override {
    if (left_ > 0 && stage == stage_)
      --left_;
  }
  bool cancelled() const override { return left_ == 0; }

 private:
  std::atomic<std::size_t> left_;
  std::string stage_;
};

struct Recorder : ReconstructionObserver {
  std::vector<std::size_t> carved;
  std::vector<FrameProblem> skipped;
  std::map<std::size_t, std::vector<Eigen::Vector3f>> blocks;  // the viewer's copy of the map
  void frameCarved(std::size_t index, const Frame&, const Eigen::Isometry3d&) override {
    carved.push_back(index);
  }
  void frameSkipped(const FrameProblem& p) override { skipped.push_back(p); }
  int noise_calls = 0;
  bool noise_before_frames = false;
  std::shared_ptr<const NoiseModel> noise;
  void noiseModelChosen(const std::shared_ptr<const NoiseModel>& model) override {
    ++noise_calls;
    noise_before_frames = carved.empty();
    noise = model;
  }
  void mapUpdated(const MapUpdate& update) override {
    for (const auto& b : update.blocks) {
      blocks[b.block] = b.points;
    }
  }
};

TEST_F(Pipeline, ReconstructsTheRiserTopFromTheFramesThatSeeIt) {
  SilentProgress progress;
  const Mission m = readMission(mission());
  const ReconstructionResult r = runPipeline(m, ReconstructionParams{}, progress);
  EXPECT_EQ(r.frames_used, 24u);
  EXPECT_TRUE(r.skipped.empty());
  EXPECT_FALSE(r.cancelled);
  ASSERT_GT(r.surface.size(), 500u);
  // Surface points lie on the riser or its first module, on the side facing the sonar.
  for (const SurfacePoint& p : r.surface) {
    ASSERT_LT(std::hypot(p.position_m.x(), p.position_m.y()), 0.45f + 0.1f)
        << p.position_m.transpose();
    ASSERT_GE(p.views, ReconstructionParams::kDefaultMinViews);
    ASSERT_GT(p.intensity, 0.0f);
  }
}

TEST_F(Pipeline, ViewerUpdatesAddUpToTheFinalMap) {
  SilentProgress progress;
  Recorder recorder;
  const Mission m = readMission(mission());
  const ReconstructionResult r = runPipeline(m, ReconstructionParams{}, progress, &recorder, 5);
  EXPECT_EQ(recorder.carved.size(), 24u);
  // The viewer hears of the denoising once, before any frame: none on noise-free frames.
  EXPECT_EQ(recorder.noise_calls, 1);
  EXPECT_TRUE(recorder.noise_before_frames);
  EXPECT_FALSE(recorder.noise);
  std::set<std::tuple<float, float, float>> shown, actual;
  for (const auto& [block, points] : recorder.blocks) {
    for (const auto& p : points)
      shown.insert({p.x(), p.y(), p.z()});
  }
  r.map->forEachOccupied([&](const Eigen::Vector3i& v, float) {
    const Eigen::Vector3f c = r.map->voxelCentre(v).cast<float>();
    actual.insert({c.x(), c.y(), c.z()});
  });
  EXPECT_EQ(shown, actual);
}

// On noisy frames with no model given, the viewer hears of the model the run learned from them,
// with the run's smoothing, before any frame is carved.
TEST(PipelineNoisy, ViewerHearsOfTheLearnedNoiseModel) {
  const test::ScratchDir dir;
  SimulationRequest request{makeDemoScene("riser"),
                            "riser",
                            paperSonar(),
                            TrajectorySpec{},
                            test::clippedBeam(),
                            NoiseSpec{},
                            NavErrorSpec{},
                            false,
                            8,
                            dir.path() / "m"};
  SilentProgress progress;
  ThreadPool pool;
  runSimulation(request, progress, pool);
  Recorder recorder;
  ReconstructionParams params;
  params.detector.smoothing = 5;
  const ReconstructionResult r =
      runPipeline(readMission(dir.path() / "m"), params, progress, &recorder);
  EXPECT_EQ(r.detector, "ztest");
  EXPECT_EQ(recorder.noise_calls, 1);
  EXPECT_TRUE(recorder.noise_before_frames);
  ASSERT_TRUE(recorder.noise);
  EXPECT_EQ(recorder.noise->smoothing(), 5);
}

TEST_F(Pipeline, ViewerUpdatesFollowTheOcclusionAwareSecondCarving) {
  SilentProgress progress;
  Recorder recorder;
  ReconstructionParams params;
  params.occlusion_aware_carving = true;
  const ReconstructionResult r = runPipeline(readMission(mission()), params, progress, &recorder);
  std::size_t shown = 0;
  for (const auto& [block, points] : recorder.blocks) {
    shown += points.size();
  }
  EXPECT_EQ(shown, r.map->occupiedCount());
  EXPECT_GT(r.surface.size(), 500u);
}

TEST_F(Pipeline, BrokenFramesAreSkippedAndReported) {
  test::ScratchDir dir;
  const auto copy = dir.path() / "m";
  std::filesystem::copy(mission(), copy, std::filesystem::copy_options::recursive);
  test::writeText(copy / "frames" / "000005.png", "truncated");
  SilentProgress progress;
  Recorder recorder;
  const ReconstructionResult r =
      runPipeline(readMission(copy), ReconstructionParams{}, progress, &recorder);
  EXPECT_EQ(r.frames_used, 23u);
  ASSERT_EQ(r.skipped.size(), 1u);
  EXPECT_EQ(r.skipped[0].index, 5u);
  EXPECT_NE(r.skipped[0].message.find("000005.png"), std::string::npos);
  ASSERT_EQ(recorder.skipped.size(), 1u);
}

TEST_F(Pipeline, CancellingWhileTheNoiseIsLearnedStopsBeforeCarving) {
  CancelAfter progress(2, "noise model");
  const ReconstructionResult r =
      runPipeline(readMission(mission()), ReconstructionParams{}, progress);
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.frames_used, 0u);
  EXPECT_TRUE(r.surface.empty());
}

TEST_F(Pipeline, CancellingStopsBetweenFrames) {
  CancelAfter progress(3);
  const ReconstructionResult r =
      runPipeline(readMission(mission()), ReconstructionParams{}, progress);
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.frames_used, 3u);
}

TEST_F(Pipeline, FrameSelectionAndStride) {
  const Mission m = readMission(mission());
  ReconstructionParams p;
  p.first_frame = 2;
  p.last_frame = 12;
  p.stride = 3;
  EXPECT_EQ(selectedFrames(m, p), (std::vector<std::size_t>{2, 5, 8, 11}));
}

TEST_F(Pipeline, ApertureOverrideNarrowsWhatEachFrameCarves) {
  SilentProgress progress;
  const Mission m = readMission(mission());
  ReconstructionParams own;
  own.mesh_enabled = false;
  ReconstructionParams same = own;
  same.vertical_aperture_rad = m.sonar.verticalAperture();
  ReconstructionParams narrow = own;
  narrow.vertical_aperture_rad = m.sonar.verticalAperture() / 2.0;
  const ReconstructionResult r_own = runPipeline(m, own, progress);
  const ReconstructionResult r_same = runPipeline(m, same, progress);
  const ReconstructionResult r_narrow = runPipeline(m, narrow, progress);
  EXPECT_EQ(r_same.occupied_voxels, r_own.occupied_voxels);
  EXPECT_EQ(r_same.surface.size(), r_own.surface.size());
  // Half the aperture: each frustum is half as tall, so the map touches fewer blocks.
  EXPECT_LT(r_narrow.map_bytes, r_own.map_bytes);
}

TEST_F(Pipeline, BeamWidthOverrideTakesTheBeamsBlurOut) {
  // The example mission gives no beam width (64 beams, 0.95 degree apart) and its frames show
  // none: nothing is taken out unless an analyst says how wide the beams are.
  SilentProgress progress;
  const Mission m = readMission(mission());
  ReconstructionParams own;
  own.mesh_enabled = false;
  ReconstructionParams wide = own;
  wide.horizontal_beam_width_rad = degToRad(3.0);
  const ReconstructionResult r_own = runPipeline(m, own, progress);
  const ReconstructionResult r_wide = runPipeline(m, wide, progress);
  const RunChoice* own_deblur = findChoice(r_own.choices, "bearing deblur");
  const RunChoice* wide_deblur = findChoice(r_wide.choices, "bearing deblur");
  ASSERT_TRUE(own_deblur && wide_deblur);
  EXPECT_EQ(own_deblur->value, "off");
  EXPECT_EQ(own_deblur->detail.rfind("off: the mission gives no horizontal beam width, and none "
                                     "was read from",
                                     0),
            0u)
      << own_deblur->detail;
  EXPECT_EQ(wide_deblur->value, "on");
  EXPECT_NE(wide_deblur->detail.find("3.00 degree beams"), std::string::npos)
      << wide_deblur->detail;
  EXPECT_NE(wide_deblur->reason.find("taken out"), std::string::npos) << wide_deblur->reason;
  EXPECT_NE(r_wide.occupied_voxels, r_own.occupied_voxels);
}

TEST(ReconstructionParamsYaml, RoundTripsAndRefusesBadValues) {
  test::ScratchDir dir;
  ReconstructionParams p;
  p.engine = Engine::Reference;
  p.carve.voxel_size_m = 0.03;
  p.carve.intensity_threshold = 12.5;
  p.carve.region = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -2, 3), Eigen::Vector3d(4, 5, 6));
  p.stride = 2;
  p.min_views = 7;
  p.vertical_aperture_rad = degToRad(12.0);
  p.horizontal_beam_width_rad = degToRad(1.0);
  test::writeText(dir.path() / "p.yaml", p.toYaml());
  const ReconstructionParams back =
      ReconstructionParams::fromYamlFile((dir.path() / "p.yaml").string());
  EXPECT_EQ(back.engine, Engine::Reference);
  EXPECT_EQ(back.carve.voxel_size_m, 0.03);
  EXPECT_EQ(back.carve.intensity_threshold, 12.5);
  EXPECT_NEAR(back.carve.elevation_step_rad, p.carve.elevation_step_rad, 1e-15);
  ASSERT_TRUE(back.carve.region);
  EXPECT_TRUE(back.carve.region->isApprox(*p.carve.region));
  EXPECT_EQ(back.stride, 2u);
  EXPECT_EQ(back.min_views, 7u);
  EXPECT_NEAR(back.vertical_aperture_rad, degToRad(12.0), 1e-12);
  EXPECT_NEAR(back.horizontal_beam_width_rad, degToRad(1.0), 1e-12);
  for (const std::string bad :
       {"voxel_size_m: -1\n", "engine: magic\n", "frames: {stride: 0}\n",
        "region: {min_m: [0, 0, 0], max_m: [-1, 1, 1]}\n", "range_min_m: 5\nrange_max_m: 4\n",
        "vertical_aperture_deg: 200\n", "vertical_aperture_deg: -3\n",
        "horizontal_beam_width_deg: -1\n", "horizontal_beam_width_deg: 45\n"}) {
    test::writeText(dir.path() / "bad.yaml", bad);
    EXPECT_THROW(ReconstructionParams::fromYamlFile((dir.path() / "bad.yaml").string()), Error)
        << bad;
  }
}

}  // namespace
}  // namespace sonarcarve
