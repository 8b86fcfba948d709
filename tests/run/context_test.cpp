// Tests for the context block: warnings on hand-made contexts, the /proc and /sys parsers on fixed text, and
// gather_context()/to_json() on this machine.
#include "run/context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <sstream>

namespace tcsb {
namespace {

// A context that should raise no warning at all; each test perturbs one field.
Context clean_context() {
  Context c;
  c.cores = 4;
  c.build_type = "Release";
  c.cxx_flags = "-O3 -DNDEBUG";
  c.optimized = true;
  c.sanitized = false;
  c.cpu_governor = "";
  c.load_average_1m = 0.1;
  return c;
}

bool has_warning_containing(const std::vector<std::string>& warnings, const std::string& needle) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const std::string& w) { return w.find(needle) != std::string::npos; });
}

TEST(ContextWarnings, CleanContextHasNone) { EXPECT_TRUE(context_warnings(clean_context()).empty()); }

TEST(ContextWarnings, NonOptimisedBuild) {
  Context c = clean_context();
  c.build_type = "Debug";
  c.optimized = false;
  const auto warnings = context_warnings(c);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "timing a non-optimised build (build type Debug): numbers are not representative");
}

TEST(ContextWarnings, NonOptimisedReleaseNamesTheFlags) {
  Context c = clean_context();
  c.cxx_flags = "-O0";
  c.optimized = false;
  const auto warnings = context_warnings(c);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(has_warning_containing(warnings, "non-optimised build (build type Release, flags '-O0')"));
}

TEST(ContextWarnings, SanitizerBuild) {
  Context c = clean_context();
  c.sanitized = true;
  const auto warnings = context_warnings(c);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(has_warning_containing(warnings, "sanitizer"));
}

TEST(ContextWarnings, FrequencyScalingOnlyWhenGovernorIsNotPerformance) {
  Context c = clean_context();
  c.cpu_governor = "performance";
  EXPECT_TRUE(context_warnings(c).empty());
  c.cpu_governor = "powersave";
  const auto warnings = context_warnings(c);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "CPU frequency scaling is active (governor 'powersave'): expect extra variance");
}

TEST(ContextWarnings, LoadedMachineAboveHalfTheCores) {
  Context c = clean_context();
  c.cores = 2;
  c.load_average_1m = 1.0;  // exactly half: not loaded
  EXPECT_TRUE(context_warnings(c).empty());
  c.load_average_1m = 1.7;
  const auto warnings = context_warnings(c);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "machine is loaded (1-min load 1.7 on 2 cores): expect extra variance");
  c.cores = 0;  // unknown core count: no basis for the warning
  EXPECT_TRUE(context_warnings(c).empty());
}

TEST(ContextWarnings, AllAtOnceInOrder) {
  Context c = clean_context();
  c.build_type = "Debug";
  c.optimized = false;
  c.sanitized = true;
  c.cpu_governor = "ondemand";
  c.load_average_1m = 8;
  const auto warnings = context_warnings(c);
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_TRUE(warnings[0].starts_with("timing a non-optimised build"));
  EXPECT_TRUE(warnings[1].starts_with("timing a sanitizer build"));
  EXPECT_TRUE(warnings[2].starts_with("CPU frequency scaling"));
  EXPECT_TRUE(warnings[3].starts_with("machine is loaded"));
}

TEST(ContextWarnings, PrintWarningsPrefixesEachLine) {
  Context c;
  c.warnings = {"first", "second"};
  std::ostringstream out;
  print_warnings(c, out);
  EXPECT_EQ(out.str(), "tcsb: warning: first\ntcsb: warning: second\n");
}

TEST(ContextOptimized, BuildTypeNdebugAndLastOFlag) {
  EXPECT_TRUE(is_optimized_build("Release", "-O3 -DNDEBUG", true));
  EXPECT_TRUE(is_optimized_build("RelWithDebInfo", "-O2 -g -DNDEBUG", true));
  EXPECT_TRUE(is_optimized_build("MinSizeRel", "-Os -DNDEBUG", true));
  EXPECT_FALSE(is_optimized_build("Debug", "-O3 -DNDEBUG", true));
  EXPECT_FALSE(is_optimized_build("", "-O3", true));
  EXPECT_FALSE(is_optimized_build("Release", "-O3", false));
  EXPECT_FALSE(is_optimized_build("Release", "-DNDEBUG", true));
  EXPECT_FALSE(is_optimized_build("Release", "-O2 -O0", true));  // the last -O wins
  EXPECT_TRUE(is_optimized_build("Release", "-O0 -O2", true));
  EXPECT_FALSE(is_optimized_build("Release", "-Og", true));
}

TEST(ContextParsers, Cpuinfo) {
  const auto info =
      context_detail::parse_cpuinfo("processor\t: 0\nmodel name\t: Test CPU @ 3.00GHz\ncpu MHz\t\t: 2999.5\n\n"
                                    "processor\t: 1\nmodel name\t: Other\ncpu MHz\t\t: 800.0\n");
  EXPECT_EQ(info.model, "Test CPU @ 3.00GHz");
  EXPECT_DOUBLE_EQ(info.mhz, 2999.5);

  const auto arm = context_detail::parse_cpuinfo("processor\t: 0\nBogoMIPS\t: 50.00\n");
  EXPECT_EQ(arm.model, "unknown");
  EXPECT_EQ(arm.mhz, 0.0);
  // cpu1's MHz must not stand in for cpu0's.
  EXPECT_EQ(context_detail::parse_cpuinfo("processor : 0\n\nprocessor : 1\ncpu MHz : 800\n").mhz, 0.0);
}

