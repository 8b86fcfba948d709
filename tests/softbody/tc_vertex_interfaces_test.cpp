// Hanging interfaces on a tree whose blocks rest on their first leaf: the vertex kinds (InterfaceKind).
#include <gtest/gtest.h>

#include "scene/scene_world.h"
#include "softbody/tc_softbody_impl.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

/// A 17^2 net, hanging interfaces, the level-1 blocks with gx < 4 (`left`) or gx >= 4 coarsened in rounds until all
/// are.
std::unique_ptr<TcSoftBody> half_coarse(SceneWorld& world, bool left, const TcSettings& base = {}) {
  const auto net = testing::square_net(17, kAllCorners, RestPlacement::kVertex);
  TcSettings settings = base;
  settings.interfaces = Interfaces::kHanging;
  auto tc = std::make_unique<TcSoftBody>(world.info(), net, testing::test_solver(), settings);
  const LodTree& tree = net->lod();
  for (bool began = true; began;) {
    began = false;
    for (int gy = 0; gy < tree.level_width(1); ++gy)
      for (int gx = 0; gx < tree.level_width(1); ++gx)
        if ((gx < 4) == left && tc->can_coarsen(tree.at(1, gx, gy)).ok) {
          tc->begin_coarse(tree.at(1, gx, gy));
          began = true;
        }
    while (tc->interpolations() > 0) tc->advance_blends();
  }
  return tc;
}

TEST(TcVertexInterfaces, OnACoarseBlocksFarSideTheFineNodeBesideTheLineHangsOnTheCoarseEdge) {
  SceneWorld world({});
  const auto tc = half_coarse(world, true);  // blocks over leaves 0..7, fine from leaf 8: their +x sides
  ASSERT_FALSE(tc->impl().interface_constraints().empty());
  for (const InterfaceConstraint& c : tc->impl().interface_constraints()) {
    EXPECT_EQ(c.kind, InterfaceKind::kVertexFar);
    ASSERT_GE(c.kept, 0);
    const TreeId in_line = c.fine[static_cast<std::size_t>(c.kept)], hanging = c.fine[c.kept == 0 ? 1 : 0];
    EXPECT_EQ(tc->net().lod().node(in_line).gy, tc->net().lod().node(c.coarse).leaf_y0);  // in line with the node
    EXPECT_EQ(tc->net().lod().node(hanging).gy, tc->net().lod().node(c.coarse).leaf_y0 + 1);
    EXPECT_NEAR(c.rest, 0, 1e-6);  // on the coarse edge's midpoint
    // The kept handle is an ordinary link (Bullet solves it); the other one is skipped.
    EXPECT_GT(tc->m_links[c.links[static_cast<std::size_t>(c.kept)]].m_c0, 0);
    EXPECT_EQ(tc->m_links[c.links[c.kept == 0 ? 1 : 0]].m_c0, 0);
  }
  EXPECT_TRUE(tc->validate().ok()) << tc->validate().summary();
}

TEST(TcVertexInterfaces, OnACoarseBlocksNearSideTheHangingLinkMeetsTheSideAtItsMidpoint) {
  TcSettings calibrated;
  calibrated.level_stiffness = {0.5, 0.25};
  SceneWorld world({});
  const auto tc = half_coarse(world, false, calibrated);  // fine leaves 0..7, blocks from leaf 8: their -x sides
  const LodTree& tree = tc->net().lod();
  int near = 0;
  for (const InterfaceConstraint& c : tc->impl().interface_constraints()) {
    if (c.kind != InterfaceKind::kVertexNear) continue;  // (the top row's +z sides face the border's blocks)
    ++near;
    const LodNode& block = tree.node(c.coarse);
    ASSERT_NE(c.corner_leaf, kNoTreeNode);
    EXPECT_EQ(tree.node(c.corner_leaf).gx, block.leaf_x0);  // the block's +z corner
    EXPECT_EQ(tree.node(c.corner_leaf).gy, block.leaf_y1);
    EXPECT_NEAR(c.rest, 0.5, 1e-6);  // one fine spacing of the 8 m, 17-node net
    EXPECT_EQ(c.stiffness, 1.0f);    // the finer level's (level 0: the solver's)
    // The kept link spans one fine spacing: the finer level's material, not the coarse block's.
    const btSoftBody::Link& kept = tc->m_links[c.links[static_cast<std::size_t>(c.kept)]];
    EXPECT_EQ(kept.m_material->m_kLST, 1.0f);
    EXPECT_GT(kept.m_c0, 0);
  }
  EXPECT_GE(near, 4);
  EXPECT_TRUE(tc->validate().ok()) << tc->validate().summary();
}

TEST(TcVertexInterfaces, AnEdgeACoarseCellSharesWithFinerClothTakesTheFinerStiffness) {
  // A 3 x 3 group of level-1 blocks in a fine 17^2 net, calibrated: a link between two of its blocks is the edge of
  // two coarse cells where the group's blocks lie on both sides of it, and of a coarse and a fine cell on the group's
  // low sides, where it takes the finer level's stiffness (edge_material).
  const auto net = testing::square_net(17, kAllCorners, RestPlacement::kVertex);
  TcSettings settings;
  settings.interfaces = Interfaces::kHanging;
  settings.level_stiffness = {0.5, 0.25};
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
  const LodTree& tree = net->lod();
  for (bool began = true; began;) {
    began = false;
    for (int gy = 2; gy < 5; ++gy)
      for (int gx = 2; gx < 5; ++gx)
        if (tc.can_coarsen(tree.at(1, gx, gy)).ok) {
          tc.begin_coarse(tree.at(1, gx, gy));
          began = true;
        }
    while (tc.interpolations() > 0) tc.advance_blends();
  }
  const auto stiffness = [&](int ax, int ay, int bx, int by) {
    const TreeId a = tree.at(1, ax, ay), b = tree.at(1, bx, by);
    for (const std::int32_t li : tc.impl().incidence(a))
      if (tc.cut_links()[static_cast<std::size_t>(li)].other(a) == b) return tc.m_links[li].m_material->m_kLST;
    ADD_FAILURE() << "no link between the blocks";
    return btScalar(0);
  };
  EXPECT_EQ(stiffness(3, 3, 4, 3), 0.5f);  // the group's blocks above and below it
  EXPECT_EQ(stiffness(3, 3, 3, 4), 0.5f);  // ... to its left and right
  EXPECT_EQ(stiffness(2, 2, 3, 2), 1.0f);  // the group's bottom row: fine cloth below
  EXPECT_EQ(stiffness(2, 2, 2, 3), 1.0f);  // its left column: fine cloth to the left
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

TEST(TcVertexInterfaces, ANetAtRestWithVertexInterfacesStaysAtRest) {
  WorldSettings no_gravity;
  no_gravity.gravity = 0;
  SceneWorld world(no_gravity);
  for (const bool left : {true, false}) {
    const auto tc = half_coarse(world, left);
    for (int s = 0; s < 50; ++s) tc->simulate_step(btScalar(1.0 / 60));
    double drift = 0;
    for (int i = 0; i < tc->node_count(); ++i) {
      const Eigen::Vector3d& rest = tc->net().lod().rest(tc->tree_id(i));
      const btVector3& x = tc->m_nodes[i].m_x;
      drift = std::max(drift, (Eigen::Vector3d(x.x(), x.y(), x.z()) - rest).norm());
    }
    EXPECT_LT(drift, 1e-5 * tc->net().extent());
  }
}

}  // namespace
}  // namespace tcsb
