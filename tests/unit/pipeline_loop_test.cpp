// The pipeline as a loop over uniform stages (pipeline/stage.h): a stage added in one line
// runs where it is put and sees what the stages before it left; cancellation, memory checks
// and the run's overall progress are handled by the loop for every stage; the run's automatic
// choices (pipeline/run_choice.h) speak to an analyst on the example mission.
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>

#include "common/error.h"
#include "io/mission/mission.h"
#include "pipeline/reconstruction.h"
#include "pipeline/run_context.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

// A toy stage after carving: counts the frames carved and records it as a choice.
class CountCarvedFrames : public Stage {
 public:
  CountCarvedFrames() : Stage("count", 0.1) {}
  void run(RunContext& run, Progress& progress) const override {
    progress.report("count", 1, 1);
    RunChoice toy;
    toy.name = "toy";
    toy.value = std::to_string(run.carved.used.size());
    toy.reason = "frames carved before the toy stage";
    run.choose(toy);
  }
};

// A toy stage that is cancelled.
class Cancels : public Stage {
 public:
  Cancels() : Stage("cancels", 0.1) {}
  void run(RunContext&, Progress&) const override { throw Cancelled(); }
};

// A toy stage that finishes cancelled runs: it only records that it ran.
class Finishes : public Stage {
 public:
  Finishes() : Stage("finishes", 0.1) {}
  bool runsAfterCancel() const override { return true; }
  void run(RunContext& run, Progress&) const override {
    RunChoice ran;
    ran.name = "finishes";
    ran.value = "ran";
    run.choose(ran);
  }
};

// A toy stage that needs more memory than any budget.
class NeedsTooMuch : public Stage {
 public:
  NeedsTooMuch() : Stage("greedy", 0.1) {}
  std::optional<MemoryNeed> memoryNeed(const RunContext&) const override {
    return MemoryNeed{{{"everything", 1e18}}, "before the greedy stage"};
  }
  void run(RunContext&, Progress&) const override { ADD_FAILURE() << "ran past its memory check"; }
};

// Records the overall fractions the loop reports.
class OverallRecorder : public SilentProgress {
 public:
  void overall(double fraction) override {
    const std::lock_guard lock(mutex_);
    fractions_.push_back(fraction);
  }
  std::vector<double> fractions() const {
    const std::lock_guard lock(mutex_);
    return fractions_;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<double> fractions_;
};

ReconstructionParams quick() {
  ReconstructionParams params;
  params.mesh_enabled = false;
  return params;
}

TEST(PipelineLoop, StandardStagesRunInOrder) {
  const Mission mission = readMission(test::exampleMission());
  ThreadPool pool(2);
  Pipeline pipeline(mission, quick(), pool);
  EXPECT_EQ(pipeline.stageNames(),
            (std::vector<std::string>{"read", "denoise", "beam check", "choose", "seabed relief",
                                      "carve", "heading sectors", "surface", "mesh"}));
  std::filesystem::path out = "/nonexistent";
  pipeline.writeOutputsTo({out, {}, false, {}, {}});
  EXPECT_EQ(pipeline.stageNames().back(), "export");
  EXPECT_EQ(pipeline.stageNames()[pipeline.stageNames().size() - 2], "report");
}

TEST(PipelineLoop, AToyStageAddedInOneLineRunsWhereItIsPut) {
  const Mission mission = readMission(test::exampleMission());
  ThreadPool pool(2);
  Pipeline pipeline(mission, quick(), pool);
  pipeline.addStage(std::make_shared<CountCarvedFrames>(), "carve");
  EXPECT_EQ(pipeline.stageNames()[6], "count");
  OverallRecorder progress;
  const ReconstructionResult result = pipeline.run(progress);
  const RunChoice* toy = findChoice(result.choices, "toy");
  ASSERT_NE(toy, nullptr);
  EXPECT_EQ(toy->value, std::to_string(result.frames_used));  // it saw the carved frames
  EXPECT_GT(result.frames_used, 0u);
  EXPECT_FALSE(result.surface.empty());  // the stages after it ran
  // The run's progress only grows, and ends whole.
  const std::vector<double> fractions = progress.fractions();
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_NEAR(fractions.back(), 1.0, 1e-12);
  EXPECT_GE(fractions.front(), 0.0);
}

TEST(PipelineLoop, ACancelledStageSkipsTheRestButThoseThatFinishARun) {
  const Mission mission = readMission(test::exampleMission());
  ThreadPool pool(2);
  Pipeline pipeline(mission, quick(), pool);
  pipeline.addStage(std::make_shared<Cancels>(), "choose");
  pipeline.addStage(std::make_shared<Finishes>());
  SilentProgress progress;
  const ReconstructionResult result = pipeline.run(progress);
  EXPECT_TRUE(result.cancelled);
  EXPECT_EQ(result.frames_used, 0u);  // carve did not run
  EXPECT_TRUE(result.surface.empty());
  EXPECT_NE(findChoice(result.choices, "finishes"), nullptr);
  EXPECT_NE(findChoice(result.choices, "denoising"), nullptr);  // before the cancel
}

TEST(PipelineLoop, AStageThatNeedsTooMuchMemoryStopsTheRunBeforeItStarts) {
  const Mission mission = readMission(test::exampleMission());
  ThreadPool pool(2);
  ReconstructionParams params = quick();
  params.memory_budget_mb = 1024;
  Pipeline pipeline(mission, params, pool);
  pipeline.addStage(std::make_shared<NeedsTooMuch>(), "read");
  SilentProgress progress;
  try {
    pipeline.run(progress);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("before the greedy stage"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("everything"), std::string::npos) << e.what();
  }
}

// Every automatic choice on the example mission, as the log and the CLI show it: one line an
// analyst reads without the engine's vocabulary; the derivation is in the detail.
TEST(PipelineLoop, EveryChoiceOnTheExampleMissionSpeaksToAnAnalyst) {
  const Mission mission = readMission(test::exampleMission());
  ThreadPool pool(2);
  SilentProgress progress;
  const ReconstructionResult result = Pipeline(mission, quick(), pool).run(progress);
  std::vector<std::string> names;
  for (const RunChoice& choice : result.choices) {
    names.push_back(choice.name);
    const std::string line = choiceLine(choice);
    SCOPED_TRACE(line);
    EXPECT_EQ(line.find('\n'), std::string::npos);
    EXPECT_LE(line.size(), 120u);  // one line of a terminal or of the workbench's log
    EXPECT_FALSE(choice.value.empty());
    EXPECT_FALSE(choice.detail.empty());
    // Internal quantities belong in the detail, not the reason.
    for (const char* internal : {"Nyquist", "cycles", "spectrum", "spacings", "percentile", "sigma",
                                 "octave", "iterations", "kernel", "counts", "power"}) {
      EXPECT_EQ(choice.reason.find(internal), std::string::npos) << internal;
    }
    for (const char c : choice.reason) {
      EXPECT_FALSE(c == '=' || c == '^') << "a formula in the reason";
    }
  }
  for (const char* expected :
       {"denoising", "bearing deblur", "shadow-aware carving", "seabed-aware carving"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
}

}  // namespace
}  // namespace sonarcarve
