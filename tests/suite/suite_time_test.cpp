// The wall-time estimate `tcsb validate` prints: nodes x steps x the per-node-step cost, per case and repetition.
#include "suite/suite_time.h"

#include <gtest/gtest.h>

namespace tcsb {
namespace {

Suite one_net_suite() {
  Suite s;
  NetSpec n;
  n.name = "n10";
  n.width = n.height = 10;
  s.nets = {n};
  s.methods = {Method::kPlain, Method::kTcsb};
  s.compression = {1.0, 0.5};
  s.steps = 90;
  s.warmup_steps = 10;
  s.repetitions = 2;
  s.solver.piterations = 4;
  s.solver.viterations = 0;
  s.solver.diterations = 0;
  return s;
}

TEST(SuiteTime, NodesTimesStepsTimesTheCostScaledByIterations) {
  // plain 100 + tcsb@1 100 + tcsb@0.5 50 nodes, 100 steps, 4 iterations (twice the cost's 2), 2 repetitions.
  EXPECT_DOUBLE_EQ(estimate_wall_seconds(one_net_suite()), 250.0 * 100 * kNodeStepSeconds * 2 * 2);
}

TEST(SuiteTime, CountsEachConfigurationWithItsSettings) {
  Suite s = one_net_suite();
  s.axes = {{"solver.piterations", {2, 8}}};
  s.configurations = {{{0}, "piterations=2"}, {{1}, "piterations=8"}};
  EXPECT_DOUBLE_EQ(estimate_wall_seconds(s), 250.0 * 100 * kNodeStepSeconds * (1 + 4) * 2);
}

TEST(SuiteTime, OnlyTheUnitsThisProcessRuns) {
  Suite s = one_net_suite();
  s.run_units = {false};  // an empty shard
  EXPECT_EQ(estimate_wall_seconds(s), 0.0);
}

}  // namespace
}  // namespace tcsb
