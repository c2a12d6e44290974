// The memory budget: what fits is taken, what is held is counted past it, everything comes back;
// and the budget the service derives from its memory limit.

#include "service/memory_budget.h"

#include <gtest/gtest.h>

#include <utility>

#include "api/routes.h"
#include "service/http_tuning.h"

namespace cutcalc::service {
namespace {

constexpr std::uint64_t kMebibyte = 1024 * 1024;

TEST(MemoryBudget, TakesWhatFitsAndRefusesWhatDoesNot) {
  MemoryBudget budget(10);
  EXPECT_TRUE(budget.try_take(6));
  EXPECT_FALSE(budget.try_take(5));
  EXPECT_EQ(budget.used(), 6U);
  EXPECT_TRUE(budget.try_take(4));
  EXPECT_TRUE(budget.spent());
  budget.give_back(10);
  EXPECT_EQ(budget.used(), 0U);
  EXPECT_FALSE(budget.try_take(11));
}

TEST(MemoryBudget, ChargeCountsHeldBytesPastTheCapacityAndGivesAllBackAtTheEnd) {
  MemoryBudget budget(10);
  {
    BudgetCharge charge(budget);
    EXPECT_TRUE(charge.try_add(4));
    charge.set(25);  // an answer that is computed already
    EXPECT_EQ(budget.used(), 25U);
    EXPECT_TRUE(budget.spent());
    EXPECT_FALSE(budget.try_take(1));
    charge.set(3);
    EXPECT_EQ(budget.used(), 3U);
  }
  EXPECT_EQ(budget.used(), 0U);
}

TEST(MemoryBudget, LeaseGivesItsBytesBackUnlessTakenOver) {
  MemoryBudget budget(100);
  ASSERT_TRUE(budget.try_take(30));
  { BudgetLease dropped(budget, 30); }
  EXPECT_EQ(budget.used(), 0U);
  ASSERT_TRUE(budget.try_take(40));
  BudgetLease handed(budget, 40);
  BudgetLease moved = std::move(handed);
  {
    BudgetCharge charge(budget);
    charge.adopt(moved.release());
    EXPECT_EQ(budget.used(), 40U);
    charge.set(10);
    EXPECT_EQ(budget.used(), 10U);
  }
  EXPECT_EQ(budget.used(), 0U);
}

TEST(MemoryBudget, ServiceBudgetIsTheLimitLessConnectionsCalculationsAndBaseline) {
  const HttpTuning tuning;
  const std::uint64_t limit = 1024 * kMebibyte;
  const std::size_t connections = effective_max_connections(tuning, limit, 2);
  EXPECT_EQ(effective_memory_budget(tuning, connections, 2, limit),
            limit - connections * tuning.connection_memory_bytes - kProcessBaselineBytes -
                2 * kCalculationPeakBytes);
  // Without a limit the connections are not bounded by memory and not counted.
  EXPECT_EQ(effective_memory_budget(tuning, 65536, 1, std::nullopt),
            kDefaultMemoryLimitBytes - kProcessBaselineBytes - kCalculationPeakBytes);
  // A 256 MiB pod: the connection cap leaves the work budget room for the largest body a route
  // takes, counted as the engine counts a large body (a program to time: 32 MiB, twice).
  for (const std::size_t threads : {1, 2}) {
    const std::uint64_t budget =
        effective_memory_budget(tuning, effective_max_connections(tuning, 256 * kMebibyte, threads),
                                threads, 256 * kMebibyte);
    EXPECT_GE(budget, kLargeBodyHeldTimes * api::kProgramBodyBytes) << threads << " threads";
    EXPECT_EQ(budget, kMinimumMemoryBudgetBytes) << threads << " threads";
  }
}

}  // namespace
}  // namespace cutcalc::service
