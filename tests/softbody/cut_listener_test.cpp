// What a CutListener hears of a TC-SB body's cut.
#include "softbody/cut_listener.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "scene/scene_world.h"
#include "softbody/tc_softbody.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

struct RecordingListener : CutListener {
  void cut_changed(OpKind kind, TreeId block) override { changes.emplace_back(kind, block); }
  void arrays_reordered() override { ++reorders; }
  std::vector<std::pair<OpKind, TreeId>> changes;
  int reorders = 0;
};

TEST(CutListener, HearsEveryOperationWithItsBlockAndEveryReordering) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSettings settings;
  settings.blend_steps = 2;
  TcSoftBody body(world.info(), net, testing::test_solver(), settings);
  RecordingListener listener;
  body.set_cut_listener(&listener);
  const TreeId block = body.tree().at(1, 3, 3);
  ASSERT_TRUE(body.can_coarsen(block).ok);
  body.begin_coarse(block);
  ASSERT_EQ(listener.changes.size(), 1u);
  EXPECT_EQ(listener.changes[0], std::make_pair(OpKind::kCoarse, block));
  while (body.interpolations() > 0) body.advance_blends();
  ASSERT_EQ(listener.changes.size(), 2u);
  EXPECT_EQ(listener.changes[1], std::make_pair(OpKind::kEndCoarse, block));
  ASSERT_TRUE(body.can_refine(block).ok);
  body.begin_refine(block);
  while (body.interpolations() > 0) body.advance_blends();
  ASSERT_EQ(listener.changes.size(), 4u);
  EXPECT_EQ(listener.changes[2], std::make_pair(OpKind::kRefine, block));
  EXPECT_EQ(listener.changes[3], std::make_pair(OpKind::kEndRefine, block));
  EXPECT_EQ(listener.reorders, 0);
  body.restore_order();
  EXPECT_EQ(listener.reorders, 1);
  body.set_cut_listener(nullptr);
  body.begin_coarse(block);
  EXPECT_EQ(listener.changes.size(), 4u);
}

}  // namespace
}  // namespace tcsb
