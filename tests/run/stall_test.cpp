// Stall detection: a repetition whose mean step is far above its median.
#include "run/stall.h"

#include <gtest/gtest.h>

#include "analysis/statistics.h"

namespace tcsb {
namespace {

RepetitionResult repetition(int index, double mean_ms, double median_ms, const char* status = "ok") {
  RepetitionResult r;
  r.repetition = index;
  r.mean_step_ms = mean_ms;
  r.median_step_ms = median_ms;
  r.status = status;
  return r;
}

TEST(Stall, OnlyRepetitionsWhoseMeanIsFarAboveTheirMedian) {
  RunResult run;
  run.suite.steps = 400;
  CaseResult& a = run.cases.emplace_back();
  a.label = "n55/tcsb@0.3";
  a.repetitions = {repetition(0, 0.21, 0.20), repetition(1, 4.558, 0.216), repetition(2, 0.60, 0.20)};
  CaseResult& b = run.cases.emplace_back();
  b.label = "n81/plain";
  b.repetitions = {repetition(0, 9.0, 0.0), repetition(1, 9.0, 1.0, "diverged"), repetition(2, 3.01, 1.0),
                   repetition(3, 3.0, 1.0)};
  const std::vector<Stall> stalls = stalled_repetitions(run);
  ASSERT_EQ(stalls.size(), 2u);
  EXPECT_EQ(stalls[0].label, "n55/tcsb@0.3");
  EXPECT_EQ(stalls[0].repetition, 1);
  EXPECT_NEAR(stalls[0].mean_over_median, 21.1, 0.05);
  EXPECT_NEAR(stalls[0].lost_s, (4.558 - 0.216) * 400 / 1000, 1e-12);
  // 3x exactly is not a stall, 3.01x is; a zero median or a diverged repetition says nothing.
  EXPECT_EQ(stalls[1].label, "n81/plain");
  EXPECT_EQ(stalls[1].repetition, 2);
}

/// A repetition with these timed steps, its mean and median computed from them.
RepetitionResult stepped(int index, const std::vector<double>& steps) {
  RepetitionResult r = repetition(index, 0, 0);
  r.series.step_ms = steps;
  r.mean_step_ms = mean(steps);
  r.median_step_ms = median(steps);
  return r;
}

TEST(Stall, ABodysOwnRhythmIsNotAStall) {
  // The largest scaling net's plain body: every 4th step re-inserts the whole DBVT and takes 6-20x a quiet one
  // (measured: 372 ms quiet, 2 380-7 256 ms on those steps), so its mean is 4.8x its median.
  std::vector<double> rhythm;
  for (int i = 0; i < 40; ++i) rhythm.push_back(i % 4 == 2 ? 6000.0 : 380.0);
  ASSERT_GT(mean(rhythm), kStallFactor * median(rhythm));
  EXPECT_TRUE(slow_by_rhythm(rhythm, median(rhythm)));
  // The same mean from a pause: one step of 61 s, or ten slow steps in a row.
  std::vector<double> one_pause(40, 380.0), long_pause(40, 380.0);
  one_pause[17] = 61000.0;
  for (int i = 10; i < 20; ++i) long_pause[i] = 6000.0;
  EXPECT_FALSE(slow_by_rhythm(one_pause, median(one_pause)));
  EXPECT_FALSE(slow_by_rhythm(long_pause, median(long_pause)));
  EXPECT_FALSE(slow_by_rhythm({}, 1.0));

  RunResult run;
  run.suite.steps = 40;
  CaseResult& c = run.cases.emplace_back();
  c.label = "n1025/plain";
  c.repetitions = {stepped(0, rhythm), stepped(1, one_pause), stepped(2, long_pause)};
  const std::vector<Stall> stalls = stalled_repetitions(run);
  ASSERT_EQ(stalls.size(), 2u);
  EXPECT_EQ(stalls[0].repetition, 1);
  EXPECT_EQ(stalls[1].repetition, 2);
}

}  // namespace
}  // namespace tcsb
