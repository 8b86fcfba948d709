// The gate's decision rule: a bootstrap interval of the change against the threshold as margin (regressed, no
// regression, undecided), Bonferroni over the family, too few samples never decide. The reported p-values are
// cross-checked with scipy.stats.mannwhitneyu (method='exact').
#include "analysis/regression_gate.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace tcsb {
namespace {

const std::vector<double> kBase = {1.00, 1.02, 1.04, 1.06, 1.08, 1.10, 1.12, 1.14, 1.16};
// Overlaps kBase a little: scipy's one-sided exact p = 0.002817770464829288, median +8.33 %.
const std::vector<double> kShifted = {1.09, 1.11, 1.13, 1.15, 1.17, 1.19, 1.21, 1.23, 1.25};

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out;
  for (const double x : v) out.push_back(x * factor);
  return out;
}

TimingDecision decide_one(const TimingSamples& s, GateSettings settings = {}) {
  const std::vector<TimingSamples> family = {s};
  return decide_timings(family, settings).at(0);
}

TEST(HolmAdjust, MatchesTheStepDownFormula) {
  // Sorted: 0.005*4 = 0.02, 0.01*3 = 0.03, 0.03*2 = 0.06, 0.04*1 = 0.04 -> made monotone 0.06.
  const std::vector<double> adjusted = holm_adjust(std::vector<double>{0.01, 0.04, 0.03, 0.005});
  ASSERT_EQ(adjusted.size(), 4u);
  EXPECT_DOUBLE_EQ(adjusted[0], 0.03);
  EXPECT_DOUBLE_EQ(adjusted[1], 0.06);
  EXPECT_DOUBLE_EQ(adjusted[2], 0.06);
  EXPECT_DOUBLE_EQ(adjusted[3], 0.02);
}

TEST(HolmAdjust, CapsAtOneAndHandlesEmpty) {
  EXPECT_TRUE(holm_adjust(std::vector<double>{}).empty());
  const std::vector<double> adjusted = holm_adjust(std::vector<double>{0.6, 0.7});
  EXPECT_DOUBLE_EQ(adjusted[0], 1.0);
  EXPECT_DOUBLE_EQ(adjusted[1], 1.0);
  EXPECT_THROW(holm_adjust(std::vector<double>{1.5}), std::invalid_argument);
  EXPECT_THROW(holm_adjust(std::vector<double>{std::numeric_limits<double>::quiet_NaN()}), std::invalid_argument);
}

/// `n` values from `from` in steps of `step`: a tight sample whose median is from + 4 step (n = 9).
std::vector<double> ramp(double from, double step, int n = 9) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(from + step * i);
  return out;
}

TEST(RegressionGate, IntervalAboveTheThresholdRegresses) {
  // +10 % with a spread of under 1 %: the whole interval lies above the 5 % margin.
  const TimingDecision d = decide_one({ramp(1.0, 0.001), ramp(1.1, 0.001)});
  EXPECT_EQ(d.verdict, TimingVerdict::kRegressed);
  ASSERT_TRUE(d.change.has_value());
  EXPECT_NEAR(*d.change, 1.104 / 1.004 - 1.0, 1e-12);
  ASSERT_TRUE(d.interval.has_value());
  EXPECT_GT(d.interval->low, 0.05);
  EXPECT_TRUE(d.interval->contains(*d.change));
  EXPECT_DOUBLE_EQ(d.confidence, 0.9);  // one metric: each end a one-sided test at alpha = 0.05
  EXPECT_FALSE(d.more_repetitions.has_value());
  EXPECT_EQ(d.base_count, 9u);
  EXPECT_EQ(d.next_count, 9u);
}

TEST(RegressionGate, SignificantButBelowThresholdPasses) {
  // Every new value beats every base value (scipy: p = 2.0567667626491154e-05), but the median moves only 3 %: the
  // whole interval lies below the 5 % margin, so no regression; at a 2 % margin the same samples regress.
  const std::vector<double> tight = ramp(1.0, 0.001), tight_shifted = ramp(1.03, 0.001);
  const TimingDecision d = decide_one({tight, tight_shifted});
  ASSERT_TRUE(d.p_value.has_value());
  EXPECT_NEAR(*d.p_value, 2.0567667626491154e-05, 1e-15);
  EXPECT_NEAR(*d.change, 0.029880478087649376, 1e-12);
  EXPECT_EQ(d.verdict, TimingVerdict::kUnchanged);
  EXPECT_LE(d.interval->high, 0.05);
  GateSettings tighter;
  tighter.threshold = 0.02;
  EXPECT_EQ(decide_one({tight, tight_shifted}, tighter).verdict, TimingVerdict::kRegressed);
}

