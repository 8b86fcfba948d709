// Context gathering: every reader tolerates a missing file, because containers and VMs routinely hide parts of
// /proc and /sys, and a result file without a cache list is still worth more than no result file.
#include "run/context.h"

#include <unistd.h>

#include <LinearMath/btScalar.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <locale>
#include <ostream>
#include <sstream>
#include <thread>

#include "build_info.h"

namespace tcsb {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// from_chars rather than stod: no locale (a German LC_NUMERIC would misread "2000.000"), no exceptions.
template <typename T>
std::optional<T> parse_number(std::string_view s) {
  s = trim(s);
  T value{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  return value;
}

// /proc files report size 0, so read by iterating rather than by seeking to the end.
std::optional<std::string> read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Formats a double with the classic locale, so warnings read the same whatever the user's locale.
std::string format_number(double value) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << value;
  return out.str();
}

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

std::string host_name() {
  char buffer[256] = {};
  if (gethostname(buffer, sizeof buffer - 1) != 0 || buffer[0] == '\0') return "unknown";
  return buffer;
}

std::vector<CacheInfo> read_caches() {
  std::vector<CacheInfo> caches;
  const std::filesystem::path base = "/sys/devices/system/cpu/cpu0/cache";
  // index0, index1, ... are contiguous; stop at the first gap.
  for (int i = 0;; ++i) {
    const auto dir = base / ("index" + std::to_string(i));
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) break;
    const auto level = read_text(dir / "level");
    const auto type = read_text(dir / "type");
    if (!level || !type) continue;
    CacheInfo cache;
    cache.level = parse_number<int>(*level).value_or(0);
    cache.type = std::string(trim(*type));
    if (const auto size = read_text(dir / "size")) {
      cache.size_bytes = context_detail::parse_cache_size(*size).value_or(0);
    }
    if (const auto shared = read_text(dir / "shared_cpu_list")) {
      cache.num_sharing = context_detail::count_cpu_list(*shared).value_or(0);
    }
    caches.push_back(std::move(cache));
  }
  return caches;
}

double finite_or_zero(double value) { return std::isfinite(value) ? value : 0.0; }

}  // namespace

namespace context_detail {

CpuInfo parse_cpuinfo(std::string_view text) {
  CpuInfo info;
  bool seen_model = false, seen_mhz = false, in_block = false;
  while (!text.empty()) {
    const auto eol = text.find('\n');
    const std::string_view line = text.substr(0, eol);
    text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
    // A blank line ends a processor block: only cpu0's values are wanted.
    if (trim(line).empty()) {
      if (in_block) break;
      continue;
    }
    in_block = true;
    const auto colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    const auto key = trim(line.substr(0, colon));
    const auto value = trim(line.substr(colon + 1));
    if (key == "model name" && !seen_model && !value.empty()) {
      info.model = std::string(value);
      seen_model = true;
    } else if (key == "cpu MHz" && !seen_mhz) {
      if (const auto mhz = parse_number<double>(value); mhz && std::isfinite(*mhz) && *mhz > 0) info.mhz = *mhz;
      seen_mhz = true;
    }
  }
  return info;
}

std::optional<std::int64_t> parse_cache_size(std::string_view text) {
  text = trim(text);
  std::int64_t multiplier = 1;
  if (!text.empty()) {
    switch (std::toupper(static_cast<unsigned char>(text.back()))) {
      case 'K': multiplier = std::int64_t{1} << 10; break;
      case 'M': multiplier = std::int64_t{1} << 20; break;
      case 'G': multiplier = std::int64_t{1} << 30; break;
      default: break;
    }
    if (multiplier != 1) text.remove_suffix(1);
  }
  if (text.empty()) return std::nullopt;
  const auto value = parse_number<std::int64_t>(text);
  if (!value || *value < 0) return std::nullopt;
  return *value * multiplier;
}

std::optional<int> count_cpu_list(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  int count = 0;
  while (true) {
    const auto comma = text.find(',');
    const auto range = text.substr(0, comma);
    const auto dash = range.find('-');
    const auto lo = parse_number<int>(range.substr(0, dash));
    const auto hi = dash == std::string_view::npos ? lo : parse_number<int>(range.substr(dash + 1));
    if (!lo || !hi || *lo < 0 || *hi < *lo) return std::nullopt;
    count += *hi - *lo + 1;
    if (comma == std::string_view::npos) break;
    text = text.substr(comma + 1);
  }
  return count;
}

std::optional<double> parse_loadavg(std::string_view text) {
  text = trim(text);
  const auto value = parse_number<double>(text.substr(0, text.find_first_of(" \t")));
  if (!value || !std::isfinite(*value) || *value < 0) return std::nullopt;
  return value;
}

std::string bracketed_choice(std::string_view text) {
  const auto open = text.find('[');
  const auto close = text.find(']', open == std::string_view::npos ? 0 : open);
  if (open == std::string_view::npos || close == std::string_view::npos) return "";
  return std::string(text.substr(open + 1, close - open - 1));
}

std::string bullet_version_string(int version) {
  const int minor = version % 100;
  return std::to_string(version / 100) + (minor < 10 ? ".0" : ".") + std::to_string(minor);
}

}  // namespace context_detail

