// TcSoftBody::restore_order(): the arrays go back to a plain body's order, and nothing else changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>
#include <vector>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody_impl.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

TcSettings unordered() {
  TcSettings s;
  s.restore_order = false;
  return s;
}

/// Steps with random operations towards `target` nodes, as the runner orders a step.
void operate(TcSoftBody& body, RandomPolicy& policy, int target, int steps) {
  for (int s = 0; s < steps; ++s) {
    body.advance_blends();
    policy.apply(body, target, 32);
    body.simulate_step(kDt);
  }
}

/// What a simulated node is, whatever its place in Bullet's array: its position and velocity bits.
using NodeState = std::tuple<btScalar, btScalar, btScalar, btScalar, btScalar, btScalar>;
/// What a link is, whatever its place: endpoints, role, operation, rest length and constant bits.
using LinkState = std::tuple<TreeId, TreeId, int, int, btScalar, btScalar>;

std::map<TreeId, NodeState> nodes_by_tree_id(const TcSoftBody& body) {
  std::map<TreeId, NodeState> out;
  for (int i = 0; i < body.node_count(); ++i) {
    const btSoftBody::Node& n = body.m_nodes[i];
    out[body.tree_id(i)] = {n.m_x.x(), n.m_x.y(), n.m_x.z(), n.m_v.x(), n.m_v.y(), n.m_v.z()};
  }
  return out;
}

std::vector<LinkState> link_set(const TcSoftBody& body) {
  std::vector<LinkState> out;
  for (int i = 0; i < body.link_count(); ++i) {
    const CutLink& m = body.cut_links()[static_cast<std::size_t>(i)];
    out.emplace_back(m.a, m.b, static_cast<int>(m.role), m.op, body.m_links[i].m_rl, body.m_links[i].m_c0);
  }
  std::sort(out.begin(), out.end());
  return out;
}

int index_of(const TcSoftBody& body, const btSoftBody::Node* n) { return static_cast<int>(n - &body.m_nodes[0]); }

TEST(TcSoftBodyOrder, RestoringKeepsEveryNodeEveryLinkAndEveryInvariant) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), unordered());
  RandomPolicy policy(7);
  operate(tc, policy, 400, 60);
  ASSERT_GT(tc.interpolations(), 0) << "the test wants operations in flight while the order is restored";
  ASSERT_GT(tc.impl().displaced(), 0);
  const auto nodes = nodes_by_tree_id(tc);
  const auto links = link_set(tc);
  const int interpolations = tc.interpolations();

  tc.restore_order();

  EXPECT_EQ(tc.impl().order_restorations(), 1);
  EXPECT_EQ(tc.impl().displaced(), 0);
  EXPECT_EQ(nodes_by_tree_id(tc), nodes);
  EXPECT_EQ(link_set(tc), links);
  EXPECT_EQ(tc.interpolations(), interpolations);
  const Validation v = tc.validate();
  ASSERT_TRUE(v.ok()) << v.summary();

  // Nodes row-major by their block's centre; links by (lower endpoint, higher endpoint).
  const LodTree& lod = net->lod();
  const auto key = [&](int i) {
    const LodNode& t = lod.node(tc.tree_id(i));
    return std::make_pair(t.leaf_y0 + t.leaf_y1, t.leaf_x0 + t.leaf_x1);
  };
  for (int i = 1; i < tc.node_count(); ++i) EXPECT_LE(key(i - 1), key(i)) << "node " << i;
  const auto link_key = [&](int li) {
    const int a = index_of(tc, tc.m_links[li].m_n[0]), b = index_of(tc, tc.m_links[li].m_n[1]);
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  for (int li = 1; li < tc.link_count(); ++li) EXPECT_LT(link_key(li - 1), link_key(li)) << "link " << li;

  // Operations go on from the restored arrays: blends end, new operations begin, invariants hold.
  operate(tc, policy, 700, 30);
  const Validation after = tc.validate();
  EXPECT_TRUE(after.ok()) << after.summary();
}

TEST(TcSoftBodyOrder, OnTheFinestCutRestoringChangesNothing) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  tc.restore_order();
  for (int s = 0; s < 50; ++s) {
    tc.advance_blends();
    tc.simulate_step(kDt);
    step_soft_body(*plain, kDt);
  }
  for (int i = 0; i < plain->m_nodes.size(); ++i) {
    ASSERT_EQ(tc.tree_id(i), i);
    ASSERT_EQ(tc.m_nodes[i].m_x, plain->m_nodes[i].m_x) << "node " << i;
    ASSERT_EQ(tc.m_nodes[i].m_v, plain->m_nodes[i].m_v) << "node " << i;
  }
}

