// Pins beyond the corners: an edge and listed grid nodes hold fixed in the plain body, CreatePatch's and TC-SB
// under random operations (blocks holding two or more pinned leaves are never simulated, so along a pinned edge the
// cut stays fine).
#include <gtest/gtest.h>

#include <random>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

std::shared_ptr<const Net> net_pinned(int width, unsigned edges, std::vector<GridNode> nodes) {
  NetSpec spec;
  spec.name = "pins";
  spec.width = spec.height = width;
  spec.pinned_corners = 0;
  spec.pinned_edges = edges;
  spec.pinned_nodes = std::move(nodes);
  return std::make_shared<const Net>(spec);
}

/// Positions of a body's nodes.
std::vector<btVector3> positions(const btSoftBody& body) {
  std::vector<btVector3> x;
  for (int i = 0; i < body.m_nodes.size(); ++i) x.push_back(body.m_nodes[i].m_x);
  return x;
}

/// Every pinned grid node of a stock body of `net` (node i = grid node i) is where it started, with zero inverse
/// mass; every other node has moved.
void expect_only_pins_held(const btSoftBody& body, const Net& net, const std::vector<btVector3>& start) {
  for (std::size_t i = 0; i < net.node_count(); ++i) {
    const btSoftBody::Node& n = body.m_nodes[static_cast<int>(i)];
    if (net.pinned()[i]) {
      EXPECT_EQ(n.m_im, 0) << "node " << i;
      EXPECT_EQ(n.m_x, start[i]) << "node " << i;
    } else {
      EXPECT_GT(n.m_im, 0) << "node " << i;
      EXPECT_NE(n.m_x, start[i]) << "node " << i;
    }
  }
}

TEST(TcPins, AnEdgePinnedPlainBodyAndCreatePatchHoldTheEdgeAndSwingTheRest) {
  const auto net = net_pinned(17, kEdgeMinZ, {});
  SceneWorld world({});
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  auto patch = make_bullet_patch(world.info(), *net, testing::test_solver());
  const std::vector<btVector3> plain_start = positions(*plain), patch_start = positions(*patch);
  for (int s = 0; s < 60; ++s) {
    step_soft_body(*plain, kDt);
    step_soft_body(*patch, kDt);
  }
  expect_only_pins_held(*plain, *net, plain_start);
  expect_only_pins_held(*patch, *net, patch_start);
  const int far = net->index(8, 16);  // the far edge hangs down
  EXPECT_LT(plain->m_nodes[far].m_x.y(), plain_start[static_cast<std::size_t>(far)].y() - 1.0);
}

/// Random operations on `net` for `steps` steps, validating every 10 (validate() checks that every simulated pinned
/// node is at rest); at the end every pinned leaf is simulated itself or by the block resting on it. Returns how
/// many pinned leaves were simulated themselves.
int random_operations_hold_the_pins(const std::shared_ptr<const Net>& net, int steps) {
  SceneWorld world({});
  TcSettings settings;
  settings.blend_steps = 3;
  TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
  RandomPolicy policy(7);
  std::mt19937 rng(11);
  for (int step = 0; step < steps; ++step) {
    tc.advance_blends();
    policy.apply(tc, 40 + static_cast<int>(rng() % 250), 16);
    tc.simulate_step(kDt);
    if (step % 10 == 9) {
      const Validation v = tc.validate();
      EXPECT_TRUE(v.ok()) << "after step " << step << ": " << v.summary();
      if (!v.ok()) return -1;
    }
  }
  int simulated = 0;
  for (std::size_t i = 0; i < net->node_count(); ++i) {
    if (!net->pinned()[i]) continue;
    const TreeId leaf = static_cast<TreeId>(i);
    if (tc.bullet_index(leaf) >= 0) {
      ++simulated;
      continue;
    }
    TreeId up = tc.tree().node(leaf).parent;
    while (up != kNoTreeNode && tc.bullet_index(up) < 0) up = tc.tree().node(up).parent;
    EXPECT_NE(up, kNoTreeNode) << "pinned leaf " << leaf << " is not simulated";
    if (up != kNoTreeNode) {
      EXPECT_EQ(tc.tree().node(up).anchor_leaf, leaf) << "block " << up;
    }
  }
  return simulated;
}

TEST(TcPins, AlongAPinnedEdgeTheCutStaysFineUnderRandomOperations) {
  const auto net = net_pinned(17, kEdgeMaxX, {});
  // Every block along the edge holds two or more of its pinned leaves and may not be simulated, except a block
  // with a single leaf of the edge (at the corner, where a level's last row of blocks is one leaf tall): at least
  // the other 16 leaves of the edge are simulated themselves, at rest.
  EXPECT_GE(random_operations_hold_the_pins(net, 400), 16);
}

TEST(TcPins, ListedPinsHoldUnderRandomOperations) {
  // An interior pin and one on the border: blocks holding one of them rest on it (and may coarsen), as at a corner.
  const auto net = net_pinned(17, 0, {{8, 8}, {0, 5}, {13, 2}});
  EXPECT_GE(random_operations_hold_the_pins(net, 400), 0);
}

}  // namespace
}  // namespace tcsb
