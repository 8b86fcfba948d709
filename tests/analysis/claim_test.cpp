#include "analysis/claim.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "non_finite.h"

namespace tcsb {
namespace {

using testing::kInf;
using testing::kNaN;

/// A deterministic claim is decided on its value.
bool passes(Comparison c, double expected, double tolerance, std::optional<double> measured) {
  return passed(check_claim("id", "desc", c, expected, tolerance, measured));
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
    for (const Evidence e : {Evidence::kDeterministic, Evidence::kRepeated}) {
      Claim claim = check_claim("id", "desc", c, 1.0, 1e9, std::nullopt, e);
      claim.interval = Interval{0.9, 1.1};  // an interval cannot rescue a claim that was never measured
      EXPECT_EQ(verdict(claim), Verdict::kFail) << comparison_name(c) << " " << evidence_name(e);
      EXPECT_FALSE(claim.measured.has_value());
    }
  }
}

TEST(Claim, NonFiniteMeasuredFailsAndIsStoredAsNotMeasured) {
  for (const double bad : {kNaN, kInf, -kInf}) {
    // -inf would "pass" at_most and +inf at_least by plain comparison; a diverged run must never pass.
    for (const Comparison c : {Comparison::kAtMost, Comparison::kAtLeast, Comparison::kWithin}) {
      const Claim claim = check_claim("id", "desc", c, 1.0, 0.5, bad);
      EXPECT_EQ(verdict(claim), Verdict::kFail) << comparison_name(c) << " " << bad;
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
  EXPECT_EQ(claim.evidence, Evidence::kDeterministic);
  EXPECT_TRUE(passed(claim));
}

TEST(Claim, RejectsBadDefinitions) {
  EXPECT_THROW(check_claim("id", "d", Comparison::kAtMost, 1.0, -0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(check_claim("id", "d", Comparison::kAtMost, kNaN, 0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(check_claim("id", "d", Comparison::kAtMost, 1.0, kInf, 1.0), std::invalid_argument);
}

TEST(Claim, OverallVerdictFailBeatsUndecidedBeatsPass) {
  const Claim good = check_claim("a", "", Comparison::kAtMost, 1.0, 0.0, 0.5);
  const Claim bad = check_claim("b", "", Comparison::kAtMost, 1.0, 0.0, 2.0);
  const Claim unmeasured = check_claim("c", "", Comparison::kAtMost, 1.0, 0.0, std::nullopt);
  const Claim open = check_claim("d", "", Comparison::kAtMost, 1.0, 0.0, 0.5, Evidence::kRepeated);  // no interval
  EXPECT_EQ(overall_verdict({}), Verdict::kPass);
  EXPECT_EQ(overall_verdict(std::vector<Claim>{good, good}), Verdict::kPass);
  EXPECT_EQ(overall_verdict(std::vector<Claim>{good, bad}), Verdict::kFail);
  EXPECT_EQ(overall_verdict(std::vector<Claim>{good, unmeasured}), Verdict::kFail);
  EXPECT_EQ(overall_verdict(std::vector<Claim>{good, open}), Verdict::kUndecided);
  EXPECT_EQ(overall_verdict(std::vector<Claim>{open, bad, good}), Verdict::kFail);
}

/// A claim measured from repetitions, with the given value and interval.
Claim with_interval(Comparison c, double expected, double tolerance, double measured, double low, double high) {
  Claim claim = check_claim("id", "desc", c, expected, tolerance, measured, Evidence::kRepeated);
  claim.interval = Interval{low, high};
  return claim;
}

TEST(Claim, RepeatedClaimsAreJudgedOnTheWholeInterval) {
  // at_most 0.2: pass only if the whole interval is at or below 0.2, fail only if all of it is above.
  EXPECT_EQ(verdict(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.15, 0.10, 0.19)), Verdict::kPass);
  EXPECT_EQ(verdict(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.15, 0.10, 0.20)), Verdict::kPass);  // closed
  EXPECT_EQ(verdict(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.15, 0.10, 0.25)), Verdict::kUndecided);
  EXPECT_EQ(verdict(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.30, 0.21, 0.40)), Verdict::kFail);
  EXPECT_EQ(verdict(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.30, 0.19, 0.40)), Verdict::kUndecided);
  EXPECT_EQ(verdict(with_interval(Comparison::kAtLeast, 0.98, 0.0, 0.99, 0.985, 0.995)), Verdict::kPass);
  EXPECT_EQ(verdict(with_interval(Comparison::kAtLeast, 0.98, 0.0, 0.95, 0.93, 0.99)), Verdict::kUndecided);
  EXPECT_EQ(verdict(with_interval(Comparison::kAtLeast, 0.98, 0.0, 0.95, 0.93, 0.97)), Verdict::kFail);
}

TEST(Claim, WithinIsAnEquivalenceTest) {
  // within 1 +- 0.03: pass only inside the band; fail only wholly outside, on either side; an interval across the
  // band, or across one edge, is undecided (the old two-valued check called [0.96, 1.04] a failure beyond noise).
  EXPECT_EQ(verdict(with_interval(Comparison::kWithin, 1.0, 0.03, 1.0, 0.98, 1.02)), Verdict::kPass);
  EXPECT_EQ(verdict(with_interval(Comparison::kWithin, 1.0, 0.03, 1.06, 1.04, 1.08)), Verdict::kFail);
  EXPECT_EQ(verdict(with_interval(Comparison::kWithin, 1.0, 0.03, 0.94, 0.92, 0.96)), Verdict::kFail);
  EXPECT_EQ(verdict(with_interval(Comparison::kWithin, 1.0, 0.03, 1.0, 0.96, 1.04)), Verdict::kUndecided);
  EXPECT_EQ(verdict(with_interval(Comparison::kWithin, 1.0, 0.03, 1.02, 0.99, 1.05)), Verdict::kUndecided);
}

TEST(Claim, ThePointEstimateNeverDecidesARepeatedClaim) {
  // Measured 0.15 satisfies at_most 0.2, but an interval wholly above says the run measured a failure.
  EXPECT_EQ(verdict(with_interval(Comparison::kAtMost, 0.2, 0.0, 0.15, 0.21, 0.3)), Verdict::kFail);
  // Without an interval (too few repetitions) a repeated claim is undecided, however clear its value looks.
  EXPECT_EQ(verdict(check_claim("id", "", Comparison::kAtMost, 1.0, 0.0, 0.01, Evidence::kRepeated)),
            Verdict::kUndecided);
  // A deterministic claim ignores any interval: its value is exact.
  Claim exact = check_claim("id", "", Comparison::kAtMost, 1.0, 0.0, 0.5);
  exact.interval = Interval{0.5, 3.0};
  EXPECT_EQ(verdict(exact), Verdict::kPass);
}

TEST(Claim, ComparisonNames) {
  EXPECT_STREQ(comparison_name(Comparison::kAtMost), "at_most");
  EXPECT_STREQ(comparison_name(Comparison::kAtLeast), "at_least");
  EXPECT_STREQ(comparison_name(Comparison::kWithin), "within");
  EXPECT_STREQ(verdict_name(Verdict::kPass), "pass");
  EXPECT_STREQ(verdict_name(Verdict::kFail), "fail");
  EXPECT_STREQ(verdict_name(Verdict::kUndecided), "undecided");
  EXPECT_STREQ(evidence_name(Evidence::kRepeated), "repeated");
}

}  // namespace
}  // namespace tcsb
