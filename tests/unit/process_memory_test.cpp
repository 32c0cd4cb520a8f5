// The bench's memory sampler (issue 18): /proc/self/status read into sane figures, and the
// trace of a run's stages and memory kept beside its progress.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "common/process_memory.h"
#include "common/progress_trace.h"

namespace sonarcarve {
namespace {

TEST(ProcessMemory, ReadsTheFieldsOfAStatusText) {
  const auto m = processMemoryFrom(
      "Name:\tbench\nVmPeak:\t  900 kB\nVmHWM:\t    4096 kB\nVmRSS:\t    2048 kB\n"
      "RssAnon:\t    1024 kB\nRssFile:\t 1024 kB\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->resident_bytes, 2048u * 1024u);
  EXPECT_EQ(m->peak_resident_bytes, 4096u * 1024u);
  EXPECT_EQ(m->anonymous_bytes, 1024u * 1024u);
  EXPECT_FALSE(processMemoryFrom("Name:\tbench\nVmRSS:\t 2048 kB\n"));  // no VmHWM
  EXPECT_FALSE(processMemoryFrom("VmRSS:\tlots\nVmHWM:\t 1 kB\n"));
  EXPECT_EQ(processMemoryFrom("VmRSS: 1 kB\nVmHWM: 2 kB\n")->anonymous_bytes, 0u);
}

TEST(ProcessMemory, ThisProcessIsSaneAndGrowsWithWhatItTouches) {
  const auto before = processMemory();
  ASSERT_TRUE(before);
  EXPECT_GT(before->resident_bytes, 1u << 20);  // a test program takes more than a MiB
  EXPECT_GE(before->peak_resident_bytes, before->resident_bytes);
  EXPECT_LE(before->anonymous_bytes, before->resident_bytes);
  EXPECT_LT(before->resident_bytes, std::uint64_t{64} << 30);
  const std::size_t size = std::size_t{64} << 20;
  auto block = std::make_unique<char[]>(size);
  std::memset(block.get(), 1, size);  // touched: resident
  const auto after = processMemory();
  ASSERT_TRUE(after);
  EXPECT_GT(after->resident_bytes, before->resident_bytes + (std::size_t{48} << 20));
  EXPECT_GT(after->anonymous_bytes, before->anonymous_bytes + (std::size_t{48} << 20));
  EXPECT_GE(after->peak_resident_bytes, after->resident_bytes);
  EXPECT_EQ(block[size - 1], 1);
}

class CountingProgress : public Progress {
 public:
  void report(const std::string&, std::size_t, std::size_t) override { ++reports; }
  bool cancelled() const override { return stop; }
  std::size_t reports = 0;
  bool stop = false;
};

TEST(MemoryTrace, SamplesAtStageChangesAndEveryNUnitsAgainstFramesCarved) {
  CountingProgress inner;
  MemoryTrace trace(inner, 100);
  trace.sample("start");
  for (std::size_t i = 1; i <= 250; ++i) {
    trace.report("carve", i, 250);
  }
  for (std::size_t i = 1; i <= 10; ++i) {
    trace.report("occlusion", i, 10);
  }
  EXPECT_EQ(inner.reports, 260u);
  EXPECT_FALSE(trace.cancelled());
  inner.stop = true;
  EXPECT_TRUE(trace.cancelled());
  const auto samples = trace.samples();
  // start; carve at 1 (new stage), 100, 200, 250 (its end); occlusion at 1 and 10.
  ASSERT_EQ(samples.size(), 7u);
  EXPECT_EQ(samples[0].stage, "start");
  EXPECT_EQ(samples[2].done, 100u);
  EXPECT_EQ(samples[4].frames_carved, 250u);
  EXPECT_EQ(samples[6].stage, "occlusion");
  EXPECT_EQ(samples[6].frames_carved, 250u);  // frames carved hold after carving
  for (const MemorySample& s : samples) {
    EXPECT_GT(s.memory.resident_bytes, 0u);
    EXPECT_GE(s.memory.peak_resident_bytes, s.memory.resident_bytes);
  }
  const auto stages = trace.stages();
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[0].stage, "carve");
  EXPECT_EQ(stages[0].units, 250u);
  EXPECT_LE(stages[0].last_report_s, stages[1].first_report_s);
}

}  // namespace
}  // namespace sonarcarve