TEST(RegressionGate, WideIntervalAcrossTheThresholdIsUndecided) {
  // The median grows 15 %, but the samples spread so widely that the interval holds changes on both sides of 5 %.
  const std::vector<double> base = {1, 5, 2, 6, 3, 7, 4, 8, 1.5};
  const std::vector<double> next = {1.1, 5.1, 2.1, 6.1, 4.5, 7.1, 4.6, 8.1, 1.6};
  const TimingDecision d = decide_one({base, next});
  ASSERT_TRUE(d.change.has_value());
  EXPECT_NEAR(*d.change, 0.15, 1e-12);
  EXPECT_NEAR(*d.p_value, 0.33323735088440964, 1e-12);
  EXPECT_EQ(d.verdict, TimingVerdict::kUndecided);
  ASSERT_TRUE(d.interval.has_value());
  EXPECT_TRUE(d.interval->contains(0.05));
  ASSERT_TRUE(d.more_repetitions.has_value());
  EXPECT_GE(*d.more_repetitions, 1);
}

TEST(RegressionGate, ImprovementBeyondTheThresholdIsReportedNotFailed) {
  GateSettings settings;
  settings.threshold = 0.02;
  const TimingDecision d = decide_one({ramp(1.03, 0.001), ramp(1.0, 0.001)}, settings);
  EXPECT_EQ(d.verdict, TimingVerdict::kImproved);
  EXPECT_LT(d.interval->high, -0.02);
}

TEST(RegressionGate, FewerThanNineSamplesAreUnreliableEvenWhenHuge) {
  const std::vector<double> eight(kBase.begin(), kBase.begin() + 8);
  const TimingDecision d = decide_one({eight, scaled(kBase, 10.0)});
  EXPECT_EQ(d.verdict, TimingVerdict::kUnreliable);
  EXPECT_FALSE(d.p_value.has_value());
  EXPECT_FALSE(d.interval.has_value());
  EXPECT_TRUE(d.change.has_value()) << "the change is still reported";
  EXPECT_EQ(decide_one({kBase, {}}).verdict, TimingVerdict::kUnreliable);
  EXPECT_FALSE(decide_one({kBase, {}}).next_median.has_value());
}

TEST(RegressionGate, TheFamilyWidensEveryInterval) {
  // Each end of an interval is a one-sided test at alpha / m over the m reliable metrics: the same samples get a
  // wider interval in a larger family, so an unchanged tree fails at most alpha however many cases the suite has.
  std::vector<TimingSamples> family = {{kBase, kShifted}};
  const TimingDecision alone = decide_timings(family, {}).at(0);
  for (int i = 0; i < 19; ++i) family.push_back({kBase, kBase});
  const std::vector<TimingDecision> d = decide_timings(family, {});
  EXPECT_DOUBLE_EQ(d[0].confidence, 1.0 - 2.0 * 0.05 / 20);
  EXPECT_LE(d[0].interval->low, alone.interval->low);
  EXPECT_GE(d[0].interval->high, alone.interval->high);
  EXPECT_NEAR(*d[0].p_value, 0.002817770464829288 * 20, 1e-12);  // Holm, reported beside it
  // Unreliable metrics are not part of the family: they do not widen it.
  family.resize(1);
  for (int i = 0; i < 8; ++i) family.push_back({{1.0}, {1.0}});
  EXPECT_DOUBLE_EQ(decide_timings(family, {}).at(0).confidence, 0.9);
}

TEST(RegressionGate, TheSameSamplesGiveTheSameVerdictEveryTime) {
  const std::vector<TimingSamples> family = {{kBase, kShifted}, {kShifted, kBase}};
  const std::vector<TimingDecision> a = decide_timings(family, {}), b = decide_timings(family, {});
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].interval->low, b[i].interval->low);
    EXPECT_EQ(a[i].interval->high, b[i].interval->high);
  }
}

TEST(RegressionGate, IdenticalSamplesAreNoRegressionAtAMarginBeyondTheirSpread) {
  const TimingDecision tied = decide_one({std::vector<double>(9, 2.0), std::vector<double>(9, 2.0)});
  EXPECT_EQ(tied.verdict, TimingVerdict::kUnchanged);
  EXPECT_DOUBLE_EQ(*tied.p_value, 1.0);
  EXPECT_DOUBLE_EQ(tied.interval->low, 0.0);
  EXPECT_DOUBLE_EQ(tied.interval->high, 0.0);
  GateSettings wide;
  wide.threshold = 0.25;  // kBase spreads 16 %: its resampled medians move well within 25 %
  const TimingDecision d = decide_one({kBase, kBase}, wide);
  EXPECT_EQ(d.verdict, TimingVerdict::kUnchanged);
  EXPECT_DOUBLE_EQ(*d.change, 0.0);
}

