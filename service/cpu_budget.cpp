#include "service/cpu_budget.h"

#include <sched.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <thread>

namespace cutcalc::service {
namespace {

std::size_t affinity_cpu_count() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int count = CPU_COUNT(&set);
    if (count > 0) return static_cast<std::size_t>(count);
  }
  return std::max(1U, std::thread::hardware_concurrency());
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !(value > 0.0)) {
    return std::nullopt;
  }
  return value;
}

std::string first_line(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// The cgroup v2 path of this process: the "0::" line of /proc/self/cgroup ("" when there is none).
std::string own_cgroup(const std::filesystem::path& self_cgroup) {
  std::ifstream in(self_cgroup);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("0::", 0) == 0) return line.substr(3);
  }
  return {};
}

// The cgroup v1 memory controller's path of this process: the "N:...memory...:" line of
// /proc/self/cgroup (nullopt when there is none).
std::optional<std::string> own_v1_memory_cgroup(const std::filesystem::path& self_cgroup) {
  std::ifstream in(self_cgroup);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find(':');
    const auto second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos) continue;
    std::string_view controllers = std::string_view(line).substr(first + 1, second - first - 1);
    while (!controllers.empty()) {
      const auto comma = controllers.find(',');
      if (controllers.substr(0, comma) == "memory") return line.substr(second + 1);
      controllers =
          comma == std::string_view::npos ? std::string_view{} : controllers.substr(comma + 1);
    }
  }
  return std::nullopt;
}

// A v1 memory.limit_in_bytes at or above this says "no limit" (the kernel's page-rounded
// LONG_MAX, 9223372036854771712).
constexpr std::uint64_t kV1Unlimited = std::uint64_t{1} << 60;

}  // namespace

std::optional<std::uint64_t> read_memory_limit(const std::filesystem::path& cgroup_root,
                                               const std::filesystem::path& self_cgroup) {
  std::optional<std::uint64_t> limit;
  std::filesystem::path relative = std::filesystem::path(own_cgroup(self_cgroup)).relative_path();
  while (true) {
    const std::string line = first_line(cgroup_root / relative / "memory.max");
    std::uint64_t bytes = 0;
    const auto [end, error] = std::from_chars(line.data(), line.data() + line.size(), bytes);
    if (error == std::errc() && end != line.data()) limit = std::min(limit.value_or(bytes), bytes);
    if (relative.empty()) break;
    relative = relative.parent_path();
  }
  // cgroup v1 (older hosts): the memory controller's hierarchy. In a container its mount is the
  // container's own group, whatever path /proc/self/cgroup names, so the mount's root counts too.
  if (const auto v1 = own_v1_memory_cgroup(self_cgroup)) {
    const std::filesystem::path mount = cgroup_root / "memory";
    relative = std::filesystem::path(*v1).relative_path();
    while (true) {
      const std::string line = first_line(mount / relative / "memory.limit_in_bytes");
      std::uint64_t bytes = 0;
      const auto [end, error] = std::from_chars(line.data(), line.data() + line.size(), bytes);
      if (error == std::errc() && end != line.data() && bytes < kV1Unlimited) {
        limit = std::min(limit.value_or(bytes), bytes);
      }
      if (relative.empty()) break;
      relative = relative.parent_path();
    }
  }
  return limit;
}

std::optional<double> parse_cpu_max(std::string_view line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == ' ')) line.remove_suffix(1);
  const auto space = line.find(' ');
  if (space == std::string_view::npos) return std::nullopt;
  const auto quota = parse_number(line.substr(0, space));  // "max" does not parse: unlimited
  const auto period = parse_number(line.substr(space + 1));
  if (!quota || !period) return std::nullopt;
  return *quota / *period;
}

CpuBudget read_cpu_budget(const std::filesystem::path& cgroup_root,
                          const std::filesystem::path& self_cgroup) {
  CpuBudget budget;
  budget.affinity_cpus = affinity_cpu_count();
  // A quota anywhere up the tree limits this cgroup too: the tightest one counts.
  std::filesystem::path relative = std::filesystem::path(own_cgroup(self_cgroup)).relative_path();
  while (true) {
    if (const auto cpus = parse_cpu_max(first_line(cgroup_root / relative / "cpu.max"))) {
      budget.quota_cpus = std::min(budget.quota_cpus.value_or(*cpus), *cpus);
    }
    if (relative.empty()) break;
    relative = relative.parent_path();
  }
  budget.usable_cpus = budget.affinity_cpus;
  if (budget.quota_cpus) {
    const auto quota = static_cast<std::size_t>(std::ceil(*budget.quota_cpus));
    budget.usable_cpus = std::min(budget.usable_cpus, std::max<std::size_t>(quota, 1));
  }
  return budget;
}

std::string describe(const CpuBudget& budget) {
  std::string text = std::to_string(budget.usable_cpus);
  text += budget.usable_cpus == 1 ? " CPU (affinity " : " CPUs (affinity ";
  text += std::to_string(budget.affinity_cpus);
  text += ", cgroup quota ";
  if (budget.quota_cpus) {
    char quota[32];
    const auto [end, error] = std::to_chars(quota, quota + sizeof(quota), *budget.quota_cpus);
    text.append(quota, error == std::errc() ? end : quota);
  } else {
    text += "none";
  }
  text += ")";
  return text;
}

}  // namespace cutcalc::service
