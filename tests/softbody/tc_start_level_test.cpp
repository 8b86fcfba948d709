// A TC-SB body that starts at a coarse cut (TcSettings::start_level).
#include <gtest/gtest.h>

#include "scene/scene_world.h"
#include "softbody/tc_softbody_impl.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

TEST(TcStartLevel, ABodyStartsAtTheWholeCutOfItsLevelInOrderAndValid) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  for (const int level : {1, 2}) {
    TcSettings settings;
    settings.start_level = level;
    TcSoftBody body(world.info(), net, testing::test_solver(), settings);
    // 33 -> 17 -> 9 nodes a side; each pinned corner's block holds one pinned leaf, so every block coarsens.
    const int side = level == 1 ? 17 : 9;
    EXPECT_EQ(body.committed_count(), side * side) << level;
    EXPECT_EQ(body.node_count(), side * side) << level;
    EXPECT_EQ(body.interpolations(), 0) << level;
    EXPECT_EQ(body.impl().displaced(), 0) << level;  // its arrays in a plain body's order from the start
    for (int i = 0; i < body.node_count(); ++i)
      ASSERT_EQ(body.tree().node(body.tree_id(i)).level, level) << "node " << i;
    const Validation v = body.validate();
    EXPECT_TRUE(v.ok()) << v.summary();
  }
}

TEST(TcStartLevel, StartingCoarseIsCoarseningAtOnceAfterBuildingFine) {
  // The same cut and the same node positions as coarsen_to_level on a body built at the finest cut: the start
  // only adds the array order and the compact node tree, which move no node.
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSettings coarse_start;
  coarse_start.start_level = 1;
  TcSoftBody started(world.info(), net, testing::test_solver(), coarse_start);
  TcSoftBody coarsened(world.info(), net, testing::test_solver(), {});
  coarsened.coarsen_to_level(1);
  ASSERT_EQ(started.node_count(), coarsened.node_count());
  for (int i = 0; i < coarsened.node_count(); ++i) {
    const TreeId id = coarsened.tree_id(i);
    ASSERT_EQ(started.state(id), CutState::kActive) << id;
    EXPECT_EQ(started.m_nodes[started.bullet_index(id)].m_x, coarsened.m_nodes[i].m_x) << id;
  }
}

TEST(TcStartLevel, ALevelPastTheCoarsestStartsAtTheCoarsestSimulableCut) {
  const auto net = testing::square_net(9);  // levels 9, 5, 3, 2, 1 nodes a side
  SceneWorld world({});
  TcSettings settings;
  settings.start_level = 30;
  TcSoftBody body(world.info(), net, testing::test_solver(), settings);
  // Blocks holding two pinned corners may not be simulated: the coarsest cut keeps the 2 x 2 of level 3.
  EXPECT_EQ(body.committed_count(), 4);
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
}

}  // namespace
}  // namespace tcsb