TEST(RepetitionsToDecide, TheEndFacingTheThresholdMustPassIt) {
  // Change 10 %, interval [0 %, 20 %] from 9 repetitions, margin 5 %: the lower end reaches 10 points below the
  // change and must come within 5: sqrt(9 / N) * 10 < 5 -> N > 36, so 27 more.
  EXPECT_EQ(repetitions_to_decide(0.10, {0.0, 0.20}, 0.05, 9), 27);
  // Below the margin the upper end faces it: change 0, [-0.1, 0.1], margin 0.05: N > 36 as well.
  EXPECT_EQ(repetitions_to_decide(0.0, {-0.1, 0.1}, 0.05, 9), 27);
  EXPECT_FALSE(repetitions_to_decide(0.05, {0.0, 0.1}, 0.05, 9).has_value()) << "on the margin: no number decides";
  EXPECT_FALSE(repetitions_to_decide(0.10, {0.08, 0.12}, 0.05, 9).has_value()) << "already decided";
  EXPECT_EQ(repetitions_to_decide(0.051, {-1.0, 1.0}, 0.05, 9), kMaxMoreRepetitions);
}

TEST(RegressionGate, ZeroBaseMedianHasNoChangeAndIsUnreliable) {
  const TimingDecision d = decide_one({std::vector<double>(9, 0.0), std::vector<double>(9, 1.0)});
  EXPECT_FALSE(d.change.has_value());
  EXPECT_EQ(d.verdict, TimingVerdict::kUnreliable);
}

TEST(RegressionGate, RejectsBadInput) {
  GateSettings s;
  s.alpha = 0.0;
  EXPECT_THROW(decide_one({kBase, kBase}, s), std::invalid_argument);
  s.alpha = 1.0;
  EXPECT_THROW(decide_one({kBase, kBase}, s), std::invalid_argument);
  s = {};
  s.threshold = -0.1;
  EXPECT_THROW(decide_one({kBase, kBase}, s), std::invalid_argument);
  std::vector<double> with_nan = kBase;
  with_nan[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(decide_one({kBase, with_nan}), std::invalid_argument);
}

TEST(RegressionGate, AMergedRunsIntervalDrawsItsProcessesFirst) {
  // The new run merged from 4 shards whose levels differ (a ratio moves between processes more than within one):
  // its interval must be at least as wide as the one that treats its 12 repetitions as one process's.
  std::vector<double> next;
  std::vector<int> process;
  for (int k = 0; k < 4; ++k) {
    for (int r = 0; r < 3; ++r) {
      next.push_back(1.0 + 0.06 * k + 0.001 * r);
      process.push_back(k + 1);
    }
  }
  const std::vector<double> base = ramp(1.0, 0.001, 12);
  const TimingDecision one = decide_one({base, next});
  const TimingDecision merged = decide_one({base, next, {}, process});
  ASSERT_TRUE(one.interval && merged.interval);
  EXPECT_EQ(one.next_processes, 1u);
  EXPECT_EQ(merged.next_processes, 4u);
  EXPECT_EQ(merged.base_processes, 1u);
  EXPECT_LE(merged.interval->low, one.interval->low);
  EXPECT_GE(merged.interval->high, one.interval->high);
  EXPECT_GT(merged.interval->high - merged.interval->low, one.interval->high - one.interval->low);
  // One process named explicitly is the plain bootstrap, draw for draw.
  const TimingDecision named = decide_one({base, next, std::vector<int>(base.size(), 7), std::vector<int>(12, 7)});
  EXPECT_EQ(named.interval->low, one.interval->low);
  EXPECT_EQ(named.interval->high, one.interval->high);
  EXPECT_THROW(decide_one({base, next, {}, {1, 2}}), std::invalid_argument) << "a process list of another length";
}

TEST(RegressionGate, VerdictNames) {
  EXPECT_STREQ(verdict_name(TimingVerdict::kRegressed), "regressed");
  EXPECT_STREQ(verdict_name(TimingVerdict::kUnreliable), "unreliable");
}

}  // namespace
}  // namespace tcsb