bool is_optimized_build(std::string_view build_type, std::string_view cxx_flags, bool ndebug_defined) {
  const bool optimising_type =
      iequals(build_type, "Release") || iequals(build_type, "RelWithDebInfo") || iequals(build_type, "MinSizeRel");
  if (!optimising_type || !ndebug_defined) return false;
  // The compiler honours the last -O flag, so "-O2 -O0" is not optimised.
  static const char* const kOptimising[] = {"-O", "-O1", "-O2", "-O3", "-Os", "-Oz", "-Ofast"};
  bool optimising_flag = false;
  std::istringstream tokens{std::string(cxx_flags)};
  for (std::string token; tokens >> token;) {
    if (!token.starts_with("-O")) continue;
    optimising_flag =
        std::any_of(std::begin(kOptimising), std::end(kOptimising), [&](const char* o) { return token == o; });
  }
  return optimising_flag;
}

std::vector<std::string> context_warnings(const Context& c) {
  std::vector<std::string> warnings;
  if (!c.optimized) {
    const std::string type = c.build_type.empty() ? "none" : c.build_type;
    const bool type_ok = iequals(type, "Release") || iequals(type, "RelWithDebInfo") || iequals(type, "MinSizeRel");
    // When the type looks right the flags are the culprit (e.g. -O0 or no NDEBUG): say so.
    warnings.push_back("timing a non-optimised build (build type " + type +
                       (type_ok ? ", flags '" + c.cxx_flags + "'" : std::string{}) +
                       "): numbers are not representative");
  }
  if (c.sanitized) {
    warnings.push_back("timing a sanitizer build (-fsanitize): numbers are not representative");
  }
  if (!c.cpu_governor.empty() && c.cpu_governor != "performance") {
    warnings.push_back("CPU frequency scaling is active (governor '" + c.cpu_governor + "'): expect extra variance");
  }
  // cores == 0 means unknown: no basis for calling the machine loaded.
  if (c.cores > 0 && c.load_average_1m > 0.5 * c.cores) {
    warnings.push_back("machine is loaded (1-min load " + format_number(c.load_average_1m) + " on " +
                       std::to_string(c.cores) + (c.cores == 1 ? " core" : " cores") + "): expect extra variance");
  }
  return warnings;
}

Context gather_context() {
  Context c;
  c.date_utc = utc_now_iso8601();
  c.host = host_name();
  c.cores = static_cast<int>(std::thread::hardware_concurrency());

  const auto cpuinfo = context_detail::parse_cpuinfo(read_text("/proc/cpuinfo").value_or(""));
  c.cpu_model = cpuinfo.model;
  c.mhz = cpuinfo.mhz;
  c.caches = read_caches();
  if (const auto governor = read_text("/sys/devices/system/cpu/cpu0/cpufreq/scaling_governor")) {
    c.cpu_governor = std::string(trim(*governor));
  }
  if (const auto loadavg = read_text("/proc/loadavg")) {
    c.load_average_1m = context_detail::parse_loadavg(*loadavg).value_or(0.0);
  }
  if (const auto thp = read_text("/sys/kernel/mm/transparent_hugepage/enabled")) {
    c.transparent_hugepages = context_detail::bracketed_choice(*thp);
  }
  if (const char* tunables = std::getenv("GLIBC_TUNABLES")) c.glibc_tunables = tunables;

  c.compiler = std::string(trim(std::string(build_info::kCompilerId) + " " + build_info::kCompilerVersion));
  c.cxx_flags = build_info::kCxxFlags;
  c.build_type = build_info::kBuildType;
#ifdef NDEBUG
  constexpr bool kNdebug = true;
#else
  constexpr bool kNdebug = false;
#endif
  c.optimized = is_optimized_build(c.build_type, c.cxx_flags, kNdebug);
  c.sanitized = c.cxx_flags.find("-fsanitize") != std::string::npos;

  c.bullet_version = context_detail::bullet_version_string(btGetVersion());
  c.bullet_precision = sizeof(btScalar) == 4 ? "single" : "double";
  c.tcsb_version = build_info::kVersion;
  c.git_commit = build_info::kGitCommit;
  c.warnings = context_warnings(c);
  return c;
}

void print_warnings(const Context& context, std::ostream& out) {
  for (const auto& warning : context.warnings) out << "tcsb: warning: " << warning << '\n';
}

nlohmann::json to_json(const Context& c) {
  nlohmann::json caches = nlohmann::json::array();
  for (const auto& cache : c.caches) {
    caches.push_back({{"level", cache.level},
                      {"type", cache.type},
                      {"size_bytes", cache.size_bytes},
                      {"num_sharing", cache.num_sharing}});
  }
  return {
      {"date_utc", c.date_utc},
      {"host", c.host},
      {"cpu_model", c.cpu_model},
      {"cores", c.cores},
      {"mhz", finite_or_zero(c.mhz)},
      {"caches", std::move(caches)},
      {"cpu_governor", c.cpu_governor},
      {"load_average_1m", finite_or_zero(c.load_average_1m)},
      {"transparent_hugepages", c.transparent_hugepages},
      {"glibc_tunables", c.glibc_tunables},
      {"compiler", c.compiler},
      {"cxx_flags", c.cxx_flags},
      {"build_type", c.build_type},
      {"optimized", c.optimized},
      {"sanitized", c.sanitized},
      {"bullet_version", c.bullet_version},
      {"bullet_precision", c.bullet_precision},
      {"tcsb_version", c.tcsb_version},
      {"git_commit", c.git_commit},
      {"warnings", c.warnings},
  };
}

}  // namespace tcsb
