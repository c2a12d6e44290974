// The event loops follow the CPUs the process may use: the affinity mask (what taskset sets) and
// the cgroup v2 quota of its cgroup and every ancestor (a fake tree here).

#include "service/cpu_budget.h"

#include <gtest/gtest.h>
#include <sched.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "service/http_tuning.h"

namespace cutcalc::service {
namespace {

namespace fs = std::filesystem;

void write_file(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A fake cgroup v2 mount and /proc/self/cgroup, removed at the end of the test.
class FakeCgroup {
 public:
  FakeCgroup()
      : root_(fs::temp_directory_path() / ("cutcalc-cgroup-" + std::to_string(::getpid()))) {
    fs::remove_all(root_);
    write_file(root_ / "self_cgroup", "0::/kubepods/pod1/cutcalc\n");
  }
  ~FakeCgroup() { fs::remove_all(root_); }
  FakeCgroup(const FakeCgroup&) = delete;
  FakeCgroup& operator=(const FakeCgroup&) = delete;

  void set_cpu_max(const std::string& cgroup, const std::string& line) {
    write_file(root_ / "fs" / cgroup / "cpu.max", line + "\n");
  }
  [[nodiscard]] CpuBudget budget() const {
    return read_cpu_budget(root_ / "fs", root_ / "self_cgroup");
  }
  void set_memory_max(const std::string& cgroup, const std::string& line) {
    write_file(root_ / "fs" / cgroup / "memory.max", line + "\n");
  }
  void set_self(const std::string& text) { write_file(root_ / "self_cgroup", text); }
  void write(const std::string& file, const std::string& line) {
    write_file(root_ / "fs" / file, line + "\n");
  }
  [[nodiscard]] std::optional<std::uint64_t> memory_limit() const {
    return read_memory_limit(root_ / "fs", root_ / "self_cgroup");
  }

 private:
  fs::path root_;
};

// Pins the calling thread to CPU 0 (as `taskset -c 0` would the process) for its lifetime.
class PinnedToOneCpu {
 public:
  PinnedToOneCpu() {
    CPU_ZERO(&saved_);
    ::sched_getaffinity(0, sizeof(saved_), &saved_);
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(0, &one);
    pinned_ = ::sched_setaffinity(0, sizeof(one), &one) == 0;
  }
  ~PinnedToOneCpu() { ::sched_setaffinity(0, sizeof(saved_), &saved_); }
  PinnedToOneCpu(const PinnedToOneCpu&) = delete;
  PinnedToOneCpu& operator=(const PinnedToOneCpu&) = delete;
  [[nodiscard]] bool pinned() const { return pinned_; }

 private:
  cpu_set_t saved_;
  bool pinned_ = false;
};

TEST(CpuBudget, CpuMaxLinesReadAsCpus) {
  EXPECT_DOUBLE_EQ(parse_cpu_max("200000 100000\n").value(), 2.0);
  EXPECT_DOUBLE_EQ(parse_cpu_max("50000 100000").value(), 0.5);
  EXPECT_FALSE(parse_cpu_max("max 100000").has_value());
  EXPECT_FALSE(parse_cpu_max("").has_value());
  EXPECT_FALSE(parse_cpu_max("100000").has_value());
  EXPECT_FALSE(parse_cpu_max("-1 100000").has_value());
  EXPECT_FALSE(parse_cpu_max("100000 0").has_value());
}

TEST(CpuBudget, NoQuotaLeavesTheAffinityMask) {
  FakeCgroup cgroup;
  cgroup.set_cpu_max("kubepods/pod1/cutcalc", "max 100000");
  const CpuBudget budget = cgroup.budget();
  EXPECT_FALSE(budget.quota_cpus.has_value());
  EXPECT_EQ(budget.usable_cpus, budget.affinity_cpus);
}

TEST(CpuBudget, TheTightestQuotaUpTheTreeCapsTheLoops) {
  FakeCgroup cgroup;
  cgroup.set_cpu_max("kubepods", "6400000 100000");     // 64 CPUs for all pods
  cgroup.set_cpu_max("kubepods/pod1", "50000 100000");  // this pod: half a CPU
  cgroup.set_cpu_max("kubepods/pod1/cutcalc", "max 100000");
  const CpuBudget budget = cgroup.budget();
  ASSERT_TRUE(budget.quota_cpus.has_value());
  EXPECT_DOUBLE_EQ(*budget.quota_cpus, 0.5);
  EXPECT_EQ(budget.usable_cpus, 1U);  // at least one loop
}

TEST(CpuBudget, AFractionalQuotaRoundsUp) {
  FakeCgroup cgroup;
  cgroup.set_cpu_max("kubepods/pod1/cutcalc", "150000 100000");
  const CpuBudget budget = cgroup.budget();
  EXPECT_EQ(budget.usable_cpus, std::min<std::size_t>(budget.affinity_cpus, 2));
}

TEST(CpuBudget, AnAffinityMaskOfOneCpuMeansOneEventLoop) {
  const PinnedToOneCpu pin;
  ASSERT_TRUE(pin.pinned());
  FakeCgroup cgroup;  // no quota at all
  const CpuBudget budget = cgroup.budget();
  EXPECT_EQ(budget.affinity_cpus, 1U);
  EXPECT_EQ(budget.usable_cpus, 1U);
  EXPECT_EQ(effective_event_loop_threads(HttpTuning{}), 1U);
  HttpTuning explicit_threads;
  explicit_threads.event_loop_threads = 3;  // --threads wins over the budget
  EXPECT_EQ(effective_event_loop_threads(explicit_threads), 3U);
}

// The connection cap follows the memory limit (issue 24): the same walk up the tree as the quota.
TEST(MemoryLimit, TheTightestMemoryMaxUpTheTreeWins) {
  FakeCgroup cgroup;
  cgroup.set_memory_max("kubepods", "8589934592");        // 8 GiB for all pods
  cgroup.set_memory_max("kubepods/pod1", "268435456");    // this pod: 256 MiB
  cgroup.set_memory_max("kubepods/pod1/cutcalc", "max");  // the container: no limit of its own
  EXPECT_EQ(cgroup.memory_limit(), std::optional<std::uint64_t>(268435456));
  cgroup.set_memory_max("kubepods/pod1/cutcalc", "134217728");  // tighter below
  EXPECT_EQ(cgroup.memory_limit(), std::optional<std::uint64_t>(134217728));
  cgroup.set_memory_max("kubepods", "67108864");  // tighter above
  EXPECT_EQ(cgroup.memory_limit(), std::optional<std::uint64_t>(67108864));
}

TEST(MemoryLimit, CgroupV1LimitInBytesCountsAndItsUnlimitedValueDoesNot) {
  FakeCgroup cgroup;
  cgroup.set_self("12:cpu,cpuacct:/x\n11:memory:/machine.slice/libpod-1\n");
  cgroup.write("memory/machine.slice/libpod-1/memory.limit_in_bytes", "9223372036854771712");
  EXPECT_FALSE(cgroup.memory_limit().has_value());
  cgroup.write("memory/machine.slice/libpod-1/memory.limit_in_bytes", "268435456");
  EXPECT_EQ(cgroup.memory_limit(), std::optional<std::uint64_t>(268435456));
  // In a container the mount's root is the container's group.
  cgroup.write("memory/memory.limit_in_bytes", "134217728");
  EXPECT_EQ(cgroup.memory_limit(), std::optional<std::uint64_t>(134217728));
}

TEST(MemoryLimit, MaxEverywhereOrNoFileMeansNone) {
  FakeCgroup cgroup;
  EXPECT_FALSE(cgroup.memory_limit().has_value());  // no memory.max at all (no cgroup v2)
  cgroup.set_memory_max("kubepods", "max");
  cgroup.set_memory_max("kubepods/pod1/cutcalc", "max");
  EXPECT_FALSE(cgroup.memory_limit().has_value());
  cgroup.set_memory_max("kubepods/pod1", "");  // unreadable as a number: ignored
  EXPECT_FALSE(cgroup.memory_limit().has_value());
}

TEST(CpuBudget, DescriptionNamesTheFigures) {
  CpuBudget budget;
  budget.affinity_cpus = 64;
  budget.quota_cpus = 1.5;
  budget.usable_cpus = 2;
  EXPECT_EQ(describe(budget), "2 CPUs (affinity 64, cgroup quota 1.5)");
  budget.quota_cpus.reset();
  budget.usable_cpus = 1;
  EXPECT_EQ(describe(budget), "1 CPU (affinity 64, cgroup quota none)");
}

}  // namespace
}  // namespace cutcalc::service