TEST(ContextParsers, CacheSize) {
  EXPECT_EQ(context_detail::parse_cache_size("48K\n"), 48 * 1024);
  EXPECT_EQ(context_detail::parse_cache_size("8M"), 8 * 1024 * 1024);
  EXPECT_EQ(context_detail::parse_cache_size("1024"), 1024);
  EXPECT_EQ(context_detail::parse_cache_size("K"), std::nullopt);
  EXPECT_EQ(context_detail::parse_cache_size("x12K"), std::nullopt);
}

TEST(ContextParsers, CpuList) {
  EXPECT_EQ(context_detail::count_cpu_list("0\n"), 1);
  EXPECT_EQ(context_detail::count_cpu_list("0-1"), 2);
  EXPECT_EQ(context_detail::count_cpu_list("0-3,8,10-11"), 7);
  EXPECT_EQ(context_detail::count_cpu_list(""), std::nullopt);
  EXPECT_EQ(context_detail::count_cpu_list("3-1"), std::nullopt);
  EXPECT_EQ(context_detail::count_cpu_list("0,,1"), std::nullopt);
}

TEST(ContextParsers, LoadavgAndBulletVersion) {
  EXPECT_EQ(context_detail::parse_loadavg("1.73 0.50 0.20 1/82 3905\n"), 1.73);
  EXPECT_EQ(context_detail::parse_loadavg("garbage"), std::nullopt);
  EXPECT_EQ(context_detail::bullet_version_string(324), "3.24");
  EXPECT_EQ(context_detail::bullet_version_string(289), "2.89");
  EXPECT_EQ(context_detail::bullet_version_string(305), "3.05");
}

TEST(ContextParsers, BracketedChoice) {
  EXPECT_EQ(context_detail::bracketed_choice("always [madvise] never\n"), "madvise");
  EXPECT_EQ(context_detail::bracketed_choice("[always] madvise never"), "always");
  EXPECT_EQ(context_detail::bracketed_choice("always madvise never"), "");
  EXPECT_EQ(context_detail::bracketed_choice("always [madvise"), "");
}

TEST(ContextGather, ReadsThisMachine) {
  const Context c = gather_context();
  EXPECT_FALSE(c.host.empty());
  EXPECT_FALSE(c.cpu_model.empty());
  EXPECT_GE(c.cores, 1);
  EXPECT_TRUE(std::regex_match(c.date_utc, std::regex(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}Z)"))) << c.date_utc;
  EXPECT_EQ(c.bullet_precision, "single");
  EXPECT_EQ(c.bullet_version, "3.24");
  EXPECT_FALSE(c.compiler.empty());
  EXPECT_FALSE(c.tcsb_version.empty());
  EXPECT_FALSE(c.git_commit.empty());
  EXPECT_GE(c.mhz, 0.0);
  EXPECT_GE(c.load_average_1m, 0.0);
  for (const auto& cache : c.caches) {
    EXPECT_GE(cache.level, 1);
    EXPECT_FALSE(cache.type.empty());
    EXPECT_GE(cache.size_bytes, 0);
  }
  EXPECT_EQ(c.warnings, context_warnings(c));
}

TEST(ContextJson, HasEveryKeyWithItsTypeAndNoNaN) {
  Context c = gather_context();
  c.caches.push_back({1, "Data", 48 * 1024, 2});
  c.mhz = std::numeric_limits<double>::quiet_NaN();
  c.load_average_1m = std::numeric_limits<double>::infinity();
  const nlohmann::json j = to_json(c);
  ASSERT_TRUE(j.is_object());
  for (const char* key :
       {"date_utc", "host", "cpu_model", "cpu_governor", "compiler", "cxx_flags", "build_type", "bullet_version",
        "bullet_precision", "tcsb_version", "git_commit", "transparent_hugepages", "glibc_tunables"}) {
    ASSERT_TRUE(j.contains(key)) << key;
    EXPECT_TRUE(j[key].is_string()) << key;
  }
  for (const char* key : {"mhz", "load_average_1m"}) {
    ASSERT_TRUE(j.contains(key)) << key;
    ASSERT_TRUE(j[key].is_number()) << key;
    EXPECT_TRUE(std::isfinite(j[key].get<double>())) << key;
  }
  ASSERT_TRUE(j.contains("cores"));
  EXPECT_TRUE(j["cores"].is_number_integer());
  EXPECT_TRUE(j.at("optimized").is_boolean());
  EXPECT_TRUE(j.at("sanitized").is_boolean());
  ASSERT_TRUE(j.at("warnings").is_array());
  for (const auto& w : j["warnings"]) EXPECT_TRUE(w.is_string());
  ASSERT_TRUE(j.at("caches").is_array());
  ASSERT_EQ(j["caches"].size(), c.caches.size());
  const auto& last = j["caches"].back();
  EXPECT_EQ(last.at("level"), 1);
  EXPECT_EQ(last.at("type"), "Data");
  EXPECT_EQ(last.at("size_bytes"), 48 * 1024);
  EXPECT_EQ(last.at("num_sharing"), 2);
  EXPECT_EQ(j.size(), 20u);  // one key per Context field: a new field must be added here too
  // The dump round-trips and holds no null where a number was NaN.
  EXPECT_EQ(nlohmann::json::parse(j.dump()), j);
  EXPECT_EQ(j.dump().find("null"), std::string::npos);
}

}  // namespace
}  // namespace tcsb
