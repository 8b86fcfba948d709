// The world pass's speed-up at equal error and its world-against-per-body comparison from a hand-made world pass:
// the rows read off discrete LOD's and fewer passes' curves, the same-nodes interpolation, and what is missing.
#include "paper/world_equal_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string_view>

namespace tcsb {
namespace {

constexpr std::size_t kWorldPassBlocks = 10;

WorldMethodResult world_row(std::string_view method, double budget, double nodes, double p95, double ms,
                            int divisor = 1) {
  WorldMethodResult m;
  m.method = std::string(method);
  m.budget = budget;
  m.solver_divisor = divisor;
  m.mean_nodes = nodes;
  m.p95_px = p95;
  // Blocks alternate ±5 % around the time: a median of `ms`, and an interval with some width.
  for (std::size_t b = 0; b < kWorldPassBlocks; ++b) m.block_step_ms.push_back(ms * (b % 2 ? 1.05 : 0.95));
  return m;
}

WorldResult world_pass_with_curves() {
  WorldResult w;
  w.bodies = 4;
  w.scene_nodes = 4000;
  w.methods = {world_row("full_resolution", 1.0, 4000, 0.0, 16.0),  world_row("tcsb_world", 0.2, 800, 2.0, 2.0),
               world_row("tcsb_body", 0.2, 800, 6.0, 2.0),          world_row("discrete_lod", 0.2, 790, 8.0, 1.0),
               world_row("tcsb_world", 0.5, 2000, 1.0, 5.0),        world_row("tcsb_body", 0.5, 2000, 1.5, 5.0),
               world_row("discrete_lod", 0.5, 1990, 1.0, 4.0),      world_row("noise_floor", 1.0, 4000, 0.05, 16.0),
               world_row("full_resolution", 1.0, 4000, 4.0, 8.0, 2)};
  return w;
}

TEST(WorldEqualError, ReadsDiscreteLodAndFewerPassesAtTcsbWorldsError) {
  const std::optional<WorldEqualError> t = world_equal_error(world_pass_with_curves());
  ASSERT_TRUE(t);
  const EqualErrorNet& scene = t->scene;
  EXPECT_TRUE(scene.missing.empty()) << scene.missing;
  EXPECT_EQ(scene.metric, "p95_px");
  EXPECT_DOUBLE_EQ(scene.floor, 0.05);
  ASSERT_EQ(scene.rows.size(), 2u);
  // Discrete LOD: 8 px at 1 ms and 1 px at 4 ms, a line of slope -1.5 in log-log: 2 px at 4^(2/3) ms.
  const EqualErrorRow& low = scene.rows[0];
  EXPECT_DOUBLE_EQ(low.compression, 0.2);
  EXPECT_EQ(low.grid.status, EqualErrorStatus::kInterpolated);
  EXPECT_NEAR(*low.grid.speedup, std::pow(4.0, 2.0 / 3.0) / 2.0, 1e-9);
  ASSERT_TRUE(low.grid.interval);
  // Fewer passes: 4 px at 8 ms, then the reference at its noise floor at 16 ms; 2 px lies between them.
  EXPECT_EQ(low.full.status, EqualErrorStatus::kInterpolated);
  EXPECT_GT(*low.full.time_ms, 8.0);
  EXPECT_LT(*low.full.time_ms, 16.0);
  // The rivals' finest point is the reference at the floor, not the full-resolution row's own 0 px.
  ASSERT_EQ(scene.grid.back().method, "reference");
  EXPECT_DOUBLE_EQ(scene.grid.back().error, 0.05);
  // At 1 px, discrete LOD's 0.5 budget is as accurate: read at that point exactly.
  EXPECT_NEAR(*scene.rows[1].grid.time_ms, 4.0, 1e-9);
}

TEST(WorldEqualError, ComparesTheWorldBudgetWithPerBodyBudgetsAtTheSameTotalNodes) {
  WorldResult w = world_pass_with_curves();
  w.methods[1].mean_nodes = 1000;  // tcsb_world at 0.2 spent more nodes than its per-body twin: read between
  const std::optional<WorldEqualError> t = world_equal_error(w);
  ASSERT_TRUE(t);
  ASSERT_EQ(t->same_nodes.size(), 2u);
  const WorldSameNodesRow& low = t->same_nodes[0];
  EXPECT_DOUBLE_EQ(low.nodes, 1000);
  ASSERT_TRUE(low.body_p95_px);
  // tcsb_body: 6 px at 800 nodes, 1.5 px at 2000, log-log between them.
  const double slope = std::log(1.5 / 6.0) / std::log(2000.0 / 800.0);
  EXPECT_NEAR(*low.body_p95_px, 6.0 * std::pow(1000.0 / 800.0, slope), 1e-9);
  EXPECT_NEAR(*low.ratio, *low.body_p95_px / 2.0, 1e-12);
  EXPECT_NEAR(*t->same_nodes[1].ratio, 1.5, 1e-12);
  // A world budget past per-body TC-SB's largest node count is never extrapolated.
  w.methods[4].mean_nodes = 2100;
  const WorldSameNodesRow beyond = world_equal_error(w)->same_nodes[1];
  EXPECT_FALSE(beyond.body_p95_px);
  EXPECT_FALSE(beyond.ratio);
}

TEST(WorldEqualError, NoCurvesNoTableAndAMissingCurveIsNamed) {
  WorldResult w = world_pass_with_curves();
  w.methods.pop_back();  // no full resolution at fewer passes
  const std::optional<WorldEqualError> t = world_equal_error(w);
  ASSERT_TRUE(t);
  EXPECT_NE(t->scene.missing.find("solver_divisors"), std::string::npos) << t->scene.missing;
  EXPECT_TRUE(t->scene.rows.empty());
  w.methods.pop_back();  // and no noise floor: a pass without curves
  EXPECT_FALSE(world_equal_error(w));
}

}  // namespace
}  // namespace tcsb
