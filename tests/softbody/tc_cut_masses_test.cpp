// Masses that follow the cut (TcSettings::masses = Masses::kCut, tc_cut_masses.cpp).
#include <gtest/gtest.h>

#include <stdexcept>

#include "scene/scene_world.h"
#include "softbody/tc_softbody.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

TcSettings cut_mass_settings() {
  TcSettings settings;
  settings.masses = Masses::kCut;
  return settings;
}

TEST(TcCutMasses, NeedBlocksRestingOnTheirFirstLeaf) {
  SceneWorld world({});
  EXPECT_THROW(TcSoftBody(world.info(), testing::square_net(17), testing::test_solver(), cut_mass_settings()),
               std::invalid_argument);
}

TEST(TcCutMasses, TheFinestCutCarriesTheLeavesMassesExactly) {
  const auto net = testing::square_net(17, kAllCorners, RestPlacement::kVertex);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), cut_mass_settings());
  for (int i = 0; i < tc.node_count(); ++i) ASSERT_EQ(tc.simulated_mass(tc.tree_id(i)), net->masses()[0]);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

TEST(TcCutMasses, AWholeLevelCutCarriesALumpedMassMatrixsMasses) {
  // On a (2^k + 1)-wide net a whole level-L cut is the evenly spaced sub-grid of spacing s = 2^L: each node carries
  // the leaves within s of it along each axis, weighted by the hat functions between the nodes, so an interior node
  // s^2 leaves, an edge node s (s + 1) / 2 and a corner ((s + 1) / 2)^2, where block sums would give the first row s^2
  // and the last row s.
  const auto net = testing::square_net(33, 0, RestPlacement::kVertex);
  const double leaf = net->masses()[0];
  SceneWorld world({});
  for (const int level : {1, 2}) {
    SCOPED_TRACE("level " + std::to_string(level));
    TcSoftBody tc(world.info(), net, testing::test_solver(), cut_mass_settings());
    const int s = 1 << level, nodes = 32 / s + 1;
    ASSERT_EQ(tc.coarsen_to_level(level), nodes * nodes);
    const double interior = s * s, edge = s * (s + 1) / 2.0, corner = (s + 1) * (s + 1) / 4.0;
    for (int i = 0; i < tc.node_count(); ++i) {
      const LodNode& n = net->lod().node(tc.tree_id(i));
      const int gx = n.leaf_x0 / s, gz = n.leaf_y0 / s;
      const int on_edges = (gx == 0 || gx == nodes - 1) + (gz == 0 || gz == nodes - 1);
      const double expected = on_edges == 0 ? interior : on_edges == 1 ? edge : corner;
      EXPECT_NEAR(tc.simulated_mass(tc.tree_id(i)), expected * leaf, 1e-12) << "node at " << gx << ", " << gz;
    }
    EXPECT_NEAR(tc.total_mass(), net->total_mass(), 1e-12);
    EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  }
}

TEST(TcCutMasses, ABoundaryBetweenLevelsSharesTheCoarseSideAsItsInterpolationDoes) {
  // One level-1 block coarsened inside a fine net, resting on its first leaf: of its four leaves, bilinear weights
  // give its node 1 + 1/2 + 1/2 + 1/4 = 9/4 of a leaf, the fine nodes at its +x and +z corners 1/2 + 1/4 each and
  // the one at its diagonal corner 1/4, on top of their own.
  const auto net = testing::square_net(17, 0, RestPlacement::kVertex);
  const double leaf = net->masses()[0];
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), cut_mass_settings());
  const TreeId p = net->lod().at(1, 3, 3);  // leaves 6..7 x 6..7, resting on leaf (6, 6)
  tc.begin_coarse(p);
  while (tc.interpolations() > 0) tc.advance_blends();
  EXPECT_NEAR(tc.simulated_mass(p), 2.25 * leaf, 1e-12);
  EXPECT_NEAR(tc.simulated_mass(net->index(8, 6)), 1.75 * leaf, 1e-12);
  EXPECT_NEAR(tc.simulated_mass(net->index(6, 8)), 1.75 * leaf, 1e-12);
  EXPECT_NEAR(tc.simulated_mass(net->index(8, 8)), 1.25 * leaf, 1e-12);
  EXPECT_NEAR(tc.simulated_mass(net->index(7, 8)), leaf, 1e-12);  // beside the corner, untouched
  EXPECT_NEAR(tc.total_mass(), net->total_mass(), 1e-12);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

}  // namespace
}  // namespace tcsb
