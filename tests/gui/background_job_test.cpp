// BackgroundJob, the GUI's one way to run work off its thread: results and errors arrive as
// values on the GUI thread, a new job supersedes the old one (its late results are dropped),
// pause holds the worker, and destruction joins a running job.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QTest>
#include <QThread>
#include <atomic>
#include <memory>
#include <optional>
#include <stdexcept>

#include "background_job.h"

namespace sonarcarve::gui {
namespace {

class BackgroundJobTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (QCoreApplication::instance() == nullptr) {
      static int argc = 1;
      static char name[] = "background_job_test";
      static char* argv[] = {name, nullptr};
      new QCoreApplication(argc, argv);
    }
  }
};

// Spins on the job's cancellation check until it is cancelled: a job that runs until stopped.
int runUntilCancelled(JobContext& context) {
  int checks = 0;
  while (!context.cancelled()) {
    context.report("waiting", static_cast<std::size_t>(++checks), 1000000);
    QThread::msleep(1);
  }
  return checks;
}

const auto kNoError = [](const JobError& e) { FAIL() << e.message.toStdString(); };

TEST_F(BackgroundJobTest, TheResultArrivesOnTheGuiThread) {
  BackgroundJob job;
  std::optional<int> result;
  QThread* delivered_on = nullptr;
  QThread* worked_on = nullptr;
  const int id = job.start(
      [&](JobContext&) {
        worked_on = QThread::currentThread();
        return 42;
      },
      [&](int value) {
        result = value;
        delivered_on = QThread::currentThread();
      },
      kNoError);
  EXPECT_GT(id, 0);
  EXPECT_TRUE(job.running());
  ASSERT_TRUE(QTest::qWaitFor([&] { return result.has_value(); }, 10000));
  EXPECT_EQ(*result, 42);
  EXPECT_EQ(delivered_on, QCoreApplication::instance()->thread());
  EXPECT_NE(worked_on, delivered_on);
  EXPECT_FALSE(job.running());
  EXPECT_EQ(job.currentJob(), id);
}

TEST_F(BackgroundJobTest, ErrorsArriveAsValuesAndCancellationIsNamed) {
  BackgroundJob job;
  std::optional<JobError> error;
  const auto keep = [&](const JobError& e) { error = e; };
  job.start([](JobContext&) -> int { throw std::runtime_error("bad log"); }, [](int) {}, keep);
  ASSERT_TRUE(QTest::qWaitFor([&] { return error.has_value(); }, 10000));
  EXPECT_EQ(error->message.toStdString(), "bad log");
  EXPECT_FALSE(error->cancelled);

  error.reset();
  job.start(
      [](JobContext& context) -> int {
        runUntilCancelled(context);
        throw Cancelled();
      },
      [](int) {}, keep);
  job.cancel();  // cancel, unlike discard, still delivers what the job ends with
  ASSERT_TRUE(QTest::qWaitFor([&] { return error.has_value(); }, 10000));
  EXPECT_TRUE(error->cancelled);
  EXPECT_FALSE(job.running());
}

TEST_F(BackgroundJobTest, ANewJobSupersedesTheRunningOne) {
  BackgroundJob job;
  std::atomic<bool> first_stopped{false};
  int first_results = 0;
  int first_reports = 0;
  const int first = job.start(
      [&](JobContext& context) {
        const int checks = runUntilCancelled(context);
        first_stopped = true;
        context.post([&] { ++first_results; });
        return checks;
      },
      [&](int) { ++first_results; }, kNoError,
      [&](const QString&, std::size_t, std::size_t) { ++first_reports; });
  ASSERT_TRUE(QTest::qWaitFor([&] { return first_reports > 0; }, 10000));
  std::optional<int> second;
  const int second_id =
      job.start([](JobContext&) { return 2; }, [&](int value) { second = value; }, kNoError);
  EXPECT_NE(second_id, first);
  EXPECT_EQ(job.currentJob(), second_id);
  ASSERT_TRUE(QTest::qWaitFor([&] { return second.has_value() && first_stopped; }, 10000));
  QTest::qWait(100);  // anything the first job posted has been processed by now
  EXPECT_EQ(*second, 2);
  EXPECT_EQ(first_results, 0);
}

// What a superseded job returns is never delivered, and is freed on its worker, not on the GUI
// thread (a cancelled run's map took the GUI thread hundreds of milliseconds to free).
TEST_F(BackgroundJobTest, ASupersededJobsResultIsFreedOnItsWorker) {
  struct Freed {
    explicit Freed(std::atomic<QThread*>* where) : on(where) {}
    Freed(const Freed&) = delete;
    Freed& operator=(const Freed&) = delete;
    ~Freed() { *on = QThread::currentThread(); }
    std::atomic<QThread*>* on;
  };
  std::atomic<QThread*> freed_on{nullptr};
  BackgroundJob job;
  std::atomic<bool> started{false};
  int first_results = 0;
  job.start(
      [&](JobContext& context) {
        started = true;
        runUntilCancelled(context);
        return std::make_shared<Freed>(&freed_on);
      },
      [&](const std::shared_ptr<Freed>&) { ++first_results; }, kNoError);
  ASSERT_TRUE(QTest::qWaitFor([&] { return started.load(); }, 10000));
  std::optional<int> second;
  job.start([](JobContext&) { return 2; }, [&](int value) { second = value; }, kNoError);
  ASSERT_TRUE(QTest::qWaitFor([&] { return second.has_value(); }, 10000));
  ASSERT_TRUE(QTest::qWaitFor([&] { return freed_on.load() != nullptr; }, 10000));
  EXPECT_NE(freed_on.load(), QThread::currentThread());
  QTest::qWait(100);  // anything the first job posted has been processed by now
  EXPECT_EQ(first_results, 0);
}

TEST_F(BackgroundJobTest, DiscardDropsTheResultAndPauseHoldsTheWorker) {
  BackgroundJob job;
  std::atomic<int> checks{0};
  bool delivered = false;
  job.start(
      [&](JobContext& context) {
        while (!context.cancelled()) {
          ++checks;
          QThread::msleep(1);
        }
        return 0;
      },
      [&](int) { delivered = true; }, [&](const JobError&) { delivered = true; });
  ASSERT_TRUE(QTest::qWaitFor([&] { return checks > 0; }, 10000));
  job.setPaused(true);
  EXPECT_TRUE(job.paused());
  QTest::qWait(50);
  const int held = checks;
  QTest::qWait(100);
  EXPECT_EQ(checks, held);
  job.discard();
  EXPECT_FALSE(job.running());
  EXPECT_FALSE(job.paused());
  EXPECT_EQ(job.currentJob(), 0);
  QTest::qWait(100);
  EXPECT_FALSE(delivered);
}

TEST_F(BackgroundJobTest, DestructionStopsAndJoinsARunningJob) {
  std::atomic<bool> began{false};
  std::atomic<bool> stopped{false};
  {
    BackgroundJob job;
    job.start(
        [&](JobContext& context) {
          began = true;
          runUntilCancelled(context);
          stopped = true;
          return 0;
        },
        [](int) {}, kNoError);
    ASSERT_TRUE(QTest::qWaitFor([&] { return began.load(); }, 10000));
    job.setPaused(true);  // a paused job is released too
  }
  EXPECT_TRUE(stopped);
}

}  // namespace
}  // namespace sonarcarve::gui
