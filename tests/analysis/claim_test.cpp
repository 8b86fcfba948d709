#include "analysis/claim.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace tcsb {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool passes(Comparison c, double expected, double tolerance, std::optional<double> measured) {
  return check_claim("id", "desc", c, expected, tolerance, measured).pass;
}

TEST(Claim, AtMostBoundaries) {
  // Values chosen exactly representable so the boundary is the boundary.
  EXPECT_TRUE(passes(Comparison::kAtMost, 1.0, 0.5, 1.5));
  EXPECT_FALSE(passes(Comparison::kAtMost, 1.0, 0.5, 1.5000001));
  EXPECT_TRUE(passes(Comparison::kAtMost, 1.0, 0.5, -100.0));
  EXPECT_TRUE(passes(Comparison::kAtMost, 1.0, 0.0, 1.0));
  EXPECT_FALSE(passes(Comparison::kAtMost, 1.0, 0.0, 1.0000001));
}

TEST(Claim, AtLeastBoundaries) {
  EXPECT_TRUE(passes(Comparison::kAtLeast, 3.0, 0.25, 2.75));
  EXPECT_FALSE(passes(Comparison::kAtLeast, 3.0, 0.25, 2.7499999));
  EXPECT_TRUE(passes(Comparison::kAtLeast, 3.0, 0.25, 1e9));
  EXPECT_TRUE(passes(Comparison::kAtLeast, 3.0, 0.0, 3.0));
}

TEST(Claim, WithinBoundaries) {
  EXPECT_TRUE(passes(Comparison::kWithin, 2.0, 0.5, 1.5));
  EXPECT_TRUE(passes(Comparison::kWithin, 2.0, 0.5, 2.5));
  EXPECT_TRUE(passes(Comparison::kWithin, 2.0, 0.5, 2.0));
  EXPECT_FALSE(passes(Comparison::kWithin, 2.0, 0.5, 2.5000001));
  EXPECT_FALSE(passes(Comparison::kWithin, 2.0, 0.5, 1.4999999));
}

TEST(Claim, NotMeasuredFailsForEveryComparison) {
  for (const Comparison c : {Comparison::kAtMost, Comparison::kAtLeast, Comparison::kWithin}) {
    const Claim claim = check_claim("id", "desc", c, 1.0, 1e9, std::nullopt);
    EXPECT_FALSE(claim.pass) << comparison_name(c);
    EXPECT_FALSE(claim.measured.has_value());
  }
}

TEST(Claim, NonFiniteMeasuredFailsAndIsStoredAsNotMeasured) {
  for (const double bad : {kNaN, kInf, -kInf}) {
    // -inf would "pass" at_most and +inf at_least by plain comparison; a diverged run must never pass.
    for (const Comparison c : {Comparison::kAtMost, Comparison::kAtLeast, Comparison::kWithin}) {
      const Claim claim = check_claim("id", "desc", c, 1.0, 0.5, bad);
      EXPECT_FALSE(claim.pass) << comparison_name(c) << " " << bad;
      EXPECT_FALSE(claim.measured.has_value());
    }
  }
}

TEST(Claim, KeepsItsFields) {
  const Claim claim = check_claim("speedup_128", "TC-SB at least 3x faster", Comparison::kAtLeast, 3.0, 0.1, 3.4);
  EXPECT_EQ(claim.id, "speedup_128");
  EXPECT_EQ(claim.description, "TC-SB at least 3x faster");
  EXPECT_EQ(claim.comparison, Comparison::kAtLeast);
  EXPECT_DOUBLE_EQ(claim.expected, 3.0);
  EXPECT_DOUBLE_EQ(claim.tolerance, 0.1);
  ASSERT_TRUE(claim.measured.has_value());
  EXPECT_DOUBLE_EQ(*claim.measured, 3.4);
  EXPECT_TRUE(claim.pass);
}

TEST(Claim, RejectsBadDefinitions) {
  EXPECT_THROW(check_claim("id", "d", Comparison::kAtMost, 1.0, -0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(check_claim("id", "d", Comparison::kAtMost, kNaN, 0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(check_claim("id", "d", Comparison::kAtMost, 1.0, kInf, 1.0), std::invalid_argument);
}

TEST(Claim, AllPass) {
  const Claim good = check_claim("a", "", Comparison::kAtMost, 1.0, 0.0, 0.5);
  const Claim bad = check_claim("b", "", Comparison::kAtMost, 1.0, 0.0, 2.0);
  const Claim unmeasured = check_claim("c", "", Comparison::kAtMost, 1.0, 0.0, std::nullopt);
  EXPECT_TRUE(all_pass({}));
  EXPECT_TRUE(all_pass(std::vector<Claim>{good, good}));
  EXPECT_FALSE(all_pass(std::vector<Claim>{good, bad}));
  EXPECT_FALSE(all_pass(std::vector<Claim>{good, unmeasured}));
}

Claim with_interval(Comparison c, double expected, double tolerance, double measured, double low, double high) {
  Claim claim = check_claim("id", "desc", c, expected, tolerance, measured);
  claim.interval = Interval{low, high};
  return claim;
}

TEST(Claim, DecidedWhenTheWholeIntervalGivesTheVerdict) {
  // at_most 0.2: 0.15 passes; decided only if the interval stays at or below 0.2.
  EXPECT_EQ(decided(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.15, 0.10, 0.19)), true);
  EXPECT_EQ(decided(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.15, 0.10, 0.25)), false);
  EXPECT_EQ(decided(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.30, 0.21, 0.40)), true);   // a decided FAIL
  EXPECT_EQ(decided(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.30, 0.19, 0.40)), false);
  EXPECT_EQ(decided(with_interval(Comparison::kAtLeast, 0.98, 0.0, 0.99, 0.985, 0.995)), true);
  EXPECT_EQ(decided(with_interval(Comparison::kAtLeast, 0.98, 0.0, 0.95, 0.93, 0.99)), false);
  // within 2 +- 0.5: an interval across the whole band fails at both ends but is not a decided FAIL.
  EXPECT_EQ(decided(with_interval(Comparison::kWithin, 2.0, 0.5, 2.2, 1.9, 2.4)), true);
  EXPECT_EQ(decided(with_interval(Comparison::kWithin, 2.0, 0.5, 3.0, 2.6, 3.5)), true);
  EXPECT_EQ(decided(with_interval(Comparison::kWithin, 2.0, 0.5, 3.0, 1.0, 3.5)), false);
}

TEST(Claim, NotDecidableWithoutIntervalOrMeasurement) {
  EXPECT_EQ(decided(check_claim("id", "desc", Comparison::kAtMost, 1.0, 0.0, 0.5)), std::nullopt);
  Claim unmeasured = check_claim("id", "desc", Comparison::kAtMost, 1.0, 0.0, std::nullopt);
  unmeasured.interval = Interval{0.1, 0.2};
  EXPECT_EQ(decided(unmeasured), std::nullopt);
}

TEST(Claim, ComparisonNames) {
  EXPECT_STREQ(comparison_name(Comparison::kAtMost), "at_most");
  EXPECT_STREQ(comparison_name(Comparison::kAtLeast), "at_least");
  EXPECT_STREQ(comparison_name(Comparison::kWithin), "within");
}

}  // namespace
}  // namespace tcsb
