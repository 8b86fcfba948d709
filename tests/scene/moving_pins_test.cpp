// Moving pins and keyframed colliders: the scene's pin path carries every pinned node of a plain body and of a
// TC-SB body alike (bit for bit on the finest cut), operations place pinned nodes where the pins are now, and a
// kinematic collider follows its keyframes.
#include <gtest/gtest.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <memory>
#include <random>

#include "../softbody/test_bodies.h"
#include "feedback/random_policy.h"
#include "net/net.h"
#include "scene/scene_world.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody.h"
#include "softbody/vector_conversion.h"
#include "view/keyframe_path.h"

namespace tcsb {
namespace {

using testing::kDt;

SolverSettings pins_solver() {
  SolverSettings s;
  s.piterations = 4;
  return s;
}

std::shared_ptr<const Net> net_of(int n, unsigned corners, unsigned edges) {
  NetSpec spec;
  spec.width = spec.height = n;
  spec.size_x = spec.size_z = 2.0;
  spec.pinned_corners = corners;
  spec.pinned_edges = edges;
  return std::make_shared<const Net>(spec);
}

/// A rod moved along +x for half a second, then up, then held.
PinPath rod_path() {
  PinPath p;
  p.keyframes = {{0.0, {0, 0, 0}}, {0.5, {0.4, 0, 0}}, {1.0, {0.4, 0.3, 0}}};
  return p;
}

TEST(KeyframePath, LinearBetweenKeyframesAndHeldAtTheEnds) {
  const std::vector<VectorKey> keys = {{1.0, {0, 0, 0}}, {2.0, {2, 4, -2}}, {4.0, {2, 0, 0}}};
  EXPECT_EQ(value_at(keys, 0.0), (std::array<double, 3>{0, 0, 0}));  // held before the first
  EXPECT_EQ(value_at(keys, 1.5), (std::array<double, 3>{1, 2, -1}));
  EXPECT_EQ(value_at(keys, 2.0), (std::array<double, 3>{2, 4, -2}));
  EXPECT_EQ(value_at(keys, 3.0), (std::array<double, 3>{2, 2, -1}));
  EXPECT_EQ(value_at(keys, 9.0), (std::array<double, 3>{2, 0, 0}));  // held after the last
  const KeyframeSpan s = keyframe_span(keys, 3.5);
  EXPECT_EQ(s.from, 1u);
  EXPECT_EQ(s.to, 2u);
  EXPECT_DOUBLE_EQ(s.weight, 0.75);
}

TEST(MovingPins, PlainAndTreeCutPinsFollowThePathAndTheFinestCutStepsBitForBitLikePlain) {
  SceneSettings scene;
  scene.pin_path = rod_path();
  SceneWorld world(WorldSettings{}, scene);
  const auto net = net_of(17, 0, kEdgeMinZ);
  const auto plain = make_plain_softbody(world.info(), *net, pins_solver());
  TcSoftBody tc(world.info(), net, pins_solver(), {});
  const SceneWorld::Attachment a = world.attach(*plain), b = world.attach(tc);
  for (int step = 1; step <= 90; ++step) {  // 1.5 s: past the last keyframe
    tc.advance_blends();
    world.step(kDt);
    const btVector3 offset = to_bullet(Eigen::Vector3d(scene.pin_path.offset_at(step * WorldSettings{}.dt).data()));
    ASSERT_EQ(tc.pin_offset(), offset);
    for (std::size_t i = 0; i < net->node_count(); ++i) {
      const int n = static_cast<int>(i);
      ASSERT_EQ(tc.m_nodes[n].m_x, plain->m_nodes[n].m_x) << "step " << step << " node " << i;
      ASSERT_EQ(tc.m_nodes[n].m_v, plain->m_nodes[n].m_v) << "step " << step << " node " << i;
      if (!net->pinned()[i]) continue;
      const btVector3 expected = to_bullet(net->rest_positions()[i]) + offset;
      ASSERT_LT((plain->m_nodes[n].m_x - expected).length(), 1e-6f) << "step " << step << " node " << i;
    }
  }
  const Validation v = tc.validate();
  EXPECT_TRUE(v.ok()) << v.summary();
  // Held after the last keyframe, with the cloth swinging from the moved edge.
  EXPECT_EQ(tc.pin_offset(), btVector3(0.4f, 0.3f, 0));
  const std::size_t far = static_cast<std::size_t>(net->index(8, 16));
  EXPECT_GT((plain->m_nodes[static_cast<int>(far)].m_x - to_bullet(net->rest_positions()[far])).length(), 0.5f);
}

TEST(MovingPins, AConstantVelocityCarriesThePinsInACollisionWorldToo) {
  SceneSettings scene;
  scene.pin_path.velocity = {0, 0.5, 0.25};
  Collider floor;
  floor.shape = ColliderShape::kPlane;
  floor.position = {0, -5, 0};
  scene.colliders.push_back(floor);
  SceneWorld world(WorldSettings{}, scene);
  const auto net = net_of(9, kAllCorners, 0);
  const auto plain = make_plain_softbody(world.info(), *net, pins_solver());
  const SceneWorld::Attachment a = world.attach(*plain);
  for (int step = 0; step < 60; ++step) world.step(kDt);
  const int corner = net->index(8, 8);
  const btVector3 expected =
      to_bullet(net->rest_positions()[static_cast<std::size_t>(corner)]) + btVector3(0, 0.5f, 0.25f);
  EXPECT_LT((plain->m_nodes[corner].m_x - expected).length(), 1e-5f);
}

/// The simulated pinned node a corner leaf is represented by (itself or the block resting on it).
TreeId simulated_pin(const TcSoftBody& tc, TreeId leaf) {
  TreeId id = leaf;
  while (id != kNoTreeNode && tc.bullet_index(id) < 0) id = tc.tree().node(id).parent;
  return id;
}

TEST(MovingPins, CoarseningAndRefiningAtAMovingPinPlaceItsNodeWhereThePinIsNow) {
  SceneSettings scene;
  scene.pin_path.velocity = {0.3, 0.2, 0};
  SceneWorld world(WorldSettings{}, scene);
  const auto net = net_of(17, kAllCorners, 0);
  TcSettings settings;
  settings.blend_steps = 2;
  TcSoftBody tc(world.info(), net, pins_solver(), settings);
  const SceneWorld::Attachment a = world.attach(tc);
  const auto run = [&](int steps) {
    for (int s = 0; s < steps; ++s) {
      tc.advance_blends();
      world.step(kDt);
    }
  };
  run(30);
  const TreeId corner = net->index(0, 0);
  const TreeId block = tc.tree().node(corner).parent;
  ASSERT_EQ(tc.tree().node(block).anchor_leaf, corner);
  ASSERT_TRUE(tc.can_coarsen(block).ok);
  tc.begin_coarse(block);
  const btVector3 moved = tc.pin_position(block);
  EXPECT_GT((moved - to_bullet(net->rest_positions()[0])).length(), 0.1f);  // the pin has moved away from rest
  EXPECT_EQ(tc.m_nodes[tc.bullet_index(block)].m_x, moved);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  run(10);
  ASSERT_EQ(simulated_pin(tc, corner), block);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  ASSERT_TRUE(tc.can_refine(block).ok);
  tc.begin_refine(block);
  EXPECT_EQ(tc.m_nodes[tc.bullet_index(corner)].m_x, tc.pin_position(corner));
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  run(10);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

TEST(MovingPins, RandomOperationsUnderMovingPinsKeepEveryInvariant) {
  SceneSettings scene;
  scene.pin_path = rod_path();
  SceneWorld world(WorldSettings{}, scene);
  const auto net = net_of(17, kCornerMinMin | kCornerMaxMin, 0);
  TcSettings settings;
  settings.blend_steps = 3;
  TcSoftBody tc(world.info(), net, pins_solver(), settings);
  const SceneWorld::Attachment a = world.attach(tc);
  RandomPolicy policy(3);
  std::mt19937 rng(4);
  for (int step = 0; step < 150; ++step) {
    tc.advance_blends();
    policy.apply(tc, 40 + static_cast<int>(rng() % 200), 16);
    world.step(kDt);
    if (step % 10 == 9) {
      const Validation v = tc.validate();
      ASSERT_TRUE(v.ok()) << "after step " << step << ": " << v.summary();
    }
  }
}

TEST(KinematicCollider, AKeyframedBoxFollowsItsPath) {
  SceneSettings scene;
  Collider box;
  box.shape = ColliderShape::kBox;
  box.motion = ColliderMotion::kKinematic;
  box.half_extents = {0.2, 0.2, 0.2};
  box.path = {{0.0, {0, -1, 0}}, {1.0, {1, -1, 0}}, {2.0, {1, -1, 2}}};
  box.position = value_at(box.path, 0);  // as the parser sets it
  scene.colliders.push_back(box);
  SceneWorld world(WorldSettings{}, scene);
  const auto net = net_of(5, kAllCorners, 0);
  const auto plain = make_plain_softbody(world.info(), *net, pins_solver());
  const SceneWorld::Attachment a = world.attach(*plain);
  const auto centre = [&] { return world.dynamics()->getCollisionObjectArray()[0]->getWorldTransform().getOrigin(); };
  for (int s = 0; s < 30; ++s) world.step(kDt);  // 0.5 s
  EXPECT_LT((centre() - btVector3(0.5f, -1, 0)).length(), 1e-5f);
  for (int s = 0; s < 60; ++s) world.step(kDt);  // 1.5 s
  EXPECT_LT((centre() - btVector3(1, -1, 1)).length(), 1e-5f);
  for (int s = 0; s < 60; ++s) world.step(kDt);  // 2.5 s: held at the last keyframe
  EXPECT_LT((centre() - btVector3(1, -1, 2)).length(), 1e-5f);
}

}  // namespace
}  // namespace tcsb
