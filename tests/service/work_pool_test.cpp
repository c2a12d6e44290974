// The calculation pool: it runs what it accepts, refuses (and counts) what does not fit its queue,
// and finishes the queued jobs before it is gone. Jobs are held on a gate, never timed.

#include "service/work_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "support/gate.h"

namespace cutcalc::service {
namespace {

using cutcalc::testing::eventually;
using cutcalc::testing::Gate;

// Opens the gate when a test leaves its scope, failed assertions included: a pool joins its
// threads on destruction, so a thread still held there would hang the test.
struct OpensOnExit {
  Gate& gate;
  ~OpensOnExit() { gate.open(); }
};

WorkPoolSettings settings(std::size_t threads, std::size_t queue_limit) {
  WorkPoolSettings result;
  result.threads = threads;
  result.queue_limit = queue_limit;
  result.nice_increment = 0;
  return result;
}

TEST(WorkPool, RunsEveryJobItAccepts) {
  WorkPoolCounters counters;
  std::atomic<int> done{0};
  {
    WorkPool pool(settings(2, 100), counters);
    for (int i = 0; i < 50; ++i) {
      ASSERT_TRUE(pool.try_submit([&done] { done.fetch_add(1); }));
    }
    ASSERT_TRUE(eventually([&] { return done.load() == 50; }));
  }
  EXPECT_EQ(counters.jobs.load(), 50U);
  EXPECT_EQ(counters.refused.load(), 0U);
}

TEST(WorkPool, RefusesBeyondTheQueueLimitAndCountsIt) {
  WorkPoolCounters counters;
  Gate gate;
  std::atomic<int> done{0};
  {
    WorkPool pool(settings(1, 2), counters);
    const OpensOnExit opens{gate};
    ASSERT_TRUE(pool.try_submit([&] {
      gate.pass();
      done.fetch_add(1);
    }));
    ASSERT_TRUE(gate.wait_inside(1));  // the one thread is busy: the rest queue
    EXPECT_TRUE(pool.try_submit([&] { done.fetch_add(1); }));
    EXPECT_TRUE(pool.try_submit([&] { done.fetch_add(1); }));
    EXPECT_EQ(counters.queued.load(), 2U);
    EXPECT_EQ(counters.running.load(), 1U);
    bool refused_job_ran = false;
    EXPECT_FALSE(pool.try_submit([&] { refused_job_ran = true; }));
    EXPECT_FALSE(pool.try_submit([&] { refused_job_ran = true; }));
    EXPECT_EQ(counters.refused.load(), 2U);
    gate.open();
    ASSERT_TRUE(eventually([&] { return done.load() == 3; }));
    EXPECT_FALSE(refused_job_ran);
  }
  EXPECT_EQ(counters.jobs.load(), 3U);
}

TEST(WorkPool, DestructorRunsTheQueuedJobsBeforeJoining) {
  WorkPoolCounters counters;
  Gate gate;
  std::atomic<int> done{0};
  auto pool = std::make_unique<WorkPool>(settings(1, 1000000), counters);
  const OpensOnExit opens{gate};
  ASSERT_TRUE(pool->try_submit([&] {
    gate.pass();
    done.fetch_add(1);
  }));
  ASSERT_TRUE(gate.wait_inside(1));
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(pool->try_submit([&done] { done.fetch_add(1); }));
  }
  // The gate opens only once the destructor has begun: from then on the pool refuses new work
  // (its queue has room, so a refusal says it is quitting). The destructor cannot finish before
  // the gate opens (it joins the held thread), so the probe never outlives the pool.
  WorkPool* const quitting = pool.get();
  std::atomic<int> accepted{0};
  std::thread opener([&] {
    while (quitting->try_submit([&done] { done.fetch_add(1); })) {
      accepted.fetch_add(1);
      std::this_thread::yield();
    }
    gate.open();
  });
  pool.reset();
  opener.join();
  EXPECT_EQ(done.load(), 6 + accepted.load());
  EXPECT_EQ(counters.queued.load(), 0U);
}

TEST(WorkPool, CountersReturnToIdleAfterTheJobs) {
  WorkPoolCounters counters;
  Gate gate;
  {
    WorkPool pool(settings(2, 4), counters);
    const OpensOnExit opens{gate};
    for (int i = 0; i < 2; ++i) {
      ASSERT_TRUE(pool.try_submit([&gate] { gate.pass(); }));
    }
    ASSERT_TRUE(gate.wait_inside(2));  // both threads held: the next four wait in the queue
    for (int i = 0; i < 4; ++i) {
      ASSERT_TRUE(pool.try_submit([&gate] { gate.pass(); }));
    }
    EXPECT_EQ(counters.running.load(), 2U);
    EXPECT_EQ(counters.queued.load(), 4U);
    gate.open();
    ASSERT_TRUE(eventually([&] { return counters.jobs.load() == 6; }));
    ASSERT_TRUE(eventually([&] { return counters.running.load() == 0; }));
    EXPECT_EQ(counters.queued.load(), 0U);
  }
  EXPECT_EQ(counters.queued.load(), 0U);
  EXPECT_EQ(counters.running.load(), 0U);
  EXPECT_EQ(counters.jobs.load(), 6U);
  EXPECT_EQ(counters.refused.load(), 0U);
}

}  // namespace
}  // namespace cutcalc::service
