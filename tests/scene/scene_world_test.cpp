// The scene seam: without colliders a world steps its body exactly as the solo step always did; with them the cloth
// meets rigid bodies — it drapes over a static sphere instead of falling through, catches a dynamic ball, is pushed
// by a kinematic box — and a TC-SB body under its controller keeps every invariant in a collision world, with the
// contact feature putting its detail where the cloth touches the sphere.
#include "scene/scene_world.h"

#include <gtest/gtest.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <cmath>
#include <memory>
#include <string>
#include <tuple>

#include "../softbody/test_bodies.h"
#include "case/state_hash.h"
#include "feedback/controller.h"
#include "net/net.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody.h"

namespace tcsb {
namespace {

using testing::kDt;

SolverSettings sheet_solver() {
  SolverSettings s;
  s.piterations = 8;
  return s;
}

/// A free square sheet of `n` x `n` nodes, `size` metres wide, lying flat at height `y`.
std::shared_ptr<const Net> sheet(int n, double size, double y, unsigned pins = 0) {
  NetSpec spec;
  spec.width = spec.height = n;
  spec.size_x = spec.size_z = size;
  spec.elevation = y;
  spec.pinned_corners = pins;
  return std::make_shared<const Net>(spec);
}

Collider sphere(double radius, std::array<double, 3> at) {
  Collider c;
  c.shape = ColliderShape::kSphere;
  c.radius = radius;
  c.position = at;
  return c;
}

/// Lowest node height of a body.
double lowest(const btSoftBody& body) {
  double y = 1e300;
  for (int i = 0; i < body.m_nodes.size(); ++i) y = std::min(y, static_cast<double>(body.m_nodes[i].m_x.y()));
  return y;
}

/// The deepest any node of `body` lies inside the world's colliders, metres.
double deepest(const SceneWorld& world, const btSoftBody& body) {
  double d = -1e300;
  for (int i = 0; i < body.m_nodes.size(); ++i) d = std::max(d, world.penetration(body.m_nodes[i].m_x));
  return d;
}

TEST(SceneWorld, WithoutCollidersTheWorldStepsExactlyAsTheSoloStep) {
  const auto net = sheet(17, 2.0, 1.0, kAllCorners);
  SceneWorld world(WorldSettings{});
  EXPECT_EQ(world.info().m_broadphase, nullptr);  // no collision world at all
  const auto stepped = make_plain_softbody(world.info(), *net, sheet_solver());
  const SceneWorld::Attachment attachment = world.attach(*stepped);
  SceneWorld other(WorldSettings{});
  const auto solo = make_plain_softbody(other.info(), *net, sheet_solver());
  for (int s = 0; s < 60; ++s) {
    world.step(kDt);
    step_soft_body(*solo, kDt);
  }
  EXPECT_EQ(world.steps(), 60);
  EXPECT_EQ(state_hash(*stepped), state_hash(*solo));
  EXPECT_EQ(stepped->m_cfg.collisions, 0);  // attach changes nothing without colliders
}

TEST(SceneWorld, PenetrationDepthOfEachShape) {
  SceneSettings scene;
  scene.colliders.push_back(sphere(1.0, {0, 0, 0}));
  Collider box;
  box.shape = ColliderShape::kBox;
  box.half_extents = {1, 2, 3};
  box.position = {10, 0, 0};
  scene.colliders.push_back(box);
  Collider ground;
  ground.shape = ColliderShape::kPlane;
  ground.position = {0, -5, 0};
  scene.colliders.push_back(ground);
  const SceneWorld world(WorldSettings{}, scene);
  EXPECT_NEAR(world.penetration({0, 0.25f, 0}), 0.75, 1e-6);    // in the sphere
  EXPECT_NEAR(world.penetration({10, 1.5f, 0}), 0.5, 1e-6);     // in the box, nearest its top face
  EXPECT_NEAR(world.penetration({30, -5.25f, 0}), 0.25, 1e-6);  // under the plane
  EXPECT_NEAR(world.penetration({0, -3.0f, 0}), -2.0, 1e-6);    // outside all: the sphere and the plane 2 m off
  EXPECT_FALSE(world.penetrated(scene.margin));
  EXPECT_TRUE(world.penetrated(scene.margin * 1.01));
}

TEST(SceneWorld, APlainSheetDrapesOverAStaticSphereInsteadOfFallingThrough) {
  SceneSettings scene;
  scene.colliders.push_back(sphere(0.5, {0, 0, 0}));
  scene.sdf_voxel = 0.05;
  SceneWorld world(WorldSettings{}, scene);
  const auto net = sheet(17, 2.0, 0.8);
  const auto body = make_plain_softbody(world.info(), *net, sheet_solver());
  const SceneWorld::Attachment attachment = world.attach(*body);
  EXPECT_EQ(body->m_cfg.collisions, static_cast<int>(btSoftBody::fCollision::SDF_RS));
  for (int s = 0; s < 120; ++s) world.step(kDt);
  // The middle node rests on the sphere's top, held at about the margin; the edges hang down past it.
  const btVector3 middle = body->m_nodes[static_cast<int>(net->index(8, 8))].m_x;
  EXPECT_NEAR(middle.y(), 0.5 + scene.margin, 0.05);
  EXPECT_LT(lowest(*body), 0.2);
  EXPECT_LT(deepest(world, *body), scene.margin + 0.02);
  EXPECT_GT(body->m_rcontacts.size(), 0);
}

TEST(SceneWorld, WithoutRigidContactTheSheetFallsThroughTheSphere) {
  SceneSettings scene;
  scene.colliders.push_back(sphere(0.5, {0, 0, 0}));
  scene.sdf_voxel = 0.05;
  scene.rigid_contact = false;  // the suite's "collisions": []
  SceneWorld world(WorldSettings{}, scene);
  const auto net = sheet(17, 2.0, 0.8);
  const auto body = make_plain_softbody(world.info(), *net, sheet_solver());
  const SceneWorld::Attachment attachment = world.attach(*body);
  EXPECT_EQ(body->m_cfg.collisions, 0);
  for (int s = 0; s < 60; ++s) world.step(kDt);
  // One second of free fall from 0.8 m: the middle node is far below the sphere, and nothing ever held it.
  EXPECT_LT(body->m_nodes[static_cast<int>(net->index(8, 8))].m_x.y(), -0.5);
  EXPECT_EQ(body->m_rcontacts.size(), 0);
}

TEST(SceneWorld, TheHangingNetCatchesADynamicBall) {
  SceneSettings scene;
  Collider ball = sphere(0.4, {0, 2.0, 0});
  ball.motion = ColliderMotion::kDynamic;
  ball.mass = 0.5;
  ball.velocity = {0, -3, 0};
  scene.colliders.push_back(ball);
  SceneWorld world(WorldSettings{}, scene);
  const auto net = sheet(17, 4.0, 0.0, kAllCorners);
  NetSpec heavy = net->spec();
  heavy.mass = 4.0;
  const Net cloth(heavy);
  const auto body = make_plain_softbody(world.info(), cloth, sheet_solver());
  const SceneWorld::Attachment attachment = world.attach(*body);
  for (int s = 0; s < 180; ++s) world.step(kDt);
  // Free fall would have taken it 45 m down by now; the net holds it a little below its rest plane.
  const btCollisionObjectArray& objects = world.dynamics()->getCollisionObjectArray();
  const btRigidBody* rigid = nullptr;
  for (int i = 0; i < objects.size(); ++i)
    if ((rigid = btRigidBody::upcast(objects[i])) != nullptr) break;
  ASSERT_NE(rigid, nullptr);
  EXPECT_GT(rigid->getWorldTransform().getOrigin().y(), -3.0);
  EXPECT_LT(rigid->getWorldTransform().getOrigin().y(), 0.4);  // it did push the net down
}

TEST(SceneWorld, AKinematicBoxFollowsItsPath) {
  SceneSettings scene;
  Collider box;
  box.shape = ColliderShape::kBox;
  box.motion = ColliderMotion::kKinematic;
  box.half_extents = {0.2, 0.2, 0.2};
  box.position = {0, -1, 0};
  box.velocity = {0, 0.6, 0};
  scene.colliders.push_back(box);
  scene.sdf_voxel = 0.05;
  SceneWorld world(WorldSettings{}, scene);
  const auto net = sheet(17, 2.0, 0.0, kAllCorners);
  const auto body = make_plain_softbody(world.info(), *net, sheet_solver());
  const SceneWorld::Attachment attachment = world.attach(*body);
  for (int s = 0; s < 120; ++s) world.step(kDt);
  // After 2 s the box's centre is at y = 0.2 and its top at 0.4: it has lifted the middle of the sagging net above
  // its rest plane and holds it on its top (later the net, pinned at its corners, slides off the small box).
  EXPECT_NEAR(world.penetration({0, 0.2f, 0}), 0.2, 1e-3);
  EXPECT_GT(body->m_nodes[static_cast<int>(net->index(8, 8))].m_x.y(), 0.35);
  EXPECT_GT(body->m_rcontacts.size(), 0);
}

TEST(SceneWorld, ReleasingAnAttachmentTakesTheBodyOutOfTheWorld) {
  SceneSettings scene;
  scene.colliders.push_back(sphere(0.5, {0, 0, 0}));
  SceneWorld world(WorldSettings{}, scene);
  const auto net = sheet(9, 2.0, 0.8);
  const auto body = make_plain_softbody(world.info(), *net, sheet_solver());
  SceneWorld::Attachment attachment = world.attach(*body);
  EXPECT_EQ(world.dynamics()->getSoftBodyArray().size(), 1);
  attachment.release();
  EXPECT_EQ(world.dynamics()->getSoftBodyArray().size(), 0);
  attachment.release();  // twice is nothing
}

/// Share of the grid points within `radius` of the sphere's top (in the rest plane) that the cut simulates at full
/// resolution (as leaves), against the share elsewhere.
std::pair<double, double> leaf_share_near(const TcSoftBody& body, double radius) {
  const LodTree& tree = body.tree();
  int near = 0, near_leaf = 0, far = 0, far_leaf = 0;
  for (std::size_t leaf = 0; leaf < tree.leaf_count(); ++leaf) {
    const Eigen::Vector3d r = tree.rest(static_cast<TreeId>(leaf));
    const bool is_near = std::hypot(r.x(), r.z()) < radius;
    const bool simulated = body.committed(static_cast<TreeId>(leaf));
    (is_near ? near : far) += 1;
    (is_near ? near_leaf : far_leaf) += simulated ? 1 : 0;
  }
  return {static_cast<double>(near_leaf) / near, static_cast<double>(far_leaf) / far};
}

/// What a TC-SB sheet did, dropped onto a sphere at 30 % of its nodes under the saliency controller.
struct TreeCutDrape {
  double near = 0, far = 0;  ///< leaf_share_near(0.3 m) after the last step
  double deepest = 0;        ///< the deepest any node lay inside the sphere then, metres
  int committed = 0, budget = 0;
  long arriving_node_steps = 0;  ///< node-steps of nodes an operation in flight had added
  long arriving_contacts = 0;    ///< Bullet's rigid contacts, summed over the steps, that held such a node
  std::string broken;            ///< the first validate() failure, with its step; empty when every step held
};

/// A 33 x 33 sheet 20 cm above a 0.5 m sphere, 150 steps driven as the harness drives a case (case/case_body.cpp),
/// validate() after every step.
TreeCutDrape drape_tree_cut_sheet(double contact_saliency, bool arrivals_collide = true) {
  SceneSettings scene;
  scene.colliders.push_back(sphere(0.5, {0, 0, 0}));
  scene.sdf_voxel = 0.05;
  SceneWorld world(WorldSettings{}, scene);
  const auto net = sheet(33, 2.0, 0.7);
  TcSettings settings;
  settings.arrivals_collide = arrivals_collide;
  TcSoftBody body(world.info(), net, sheet_solver(), settings);
  const SceneWorld::Attachment attachment = world.attach(body);
  FeedbackSettings feedback;
  feedback.contact_saliency = contact_saliency;
  TreeCutDrape out;
  out.budget = static_cast<int>(0.3 * static_cast<double>(net->node_count()));
  const auto controller = make_controller(feedback, out.budget, 1);
  for (int s = 0; s < 150 && out.broken.empty(); ++s) {
    body.advance_blends();
    controller->before_step(body);
    world.step(kDt);
    for (int i = 0; i < body.m_nodes.size(); ++i)
      out.arriving_node_steps += body.state(body.tree_ids()[static_cast<std::size_t>(i)]) == CutState::kArriving;
    for (int c = 0; c < body.m_rcontacts.size(); ++c) {
      const auto i = static_cast<std::size_t>(body.m_rcontacts[c].m_node - &body.m_nodes[0]);
      out.arriving_contacts += body.state(body.tree_ids()[i]) == CutState::kArriving;
    }
    controller->after_step(body);
    if (const Validation v = body.validate(); !v.ok()) out.broken = "step " + std::to_string(s) + ": " + v.summary();
  }
  std::tie(out.near, out.far) = leaf_share_near(body, 0.3);
  out.deepest = deepest(world, body);
  out.committed = body.committed_count();
  return out;
}

TEST(SceneWorld, ATreeCutSheetKeepsItsInvariantsInACollisionWorldAndItsDetailAtTheContact) {
  const TreeCutDrape d = drape_tree_cut_sheet(1.0);
  ASSERT_EQ(d.broken, "");
  EXPECT_LE(d.committed, d.budget);
  EXPECT_LT(d.deepest, SceneSettings{}.margin + 0.02);  // TC-SB's nodes collide like plain ones
  // Where the cloth lies on the sphere it is simulated finer than elsewhere. (The contact region is larger than
  // the budget can hold at full resolution, so it is refined evenly, to level 1, where the block sizes weigh the
  // refines: about a quarter of its grid points are simulated.)
  EXPECT_GT(d.near, 0.2);
  EXPECT_GT(d.near, 2.5 * d.far) << "near " << d.near << ", far " << d.far;
}

TEST(SceneWorld, WithoutTheContactFeatureMotionSaliencyCoarsensTheClothRestingOnTheSphere) {
  // What the contact feature is for: cloth at rest on a collider has no relative motion.
  const TreeCutDrape d = drape_tree_cut_sheet(0.0);
  ASSERT_EQ(d.broken, "");
  EXPECT_LT(d.near, d.far);
}

TEST(SceneWorld, UnderThePapersRuleTheNodesAnOperationAddsJoinCollisionsWhenItEnds) {
  // TcSettings::arrivals_collide false (the paper's sections 3.3-3.4): Bullet holds none of the arriving nodes on
  // the sphere, though many arrive where the cloth touches it; by default it holds them from the start.
  const TreeCutDrape paper = drape_tree_cut_sheet(1.0, false);
  ASSERT_EQ(paper.broken, "");  // validate() checks each node's collision state against its operation
  EXPECT_GT(paper.arriving_node_steps, 1000);
  EXPECT_EQ(paper.arriving_contacts, 0);
  const TreeCutDrape ours = drape_tree_cut_sheet(1.0, true);
  EXPECT_GT(ours.arriving_contacts, 0);
}

}  // namespace
}  // namespace tcsb
