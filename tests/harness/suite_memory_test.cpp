#include "harness/suite_memory.h"

#include <gtest/gtest.h>

#include <fstream>

namespace tcsb {
namespace {

TEST(SuiteMemory, EstimateGrowsWithNetsAndMethods) {
  Suite s;
  s.methods = {Method::kPlain};
  NetSpec small;
  small.width = small.height = 33;
  NetSpec big = small;
  big.width = big.height = 257;
  s.nets = {small};
  const std::uint64_t plain_small = estimate_peak_bytes(s);
  s.nets = {small, big};
  const std::uint64_t plain_big = estimate_peak_bytes(s);
  EXPECT_GT(plain_big, 50 * plain_small);  // ~ 60x the nodes
  s.methods = {Method::kPlain, Method::kTcsb};
  s.compression = {1.0};
  EXPECT_GT(estimate_peak_bytes(s), 2 * plain_big);  // TC-SB reserves the whole hierarchy
  // Node bytes alone are a floor: 257^2 Bullet nodes of 256 B.
  EXPECT_GT(plain_big, 257ull * 257ull * 256ull);
}

TEST(SuiteMemory, ShortfallNamesTheLargestNet) {
  if (!std::ifstream("/proc/meminfo").good()) GTEST_SKIP() << "/proc/meminfo unreadable: no estimate by design";
  Suite s;
  s.methods = {Method::kPlain};
  NetSpec small;
  small.width = small.height = 33;
  s.nets = {small};
  EXPECT_FALSE(memory_shortfall(s).has_value());
  NetSpec huge = small;
  huge.width = huge.height = 1 << 17;  // 2^34 nodes: terabytes on any machine this runs on
  s.nets = {small, huge, small};
  const std::optional<MemoryShortfall> shortfall = memory_shortfall(s);
  ASSERT_TRUE(shortfall.has_value());
  EXPECT_EQ(shortfall->net, 1u);
  EXPECT_GT(shortfall->needed, shortfall->usable);
  EXPECT_DOUBLE_EQ(shortfall->usable, 0.8 * shortfall->available);
}

TEST(SuiteMemory, FormatBytes) {
  EXPECT_EQ(format_bytes(0), "0.0 MiB");
  EXPECT_EQ(format_bytes(1.5 * 1024 * 1024), "1.5 MiB");
  EXPECT_EQ(format_bytes(1024.0 * 1024 * 1024), "1.0 GiB");
  EXPECT_EQ(format_bytes(2.5 * 1024 * 1024 * 1024), "2.5 GiB");
}

}  // namespace
}  // namespace tcsb