TEST(TcSoftBodyOrder, BackOnTheFinestCutTheArraysAreAPlainBodysOrder) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), unordered());
  RandomPolicy policy(11);
  operate(tc, policy, 90, 80);
  for (int round = 0; round < 500 && tc.committed_count() < 17 * 17; ++round) {
    tc.advance_blends();
    for (int i = 0; i < tc.node_count(); ++i)
      if (tc.can_refine(tc.tree_id(i)).ok) tc.begin_refine(tc.tree_id(i));
    tc.simulate_step(kDt);
  }
  for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  ASSERT_EQ(tc.node_count(), 17 * 17);
  tc.restore_order();
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  ASSERT_EQ(tc.link_count(), plain->m_links.size());
  for (int i = 0; i < tc.node_count(); ++i) ASSERT_EQ(tc.tree_id(i), i);
  for (int li = 0; li < tc.link_count(); ++li) {
    const int a = index_of(tc, tc.m_links[li].m_n[0]), b = index_of(tc, tc.m_links[li].m_n[1]);
    const auto* base = &plain->m_nodes[0];
    const int pa = static_cast<int>(plain->m_links[li].m_n[0] - base);
    const int pb = static_cast<int>(plain->m_links[li].m_n[1] - base);
    ASSERT_EQ(std::minmax(a, b), std::minmax(pa, pb)) << "link " << li;
  }
}

/// Restores on any body, however small (the default waits for TcSettings::restore_order_min_nodes).
TcSettings always_ordered() {
  TcSettings s;
  s.restore_order_min_nodes = 0;
  return s;
}

TEST(TcSoftBodyOrder, OperationsRestoreTheOrderOncePastTheFraction) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSoftBody on(world.info(), net, testing::test_solver(), always_ordered());
  TcSoftBody off(world.info(), net, testing::test_solver(), unordered());
  RandomPolicy policy_on(3), policy_off(3);
  for (int s = 0; s < 200; ++s) {
    operate(on, policy_on, 300 + (s / 40) * 150, 1);
    operate(off, policy_off, 300 + (s / 40) * 150, 1);
    // advance_blends() restores once the displaced elements pass the fraction, so right after it they never do;
    // the operations begun since may add at most their own.
    const double limit = TcSettings::kReorderFraction * (on.node_count() + on.link_count());
    ASSERT_LE(on.impl().displaced(), limit + 32 * 40) << "step " << s;
  }
  EXPECT_GT(on.impl().order_restorations(), 1);
  EXPECT_EQ(off.impl().order_restorations(), 0);
  EXPECT_GT(off.impl().displaced(), TcSettings::kReorderFraction * (off.node_count() + off.link_count()));
  EXPECT_TRUE(on.validate().ok()) << on.validate().summary();
}

TEST(TcSoftBodyOrder, BodiesBelowTheMinimumNodeCountAreLeftInTheOperationsOrder) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSettings settings;
  // Above anything this net can simulate (blends hold old and new nodes at once, so more than its leaves).
  settings.restore_order_min_nodes = static_cast<int>(net->lod().size()) + 1;
  TcSoftBody below(world.info(), net, testing::test_solver(), settings);
  settings.restore_order_min_nodes = 33 * 33 / 2;  // restores while it simulates at least half the leaves
  TcSoftBody above(world.info(), net, testing::test_solver(), settings);
  RandomPolicy policy_below(3), policy_above(3);
  operate(below, policy_below, 800, 40);
  operate(above, policy_above, 800, 40);
  EXPECT_EQ(below.impl().order_restorations(), 0);
  EXPECT_GT(below.impl().displaced(), TcSettings::kReorderFraction * (below.node_count() + below.link_count()));
  EXPECT_GT(above.impl().order_restorations(), 0);
  EXPECT_TRUE(below.validate().ok()) << below.validate().summary();
}

/// True when Bullet's arrays are in the order restore_order() gives: nodes by their blocks' spatial ranks, links by
/// (lower endpoint, higher endpoint).
bool in_plain_order(const TcSoftBody& body) {
  const LodTree& lod = body.tree();
  for (int i = 1; i < body.node_count(); ++i)
    if (lod.spatial_rank(body.tree_id(i - 1)) >= lod.spatial_rank(body.tree_id(i))) return false;
  const auto ends = [&](int li) {
    const int a = index_of(body, body.m_links[li].m_n[0]), b = index_of(body, body.m_links[li].m_n[1]);
    return std::pair{std::min(a, b), std::max(a, b)};
  };
  for (int li = 1; li < body.link_count(); ++li)
    if (!(ends(li - 1) < ends(li))) return false;
  return true;
}

