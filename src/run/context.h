// Context: the facts needed to interpret a timing — machine, build and library — gathered in one place (in the
// spirit of Google Benchmark's sysinfo.cc) and recorded in every result file, with warnings for conditions that
// make numbers unrepresentative (debug or sanitizer builds, frequency scaling, a loaded machine).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace tcsb {

/// One CPU cache as seen from cpu0 (/sys/devices/system/cpu/cpu0/cache/index*).
struct CacheInfo {
  int level = 0;     ///< 1, 2, 3, ...
  std::string type;  ///< "Data", "Instruction" or "Unified"
  std::int64_t size_bytes = 0;
  int num_sharing = 0;  ///< logical CPUs sharing this cache (0 if unknown)
};

/// Everything a result file records about where and how it was produced.
struct Context {
  std::string date_utc;           ///< ISO 8601 UTC, e.g. 2026-11-22T01:02:03Z
  std::string host;               ///< gethostname(), "unknown" if it fails
  std::string cpu_model;          ///< first /proc/cpuinfo "model name", "unknown" if absent
  int cores = 0;                  ///< std::thread::hardware_concurrency (0: unknown)
  double mhz = 0;                 ///< /proc/cpuinfo "cpu MHz" of cpu0, 0 if unknown
  std::vector<CacheInfo> caches;  ///< cpu0's caches in index order; empty if /sys does not say
  std::string cpu_governor;       ///< cpu0 scaling_governor, "" if absent (VMs, containers)
  double load_average_1m = 0;     ///< /proc/loadavg first field at gather time
  /// Transparent huge pages mode (the bracketed choice of /sys/kernel/mm/transparent_hugepage/enabled, e.g.
  /// "madvise"), "" if absent; and the GLIBC_TUNABLES environment variable, "" if unset. Operations on large nets
  /// run 10-17 % faster with glibc.malloc.hugetlb=1 (docs/methodology.md, "Huge pages"): numbers are only
  /// comparable with both known.
  std::string transparent_hugepages;
  std::string glibc_tunables;
  std::string compiler;               ///< compiler id and version, e.g. "GNU 12.2.0"
  std::string cxx_flags;              ///< the CXX flags of this build type
  std::string build_type;             ///< CMAKE_BUILD_TYPE
  bool optimized = false;             ///< see is_optimized_build()
  bool sanitized = false;             ///< cxx_flags contain -fsanitize
  std::string bullet_version;         ///< btGetVersion() as "major.minor", e.g. "3.24"
  std::string bullet_precision;       ///< "single" or "double" (sizeof(btScalar))
  std::string tcsb_version;           ///< project version
  std::string git_commit;             ///< HEAD at configure time, "-dirty" suffixed if modified
  std::vector<std::string> warnings;  ///< context_warnings() of the fields above
};

/// Reads the machine and the build now; fills `warnings` with context_warnings(). Never throws for a missing
/// /proc or /sys file: absent facts keep their "unknown" values.
Context gather_context();

/// Pure: the warnings implied by the fields (non-optimised build, sanitizer build, CPU frequency scaling,
/// loaded machine), each one short sentence without the "tcsb: warning: " prefix.
std::vector<std::string> context_warnings(const Context& context);

/// Writes each of context.warnings as "tcsb: warning: ...\n".
void print_warnings(const Context& context, std::ostream& out);

/// The context as JSON with every field present (keys sorted, so the order is stable); caches as a list of
/// {level, type, size_bytes, num_sharing}; non-finite doubles are written as 0, never NaN/null.
nlohmann::json to_json(const Context& context);

/// True for an optimised build: build type Release/RelWithDebInfo/MinSizeRel, NDEBUG defined, and the last -O
/// flag in `cxx_flags` one of -O/-O1/-O2/-O3/-Os/-Oz/-Ofast (the last one wins, as with the compiler).
bool is_optimized_build(std::string_view build_type, std::string_view cxx_flags, bool ndebug_defined);

/// Parsers for the /proc and /sys text formats, exposed so they can be tested on fixed inputs.
namespace context_detail {

/// "model name" and "cpu MHz" of the first processor block of /proc/cpuinfo text.
struct CpuInfo {
  std::string model = "unknown";
  double mhz = 0;
};
/// Parses /proc/cpuinfo text; fields absent from the first processor block keep their defaults.
CpuInfo parse_cpuinfo(std::string_view text);

/// Parses a sysfs cache size such as "48K", "2048K", "8M" or "1024" into bytes; nullopt if malformed.
std::optional<std::int64_t> parse_cache_size(std::string_view text);

/// Counts the CPUs in a sysfs cpu list such as "0-3,8,10-11" (-> 7); nullopt if malformed.
std::optional<int> count_cpu_list(std::string_view text);

/// Parses the first field of /proc/loadavg text; nullopt if malformed.
std::optional<double> parse_loadavg(std::string_view text);

/// The bracketed choice of a sysfs selector such as "always [madvise] never" (-> "madvise"); "" if none.
std::string bracketed_choice(std::string_view text);

/// Formats btGetVersion()-style numbers: 324 -> "3.24", 289 -> "2.89".
std::string bullet_version_string(int version);

}  // namespace context_detail
}  // namespace tcsb
