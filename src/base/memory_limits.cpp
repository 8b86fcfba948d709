#include "base/memory_limits.h"

#include <sys/resource.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace tcsb {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The lines of `text`, one at a time.
template <typename F>
void for_each_line(std::string_view text, F&& f) {
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    f(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::optional<std::uint64_t> whole_number(std::string_view s) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return value;
}

/// "Key: 123 kB" lines (meminfo, status): the number of kB, in bytes.
std::optional<std::uint64_t> kib_field(std::string_view text, std::string_view key) {
  std::optional<std::uint64_t> found;
  for_each_line(text, [&](std::string_view line) {
    if (found || line.size() <= key.size() || line.substr(0, key.size()) != key || line[key.size()] != ':') return;
    std::string_view rest = trimmed(line.substr(key.size() + 1));
    if (rest.size() < 3 || rest.substr(rest.size() - 3) != " kB") return;
    if (const auto kib = whole_number(trimmed(rest.substr(0, rest.size() - 3)))) found = *kib * 1024;
  });
  return found;
}

/// The path of the /proc/self/cgroup line whose controller list satisfies `wanted`.
template <typename F>
std::optional<std::string> cgroup_path(std::string_view text, F&& wanted) {
  std::optional<std::string> found;
  for_each_line(text, [&](std::string_view line) {
    const std::size_t first = line.find(':');
    const std::size_t second = first == std::string_view::npos ? first : line.find(':', first + 1);
    if (found || second == std::string_view::npos) return;
    if (wanted(line.substr(first + 1, second - first - 1))) found = std::string(line.substr(second + 1));
  });
  return found;
}

/// RLIMIT_AS / RLIMIT_DATA against what this process already has of it (VmSize / VmData).
std::optional<std::uint64_t> rlimit_headroom(int resource, std::string_view status, std::string_view used_key) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  const std::optional<std::uint64_t> used = parse_status_bytes(status, used_key);
  return headroom(static_cast<std::uint64_t>(limit.rlim_cur), used.value_or(0));
}

}  // namespace

std::optional<std::uint64_t> cgroup_headroom(const std::filesystem::path& mount, std::string_view path,
                                             const char* limit_file, const char* usage_file) {
  std::optional<std::uint64_t> smallest;
  std::filesystem::path dir = mount;
  while (true) {
    const std::optional<std::uint64_t> limit = parse_cgroup_limit(read_text(dir / limit_file));
    const std::optional<std::uint64_t> used = whole_number(trimmed(read_text(dir / usage_file)));
    if (limit && used) smallest = std::min(smallest.value_or(UINT64_MAX), headroom(*limit, *used));
    while (!path.empty() && path.front() == '/') path.remove_prefix(1);
    if (path.empty()) break;
    const std::size_t slash = path.find('/');
    const std::string_view part = path.substr(0, slash);
    if (part == "..") break;  // never climb out of the mount
    dir /= std::string(part);
    path.remove_prefix(part.size());
  }
  return smallest;
}

std::optional<std::uint64_t> parse_mem_available(std::string_view meminfo) {
  return kib_field(meminfo, "MemAvailable");
}

std::optional<std::uint64_t> parse_status_bytes(std::string_view status, std::string_view key) {
  return kib_field(status, key);
}

std::optional<std::string> cgroup_v2_path(std::string_view proc_self_cgroup) {
  // The v2 line is "0::PATH": hierarchy 0, no controller list.
  std::optional<std::string> found;
  for_each_line(proc_self_cgroup, [&](std::string_view line) {
    if (!found && line.substr(0, 3) == "0::") found = std::string(line.substr(3));
  });
  return found;
}

std::optional<std::string> cgroup_v1_memory_path(std::string_view proc_self_cgroup) {
  return cgroup_path(proc_self_cgroup, [](std::string_view controllers) {
    for (;;) {
      const std::size_t comma = controllers.find(',');
      if (controllers.substr(0, comma) == "memory") return true;
      if (comma == std::string_view::npos) return false;
      controllers.remove_prefix(comma + 1);
    }
  });
}

std::optional<std::uint64_t> parse_cgroup_limit(std::string_view text) {
  const std::optional<std::uint64_t> limit = whole_number(trimmed(text));
  if (!limit || *limit >= (std::uint64_t{1} << 62)) return std::nullopt;
  return limit;
}

std::uint64_t headroom(std::uint64_t limit, std::uint64_t used) { return used >= limit ? 0 : limit - used; }

std::optional<MemoryHeadroom> smallest_headroom(const std::vector<MemoryHeadroom>& limits) {
  if (limits.empty()) return std::nullopt;
  return *std::min_element(limits.begin(), limits.end(),
                           [](const MemoryHeadroom& a, const MemoryHeadroom& b) { return a.bytes < b.bytes; });
}

std::vector<MemoryHeadroom> memory_headrooms() {
  std::vector<MemoryHeadroom> limits;
  if (const auto available = parse_mem_available(read_text("/proc/meminfo")))
    limits.push_back({"MemAvailable", *available});
  const std::string cgroups = read_text("/proc/self/cgroup");
  if (const auto path = cgroup_v2_path(cgroups)) {
    if (const auto h = cgroup_headroom("/sys/fs/cgroup", *path, "memory.max", "memory.current"))
      limits.push_back({"cgroup memory.max", *h});
  }
  if (const auto path = cgroup_v1_memory_path(cgroups)) {
    const auto h = cgroup_headroom("/sys/fs/cgroup/memory", *path, "memory.limit_in_bytes", "memory.usage_in_bytes");
    if (h) limits.push_back({"cgroup memory.limit_in_bytes", *h});
  }
  const std::string status = read_text("/proc/self/status");
  if (const auto h = rlimit_headroom(RLIMIT_AS, status, "VmSize")) limits.push_back({"ulimit -v (RLIMIT_AS)", *h});
  if (const auto h = rlimit_headroom(RLIMIT_DATA, status, "VmData")) limits.push_back({"ulimit -d (RLIMIT_DATA)", *h});
  return limits;
}

}  // namespace tcsb
