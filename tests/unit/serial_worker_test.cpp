#include <gtest/gtest.h>

#include <future>
#include <stdexcept>
#include <vector>

#include "common/error.h"
#include "common/serial_worker.h"

namespace sonarcarve {
namespace {

TEST(SerialWorker, RunsJobsInTheOrderSubmitted) {
  SerialWorker worker(2);
  std::vector<int> order;  // written by the worker only, read after finish()
  for (int i = 0; i < 100; ++i) {
    worker.submit([&order, i] { order.push_back(i); });
  }
  worker.finish();
  ASSERT_EQ(order.size(), 100u);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(order[static_cast<std::size_t>(i)], i);
  }
}

TEST(SerialWorker, AFailedJobIsRethrownAndTheJobsQueuedBehindItAreDropped) {
  SerialWorker worker(2);
  std::promise<void> gate;
  std::shared_future<void> opened = gate.get_future().share();
  bool later_ran = false;
  worker.submit([opened] {
    opened.wait();
    throw std::runtime_error("disk full");
  });
  worker.submit([&later_ran] { later_ran = true; });  // waits behind the failing job
  gate.set_value();
  EXPECT_THROW(worker.finish(), std::runtime_error);
  EXPECT_FALSE(later_ran);
  // The failure is reported once; the worker takes jobs again.
  bool after = false;
  worker.submit([&after] { after = true; });
  worker.finish();
  EXPECT_TRUE(after);
}

TEST(SerialWorker, TheNextSubmitReportsAFailure) {
  SerialWorker worker(1);
  worker.submit([] { throw std::runtime_error("encoding failed"); });
  // The failing job has run by the time a third job would have to wait: a submit sees it.
  EXPECT_THROW(
      {
        for (int i = 0; i < 3; ++i) {
          worker.submit([] {});
        }
      },
      std::runtime_error);
}

TEST(SerialWorker, RefusesAQueueOfNoJobs) {
  EXPECT_THROW(SerialWorker(0), Error);
}

}  // namespace
}  // namespace sonarcarve
