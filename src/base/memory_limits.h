// How much more memory this process may take: the smallest headroom among the machine (MemAvailable), the control
// groups it runs in (cgroup v2 memory.max, v1 memory.limit_in_bytes, at every level up to the root) and its own
// resource limits (ulimit -v: RLIMIT_AS, RLIMIT_DATA). A suite checked against MemAvailable alone passes inside a
// 1 GiB container on a 64 GiB host and is then killed, or crashes in Bullet's allocator, mid-run.
//
// The parsers take file contents as text, so they are tested without a real cgroup or limit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tcsb {

/// One limit on this process's memory and how much of it is still free.
struct MemoryHeadroom {
  std::string source;       ///< what limits it, for messages: "MemAvailable", "cgroup memory.max", "ulimit -v"
  std::uint64_t bytes = 0;  ///< how much more may be allocated under it
};

/// MemAvailable of /proc/meminfo text, in bytes.
std::optional<std::uint64_t> parse_mem_available(std::string_view meminfo);

/// A "Key:   123 kB" field of /proc/self/status text (e.g. "VmSize"), in bytes.
std::optional<std::uint64_t> parse_status_bytes(std::string_view status, std::string_view key);

/// The cgroup v2 path ("0::/a/b" -> "/a/b") of /proc/self/cgroup text.
std::optional<std::string> cgroup_v2_path(std::string_view proc_self_cgroup);

/// The cgroup v1 path of the memory controller ("4:memory:/a" or "4:cpu,memory:/a" -> "/a").
std::optional<std::string> cgroup_v1_memory_path(std::string_view proc_self_cgroup);

/// A limit file's value (memory.max, memory.limit_in_bytes): nothing for "max" or a v1 "no limit" (at least 2^62,
/// v1 writes PAGE_COUNTER_MAX pages as 9223372036854771712), or text that is not a number.
std::optional<std::uint64_t> parse_cgroup_limit(std::string_view text);

/// The smallest limit - usage over the cgroup directory `mount`/`path` and each level above it up to `mount`: a
/// limit set on a parent (a container's) binds its children too. Levels without both files (not visible from here,
/// or no limit: "max") are skipped; nothing when no level has a limit.
std::optional<std::uint64_t> cgroup_headroom(const std::filesystem::path& mount, std::string_view path,
                                             const char* limit_file, const char* usage_file);

/// limit - used, 0 when used is at or over the limit.
std::uint64_t headroom(std::uint64_t limit, std::uint64_t used);

/// The smallest of `limits`; nothing when there is none.
std::optional<MemoryHeadroom> smallest_headroom(const std::vector<MemoryHeadroom>& limits);

/// Every limit this process runs under that the system tells: MemAvailable, the cgroup levels, RLIMIT_AS against
/// VmSize and RLIMIT_DATA against VmData. Unreadable or unlimited ones are left out.
std::vector<MemoryHeadroom> memory_headrooms();

}  // namespace tcsb
