// Bullet's anchors (appendAnchor: a node attached to a rigid body, held by a Node*) on a TcSoftBody: they follow
// their node through every move the body makes of it, and an anchor whose node an operation removes goes to the node
// that takes its place.
#include <gtest/gtest.h>

#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <vector>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody_impl.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

/// The tree node an anchor holds, or kNoTreeNode when its Node* is no simulated node.
TreeId anchored_tree_node(const TcSoftBody& tc, int anchor) {
  const auto i = tc.m_anchors[anchor].m_node - &tc.m_nodes[0];
  return i >= 0 && i < tc.node_count() ? tc.tree_id(static_cast<int>(i)) : kNoTreeNode;
}

class AnchorsFollow : public ::testing::TestWithParam<int> {};

TEST_P(AnchorsFollow, TheirNodesThroughRemovalsAndReorderings) {
  // Anchors on nodes spread over Bullet's array, the last one included (every swap-with-last removal moves it), under
  // random operations; settings 0: swaps only, 1: restore_order on this small body, 2: exact_order. No pins: Bullet's
  // anchor on a pinned node (zero inverse mass) to a static body divides by zero.
  const auto net = testing::square_net(17, 0);
  SceneWorld world({});
  TcSettings settings;
  if (GetParam() == 1) settings.restore_order_min_nodes = 0;
  if (GetParam() == 2) settings.exact_order = true;
  TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
  btSphereShape shape(0.1f);
  btRigidBody rigid(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &shape));
  const std::vector<TreeId> held{net->index(16, 16), net->index(8, 8), net->index(3, 12), net->index(12, 0)};
  for (const TreeId id : held) tc.appendAnchor(tc.bullet_index(id), &rigid);
  RandomPolicy policy(5);
  bool moved = false;
  for (int step = 0; step < 150; ++step) {
    tc.advance_blends();
    policy.apply(tc, 100, 8);
    tc.settle_order();
    tc.simulate_step(kDt);
    ASSERT_TRUE(tc.validate().ok()) << "step " << step << ": " << tc.validate().summary();
    for (int a = 0; a < static_cast<int>(held.size()); ++a)
      ASSERT_EQ(anchored_tree_node(tc, a), held[static_cast<std::size_t>(a)]) << "step " << step << ", anchor " << a;
    moved = moved || tc.bullet_index(held[0]) != 16 * 17 + 16;
  }
  EXPECT_TRUE(moved);  // the last node did move
  EXPECT_LT(tc.node_count(), 17 * 17);
  if (GetParam() != 0) {
    EXPECT_GT(tc.impl().order_restorations(), 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, AnchorsFollow, ::testing::Values(0, 1, 2));

TEST(Anchors, ANodeAnchoredWhileItLeavesHandsItsAnchorOn) {
  const auto net = testing::square_net(17, 0);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  btSphereShape shape(0.1f);
  btRigidBody rigid(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &shape));
  const LodTree& lod = net->lod();
  // A coarse: its children leave at the end; one anchored meanwhile hands its anchor to the parent.
  const TreeId parent = lod.at(1, 2, 2);
  ASSERT_TRUE(tc.can_coarsen(parent).ok);
  tc.begin_coarse(parent);
  const TreeId child = lod.node(parent).children[1];
  tc.appendAnchor(tc.bullet_index(child), &rigid);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  EXPECT_EQ(tc.bullet_index(child), -1);
  EXPECT_EQ(anchored_tree_node(tc, 0), parent);
  EXPECT_TRUE(tc.anchored(parent));
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  EXPECT_FALSE(tc.can_refine(parent).ok);  // anchored: it stays
  // A refine: the parent leaves at the end; anchored meanwhile, its anchor goes to its nearest child.
  tc.m_anchors.clear();
  tc.m_nodes[tc.bullet_index(parent)].m_battach = 0;  // (what an application removing its anchor does)
  ASSERT_TRUE(tc.can_refine(parent).ok);
  tc.begin_refine(parent);
  tc.appendAnchor(tc.bullet_index(parent), &rigid);
  const btVector3 x = tc.m_nodes[tc.bullet_index(parent)].m_x;
  for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  const TreeId heir = anchored_tree_node(tc, 0);
  ASSERT_NE(heir, kNoTreeNode);
  EXPECT_EQ(lod.node(heir).parent, parent);
  for (int i = 0; i < lod.node(parent).child_count; ++i) {
    const TreeId c = lod.node(parent).children[static_cast<std::size_t>(i)];
    EXPECT_LE((tc.m_nodes[tc.bullet_index(heir)].m_x - x).length(), (tc.m_nodes[tc.bullet_index(c)].m_x - x).length());
  }
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

TEST(Anchors, ValidateNamesAnAnchorMovedToAnotherNode) {
  const auto net = testing::square_net(9);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  btSphereShape shape(0.1f);
  btRigidBody rigid(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &shape));
  tc.appendAnchor(10, &rigid);
  ASSERT_TRUE(tc.validate().ok()) << tc.validate().summary();
  tc.m_anchors[0].m_node = &tc.m_nodes[11];  // what a stale Node* does after a move: another node
  const Validation broken = tc.validate();
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.problems.front().rfind("anchor 0: its node (Bullet 11", 0), 0u) << broken.summary();
}

TEST(Anchors, ValidateNamesAPinnedNodeAnchoredToAStaticBody) {
  // Bullet's anchor solve inverts the sum of the node's and the body's inverse masses: both zero, the cloth goes NaN.
  const auto net = testing::square_net(9);  // pinned corners
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  btSphereShape shape(0.1f);
  btRigidBody rigid(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &shape));
  tc.appendAnchor(tc.bullet_index(net->index(0, 0)), &rigid);
  const Validation v = tc.validate();
  ASSERT_FALSE(v.ok());
  EXPECT_EQ(v.problems.front().rfind("anchor 0: holds a pinned node", 0), 0u) << v.summary();
}

}  // namespace
}  // namespace tcsb
