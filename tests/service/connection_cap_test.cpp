// The connection cap follows the memory limit (issue 24): at the cap a new connection gets 503,
// before the container's memory limit would kill the process.

#include <sys/resource.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "service/http_tuning.h"

namespace cutcalc::service {
namespace {

constexpr std::uint64_t kMiB = 1024 * 1024;

// Raises the soft RLIMIT_NOFILE to the hard limit for the test's lifetime, so that the descriptor
// bound is as far from the memory bound as this machine allows.
class SoftFdLimitAtHard {
 public:
  SoftFdLimitAtHard() {
    ::getrlimit(RLIMIT_NOFILE, &saved_);
    rlimit raised = saved_;
    raised.rlim_cur = saved_.rlim_max;
    ::setrlimit(RLIMIT_NOFILE, &raised);
  }
  ~SoftFdLimitAtHard() { ::setrlimit(RLIMIT_NOFILE, &saved_); }
  SoftFdLimitAtHard(const SoftFdLimitAtHard&) = delete;
  SoftFdLimitAtHard& operator=(const SoftFdLimitAtHard&) = delete;

 private:
  rlimit saved_{};
};

TEST(ConnectionCap, FollowsTheMemoryLimit) {
  const SoftFdLimitAtHard raised;
  const HttpTuning tuning;  // 16 KiB a connection
  ASSERT_EQ(tuning.max_connections, 0U);

  // No memory limit: the descriptor limit less a small reserve decides (at most 65536).
  const std::size_t by_descriptors = effective_max_connections(tuning, std::nullopt, 2);
  rlimit limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &limit), 0);
  if (limit.rlim_cur == RLIM_INFINITY) {
    EXPECT_EQ(by_descriptors, 65536U);
  } else {
    const auto soft = static_cast<std::size_t>(limit.rlim_cur);
    EXPECT_LT(by_descriptors, std::max<std::size_t>(soft, 2));
    EXPECT_GE(by_descriptors,
              std::min<std::size_t>(soft, 65536) - std::min<std::size_t>(soft, 256));
  }
  EXPECT_GE(by_descriptors, 1U);

  // 256 MiB less the baseline (32), a calculation peak per thread (64 each) and the least work
  // budget (64), at 16 KiB each, unless the descriptors are fewer.
  EXPECT_EQ(effective_max_connections(tuning, 256 * kMiB, 2),
            std::min<std::size_t>(2048, by_descriptors));
  EXPECT_EQ(effective_max_connections(tuning, 256 * kMiB, 1),
            std::min<std::size_t>(6144, by_descriptors));
  EXPECT_EQ(effective_max_connections(tuning, 1024 * kMiB, 2),
            std::min<std::size_t>(51200, by_descriptors));
  // A memory limit too small for its calculations still takes the least cap.
  EXPECT_EQ(effective_max_connections(tuning, 128 * kMiB, 2),
            std::min<std::size_t>(kMinimumMemoryConnections, by_descriptors));
  EXPECT_EQ(effective_max_connections(tuning, 0, 2),
            std::min<std::size_t>(kMinimumMemoryConnections, by_descriptors));

  // What a connection is budgeted counts.
  HttpTuning costly = tuning;
  costly.connection_memory_bytes = 32 * 1024;
  EXPECT_EQ(effective_max_connections(costly, 256 * kMiB, 1),
            std::min<std::size_t>(3072, by_descriptors));

  // --max-connections wins over both limits.
  HttpTuning given = tuning;
  given.max_connections = 7;
  EXPECT_EQ(effective_max_connections(given, 256 * kMiB, 2), 7U);
  EXPECT_EQ(effective_max_connections(given, 1 * kMiB, 2), 7U);
  EXPECT_EQ(effective_max_connections(given, std::nullopt, 2), 7U);
  given.max_connections = 500000;
  EXPECT_EQ(effective_max_connections(given, 128 * kMiB, 2), 500000U);
}

}  // namespace
}  // namespace cutcalc::service
