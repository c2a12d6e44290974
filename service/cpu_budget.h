#pragma once
// How many CPUs this process may really use: the CPUs of its affinity mask (taskset, cpusets),
// capped by the cgroup v2 CPU quota (cpu.max: a pod limited to 1 CPU on a 64-core node) of its
// cgroup and every ancestor. The event loops are sized from it, not from the host's core count.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace cutcalc::service {

struct CpuBudget {
  std::size_t affinity_cpus = 1;     // CPUs in the affinity mask
  std::optional<double> quota_cpus;  // quota / period of the tightest cpu.max; none: unlimited
  std::size_t usable_cpus = 1;       // min(affinity, ceil(quota)), at least 1
};

// The CPUs a cgroup v2 `cpu.max` line allows ("200000 100000" -> 2.0); nullopt for "max ..." or an
// unreadable line.
std::optional<double> parse_cpu_max(std::string_view line);

// The budget of this process. `cgroup_root` is where cgroup v2 is mounted and `self_cgroup` the
// /proc/self/cgroup file naming the process's cgroup ("0::/kubepods/pod1/c1"); both are parameters
// so that tests can point them at a fake tree.
CpuBudget read_cpu_budget(const std::filesystem::path& cgroup_root = "/sys/fs/cgroup",
                          const std::filesystem::path& self_cgroup = "/proc/self/cgroup");

// The tightest cgroup v2 `memory.max` of this process's cgroup and its ancestors (or, on a cgroup
// v1 host, `memory.limit_in_bytes` of its memory group, its ancestors and its mount), bytes;
// nullopt when none is set ("max") or there is no cgroup v2. Same parameters as read_cpu_budget().
std::optional<std::uint64_t> read_memory_limit(
    const std::filesystem::path& cgroup_root = "/sys/fs/cgroup",
    const std::filesystem::path& self_cgroup = "/proc/self/cgroup");

// "2 CPUs (affinity 64, cgroup quota 1.5)": for the log line at start.
std::string describe(const CpuBudget& budget);

}  // namespace cutcalc::service
