// The neighbour balance of a candidate (how many level boundaries its operation removes less how many it adds), and
// the evaluator's interface charge: coarse regions grow together, so a cut settles with fewer level boundaries.
#include "feedback/interface_balance.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "feedback/budget_policy.h"
#include "feedback/evaluator.h"
#include "feedback/saliency_controller.h"
#include "fixed_field.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"

namespace tcsb {
namespace {

std::shared_ptr<const Net> unpinned_net(int width) {
  NetSpec spec;
  spec.width = spec.height = width;
  spec.pinned_corners = 0;
  return std::make_shared<const Net>(spec);
}

void coarsen_now(TcSoftBody& body, TreeId parent) {
  ASSERT_TRUE(body.can_coarsen(parent).ok);
  body.begin_coarse(parent);
  while (body.interpolations() > 0) body.advance_blends();
}

using testing::level_boundary_links;

TEST(InterfaceBalance, CountsNeighboursAtTheSameLevelOrCoarserAgainstFinerOnes) {
  const auto net = unpinned_net(17);
  SceneWorld world(WorldSettings{});
  TcSoftBody body(world.info(), net, {}, {});
  const LodTree& tree = body.tree();
  // All leaves: every level-1 neighbour is finer than level 1; a block on the border has one neighbour fewer.
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 3, 3)), -4);
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 0, 3)), -3);
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 0, 0)), -2);

  coarsen_now(body, tree.at(1, 3, 3));
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 4, 3)), -2) << "one coarse neighbour, three fine ones";
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 3, 3)), -4) << "the coarse block among fine ones";
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 5, 3)), -4);

  // A level-1 region (blocks 2..7 along both axes) with one level-2 block inside (level-1 blocks 4..5): a level-1
  // neighbour inside the level-2 block counts as coarser.
  for (int gy = 2; gy < 8; ++gy)
    for (int gx = 2; gx < 8; ++gx)
      if (!body.committed(tree.at(1, gx, gy))) coarsen_now(body, tree.at(1, gx, gy));
  coarsen_now(body, tree.at(2, 2, 2));
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 3, 4)), 4);
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(1, 2, 4)), 2) << "on the region's edge";
  EXPECT_EQ(neighbour_balance(cut_view(body), tree.at(2, 2, 2)), -4) << "level-1 blocks all round";
}

TEST(InterfaceBalance, TheChargeCoarsensNextToCoarseBlocksFirst) {
  const auto net = unpinned_net(17);
  SceneWorld world(WorldSettings{});
  TcSoftBody body(world.info(), net, {}, {});
  const LodTree& tree = body.tree();
  coarsen_now(body, tree.at(1, 3, 3));
  CutSnapshot snapshot;
  take_snapshot(body, cut_view(body), false, 0, snapshot);
  const std::vector<float> saliency(snapshot.size(), 0.0f);  // at rest: only the charge tells blocks apart
  Evaluation plain, charged, zero;
  rank_candidates(snapshot, saliency, 1000, plain);
  rank_candidates(snapshot, saliency, 1000, zero, {}, {0.0, {}});
  rank_candidates(snapshot, saliency, 1000, charged, {}, {3.0, {}});
  ASSERT_EQ(plain.coarse.size(), zero.coarse.size());
  for (std::size_t i = 0; i < plain.coarse.size(); ++i) EXPECT_EQ(plain.coarse[i].id, zero.coarse[i].id);
  ASSERT_EQ(charged.coarse.size(), plain.coarse.size());
  const auto balance = [&](TreeId id) { return neighbour_balance(snapshot.cut, id); };
  for (std::size_t i = 1; i < charged.coarse.size(); ++i)
    EXPECT_GE(balance(charged.coarse[i - 1].id), balance(charged.coarse[i].id)) << "at rank " << i;
  EXPECT_EQ(balance(charged.coarse.front().id), -2) << "a block beside the coarse one goes first";
  // The coarse block is the one refine candidate; its balance (-4: all finer) only raises its priority.
  ASSERT_EQ(charged.refine.size(), 1u);
  EXPECT_GT(charged.refine.front().priority, plain.refine.front().priority);
}

/// A fixed field of salience values spread over the net, evaluated every step on cloth at rest, for 300 steps under
/// a budget of 75 % of the nodes: the level boundaries of the cut it settles in.
int boundaries_after_settling(double interface_charge) {
  const auto net = unpinned_net(33);
  testing::StillBody still(net);
  TcSoftBody& body = still.body;
  FeedbackSettings settings;
  settings.max_ops_per_step = 16;
  settings.threshold = 0.3;
  settings.interface_charge = interface_charge;
  BudgetState state;
  const int budget = net->node_count() * 3 / 4;
  testing::run_on_fixed_field(
      body, settings, budget, 300,
      [&](TreeId id) {
        // a hash of the first leaf under the node: salience without structure
        const LodNode& node = net->lod().node(id);
        const auto leaf = static_cast<std::uint32_t>(node.leaf_y0 * net->width() + node.leaf_x0 + 1);
        return static_cast<float>(((leaf * 2654435761u) >> 8) % 1000) / 1000.0f;
      },
      state);
  EXPECT_TRUE(state.converged);
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
  return level_boundary_links(body);
}

TEST(InterfaceBalance, TheChargeLeavesFewerLevelBoundaries) {
  const int plain = boundaries_after_settling(0.0), charged = boundaries_after_settling(3.0);
  EXPECT_GT(plain, 0);
  EXPECT_LT(charged, plain / 2) << "plain " << plain << ", charged " << charged;
}

/// A 33 x 33 net pinned at two corners, swinging, under the saliency controller at 75 % for 200 steps: the level
/// boundaries of its final cut.
int boundaries_of_the_controllers_cut(double interface_charge) {
  NetSpec spec;
  spec.width = spec.height = 33;
  const auto net = std::make_shared<const Net>(spec);
  SceneWorld world({});
  TcSoftBody body(world.info(), net, {}, {});
  FeedbackSettings settings;
  settings.threshold = 0.3;
  settings.interface_charge = interface_charge;
  SaliencyController controller(settings, net->node_count() * 3 / 4);
  for (int step = 0; step < 200; ++step) {
    body.advance_blends();
    controller.before_step(body);
    body.simulate_step(1.0f / 60);
    controller.after_step(body);
  }
  EXPECT_TRUE(controller.converged());
  return level_boundary_links(body);
}

TEST(InterfaceBalance, TheControllerPassesTheChargeOn) {
  const int plain = boundaries_of_the_controllers_cut(0.0), charged = boundaries_of_the_controllers_cut(3.0);
  EXPECT_LT(charged, plain) << "plain " << plain << ", charged " << charged;
}

}  // namespace
}  // namespace tcsb
