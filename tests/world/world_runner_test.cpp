// The world pass on a tiny scene of three banners: every method runs, full resolution is its own reference, the
// budgets hold, the world budget favours the banner near the camera, and discrete LOD's switches are measured.
#include "world/world_runner.h"

#include <gtest/gtest.h>

#include "suite/scene_bodies.h"
#include "world_suite_json.h"

namespace tcsb {
namespace {

const WorldMethodResult& world_method(const WorldResult& r, const std::string& name) {
  for (const WorldMethodResult& m : r.methods)
    if (m.method == name) return m;
  throw std::runtime_error("no method " + name);
}

class WorldPass : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    nlohmann::json j = testing::world_suite_json();
    suite_ = new Suite(parse_suite_text(j.dump(), "row.json"));
    result_ = new WorldResult(run_world(*suite_));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete suite_;
  }
  static Suite* suite_;
  static WorldResult* result_;
};
Suite* WorldPass::suite_ = nullptr;
WorldResult* WorldPass::result_ = nullptr;

TEST_F(WorldPass, RunsEveryMethod) {
  ASSERT_EQ(result_->bodies, 3);
  EXPECT_EQ(result_->scene_nodes, 3 * 81);
  ASSERT_EQ(result_->methods.size(), 4u);
  for (const WorldMethodResult& m : result_->methods) {
    EXPECT_EQ(m.status, "ok") << m.method << ": " << m.diverged_reason;
    EXPECT_GT(m.step_ms, 0.0) << m.method;
  }
}

TEST_F(WorldPass, FullResolutionIsItsOwnReference) {
  const WorldMethodResult& full = world_method(*result_, "full_resolution");
  EXPECT_EQ(full.p95_px, 0.0);
  EXPECT_EQ(full.mean_nodes, 3 * 81);
  EXPECT_EQ(full.resolution_changes, 0);
}

TEST_F(WorldPass, TheBudgetsHoldOnAverage) {
  const double budget = 0.5 * 3 * 81;
  // TC-SB comes down to its budget over the first steps (a few operations a step), hence a little slack.
  EXPECT_LE(world_method(*result_, "tcsb_world").mean_nodes, budget * 1.1);
  EXPECT_LE(world_method(*result_, "discrete_lod").mean_nodes, budget);
  EXPECT_GT(world_method(*result_, "discrete_lod").p95_px, 0.0);
}

TEST(WorldPassBudget, GivesTheBannerNearTheCameraMoreNodesThanAFarOne) {
  // The camera stays a metre and a half in front of the first banner: the third, 6 m along, looks small.
  nlohmann::json j = testing::world_suite_json();
  j["scene"]["camera"]["path"][1]["position"] = {-2.5, 1.5, -1.5};
  j["scene"]["camera"]["path"][1]["target"] = {-2.5, 1.5, 0.0};
  j["scene"]["camera"]["path"][0]["position"] = {-3.0, 1.5, -1.5};
  const WorldResult r = run_world(parse_suite_text(j.dump(), "near.json"));
  const WorldMethodResult& w = world_method(r, "tcsb_world");
  ASSERT_EQ(w.body_mean_nodes.size(), 3u);
  EXPECT_GT(w.body_mean_nodes[0], w.body_mean_nodes[2]);
  // Per-body budgets cannot: each banner holds half its own nodes wherever the camera is.
  const WorldMethodResult& b = world_method(r, "tcsb_body");
  EXPECT_GT(w.body_mean_nodes[0] - w.body_mean_nodes[2], b.body_mean_nodes[0] - b.body_mean_nodes[2]);
}

TEST_F(WorldPass, CountsTcsbsOperationsOnly) {
  for (const WorldMethodResult& m : result_->methods) {
    if (m.method.rfind("tcsb", 0) != 0) {
      EXPECT_FALSE(m.churn) << m.method;
      continue;
    }
    ASSERT_TRUE(m.churn) << m.method;
    EXPECT_GT(m.churn->refines + m.churn->coarsens, 0) << m.method;
    EXPECT_LE(m.churn->undone, m.churn->refines + m.churn->coarsens) << m.method;
    // An operation moves a body's committed nodes by at most three (four children for their parent).
    EXPECT_LE(m.churn->nodes_moved, 3 * (m.churn->refines + m.churn->coarsens)) << m.method;
  }
}

TEST_F(WorldPass, DiscreteLodSwitchesAndItsPopsAreMeasured) {
  const WorldMethodResult& lod = world_method(*result_, "discrete_lod");
  ASSERT_TRUE(lod.lod_scale);
  EXPECT_GT(lod.resolution_changes, 0);
  EXPECT_GT(lod.popping_px, 0.0);
}

}  // namespace
}  // namespace tcsb
