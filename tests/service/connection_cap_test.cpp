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
  const HttpTuning tuning;  // 16 KiB a connection, 96 MiB reserved
  ASSERT_EQ(tuning.max_connections, 0U);

  // No memory limit: the descriptor limit less a small reserve decides (at most 65536).
  const std::size_t by_descriptors = effective_max_connections(tuning, std::nullopt);
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

  // 256 MiB: (256 - 96) MiB at 16 KiB each, unless the descriptors are fewer.
  EXPECT_EQ(effective_max_connections(tuning, 256 * kMiB),
            std::min<std::size_t>(10240, by_descriptors));
  EXPECT_EQ(effective_max_connections(tuning, 128 * kMiB),
            std::min<std::size_t>(2048, by_descriptors));
  // A memory limit no larger than the reserve still lets one connection in.
  EXPECT_EQ(effective_max_connections(tuning, 96 * kMiB), 1U);
  EXPECT_EQ(effective_max_connections(tuning, 64 * kMiB), 1U);
  EXPECT_EQ(effective_max_connections(tuning, 0), 1U);

  // What a connection is budgeted counts.
  HttpTuning costly = tuning;
  costly.connection_memory_bytes = 32 * 1024;
  EXPECT_EQ(effective_max_connections(costly, 128 * kMiB),
            std::min<std::size_t>(1024, by_descriptors));

  // --max-connections wins over both limits.
  HttpTuning given = tuning;
  given.max_connections = 7;
  EXPECT_EQ(effective_max_connections(given, 256 * kMiB), 7U);
  EXPECT_EQ(effective_max_connections(given, 1 * kMiB), 7U);
  EXPECT_EQ(effective_max_connections(given, std::nullopt), 7U);
  given.max_connections = 500000;
  EXPECT_EQ(effective_max_connections(given, 128 * kMiB), 500000U);
}

}  // namespace
}  // namespace cutcalc::service