TEST(TcSoftBodyOrder, WithExactOrderEveryStepSweepsTheArraysInAPlainBodysOrder) {
  const auto net = testing::square_net(33);  // below restore_order_min_nodes: only exact_order restores here
  SceneWorld world({});
  TcSettings settings;
  settings.exact_order = true;
  TcSoftBody exact(world.info(), net, testing::test_solver(), settings);
  TcSoftBody amortised(world.info(), net, testing::test_solver(), TcSettings{});
  RandomPolicy policy_exact(5), policy_amortised(5);
  int out_of_order = 0;
  for (int s = 0; s < 200; ++s) {
    const int target = 300 + (s / 40) * 150;
    exact.advance_blends();
    ASSERT_EQ(exact.impl().displaced(), 0) << "step " << s;
    ASSERT_TRUE(in_plain_order(exact)) << "step " << s;
    policy_exact.apply(exact, target, 32);
    exact.settle_order();  // as a controller does once it has begun the boundary's operations
    ASSERT_TRUE(in_plain_order(exact)) << "step " << s << ", after the operations";
    exact.simulate_step(kDt);
    operate(amortised, policy_amortised, target, 1);
    if (!in_plain_order(amortised)) ++out_of_order;
  }
  EXPECT_GT(exact.impl().order_restorations(), 50);
  EXPECT_EQ(amortised.impl().order_restorations(), 0);
  EXPECT_GT(out_of_order, 150);  // the default leaves a body this small in the operations' order
  EXPECT_TRUE(exact.validate().ok()) << exact.validate().summary();
}

TEST(TcSoftBodyDbvt, ABodyThatShrankGetsAFreshTreeAndMovesExactlyAsWithout) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSettings without = always_ordered();
  without.rebuild_dbvt = false;
  TcSoftBody on(world.info(), net, testing::test_solver(), always_ordered());
  TcSoftBody off(world.info(), net, testing::test_solver(), without);
  RandomPolicy policy_on(5), policy_off(5);
  operate(on, policy_on, 300, 60);
  operate(off, policy_off, 300, 60);
  // From 1 089 nodes to about 300: a tree built again each time the body is down by the factor since the last.
  EXPECT_GE(on.impl().dbvt_rebuilds(), 3);
  EXPECT_EQ(off.impl().dbvt_rebuilds(), 0);
  EXPECT_TRUE(on.validate().ok()) << on.validate().summary();
  // The tree takes no part in the physics: every node and link the same, bit for bit.
  EXPECT_EQ(nodes_by_tree_id(on), nodes_by_tree_id(off));
  EXPECT_EQ(link_set(on), link_set(off));
  EXPECT_EQ(on.m_ndbvt.m_leaves, on.node_count());

  // At a fixed compression the body does not shrink, and no tree is built again.
  const int rebuilds = on.impl().dbvt_rebuilds();
  operate(on, policy_on, 300, 100);
  EXPECT_EQ(on.impl().dbvt_rebuilds(), rebuilds);
  EXPECT_TRUE(on.validate().ok()) << on.validate().summary();
}

TEST(TcSoftBodyDbvt, TheStepAfterARebuildReinsertsNoMoreThanAnyOther) {
  // Rebuilt with the boxes Bullet's update gives, the moving cloth stays inside its leaves' boxes for the next
  // steps; with bare boxes every moving node would leave its box on the next step and be re-inserted.
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSoftBody body(world.info(), net, testing::test_solver(), always_ordered());
  RandomPolicy policy(5);
  operate(body, policy, body.node_count(), 10);  // falling, on the finest cut
  int checked = 0;
  for (int s = 0; s < 60; ++s) {
    const int rebuilds = body.impl().dbvt_rebuilds();
    body.advance_blends();
    if (body.impl().dbvt_rebuilds() == rebuilds) {
      policy.apply(body, 300, 32);
      body.simulate_step(kDt);
      continue;
    }
    std::map<const btDbvtNode*, btDbvtAabbMm> boxes;
    for (int i = 0; i < body.node_count(); ++i) boxes[body.m_nodes[i].m_leaf] = body.m_nodes[i].m_leaf->volume;
    body.simulate_step(kDt);  // Bullet's step alone: no operation adds or removes a leaf
    int reinserted = 0;
    for (int i = 0; i < body.node_count(); ++i) {
      const btDbvtNode* leaf = body.m_nodes[i].m_leaf;
      reinserted += std::memcmp(&boxes.at(leaf), &leaf->volume, sizeof(btDbvtAabbMm)) != 0;
    }
    EXPECT_LT(reinserted, body.node_count() / 20) << "rebuild " << body.impl().dbvt_rebuilds() << ", step " << s;
    ++checked;
  }
  EXPECT_GE(checked, 3);
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
}

TEST(TcSoftBodyDbvt, ARebuiltTreeIsThePlainBodysTree) {
  // Rebuilt on the finest cut, the tree is the one a plain body of the net builds: the same leaves in the same
  // shuffled order, so the same shape.
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), always_ordered());
  tc.impl().rebuild_node_dbvt();
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  const auto shape = [](const btDbvtNode* root) {
    std::vector<int> depths;
    std::vector<std::pair<const btDbvtNode*, int>> stack{{root, 0}};
    while (!stack.empty()) {
      const auto [node, depth] = stack.back();
      stack.pop_back();
      if (node->isleaf()) {
        depths.push_back(depth);
      } else {
        stack.push_back({node->childs[0], depth + 1});
        stack.push_back({node->childs[1], depth + 1});
      }
    }
    return depths;
  };
  EXPECT_EQ(shape(tc.m_ndbvt.m_root), shape(plain->m_ndbvt.m_root));
  EXPECT_EQ(tc.impl().dbvt_rebuilds(), 1);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

}  // namespace
}  // namespace tcsb
