// Stall detection: a repetition whose mean step is far above its median.
#include "run/stall.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tcsb
