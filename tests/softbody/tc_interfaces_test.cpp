// Hanging interfaces (TcSettings::interfaces = kHanging): each fan becomes one constraint, validate() watches it, the
// projection conserves momentum, and both ways a body is stepped (solo, and in a world through TcSoftBodySolver)
// project it. (Without interfaces the body steps as Bullet's: tc_softbody_test.cpp.)
#include <gtest/gtest.h>

#include <cstring>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody_impl.h"
#include "softbody/tc_softbody_solver.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

TcSettings hanging() {
  TcSettings s;
  s.interfaces = Interfaces::kHanging;
  return s;
}

/// Coarsens one level-1 block in the middle of a 17^2 net and lets its blend end: a level-1 node among leaves, with
/// two leaves facing each of its four sides.
TreeId coarsen_one_block(TcSoftBody& tc) {
  const TreeId parent = tc.tree().at(1, 3, 3);
  EXPECT_TRUE(tc.can_coarsen(parent).ok);
  tc.begin_coarse(parent);
  for (int s = 0; s < tc.settings().blend_steps; ++s) {
    tc.advance_blends();
    tc.simulate_step(kDt);
  }
  EXPECT_EQ(tc.state(parent), CutState::kActive);
  return parent;
}

/// Links of `id` to nodes of another level, and how many of them Bullet's link solver solves (m_c0 > 0).
std::pair<int, int> cross_level_links(const TcSoftBody& tc, TreeId id) {
  int links = 0, solved = 0;
  for (const std::int32_t li : tc.impl().incidence(id)) {
    const CutLink& m = tc.cut_links()[static_cast<std::size_t>(li)];
    if (tc.tree().node(m.other(id)).level == tc.tree().node(id).level) continue;
    ++links;
    solved += tc.m_links[li].m_c0 > 0;
  }
  return {links, solved};
}

TEST(TcInterfaces, EachFanBecomesOneConstraintAndTheFansAreLeftToTheSolverWithoutThem) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody fans(world.info(), net, testing::test_solver(), {});
  TcSoftBody hung(world.info(), net, testing::test_solver(), hanging());
  const TreeId p = coarsen_one_block(fans);
  ASSERT_EQ(coarsen_one_block(hung), p);

  EXPECT_TRUE(fans.impl().interface_constraints().empty());
  EXPECT_EQ(cross_level_links(fans, p), std::make_pair(8, 8));  // a fan of two links on each of four sides

  ASSERT_EQ(hung.impl().interface_constraints().size(), 4u);
  EXPECT_EQ(cross_level_links(hung, p), std::make_pair(8, 0));  // the same links, now handles Bullet skips
  for (const InterfaceConstraint& c : hung.impl().interface_constraints()) {
    EXPECT_EQ(c.coarse, p);
    EXPECT_EQ(net->lod().node(c.fine[0]).parent, net->lod().node(c.fine[1]).parent);
    // The leaves' midpoint lies one and a half leaf spacings from the block's centre, straight across its side.
    EXPECT_NEAR(c.rest, 1.5 * net->extent() / 16, 1e-5);  // 17 leaves over the extent: 16 spacings
    EXPECT_EQ(c.stiffness, 1.0f);                         // uncalibrated: the solver's
  }
  EXPECT_TRUE(hung.validate().ok()) << hung.validate().summary();

  // Refining the block back leaves no constraint and the plain body's links, all solved by Bullet.
  hung.begin_refine(p);
  for (int s = 0; s < hung.settings().blend_steps; ++s) hung.advance_blends();
  EXPECT_TRUE(hung.impl().interface_constraints().empty());
  EXPECT_EQ(hung.link_count(), 2 * 17 * 16);
  for (int li = 0; li < hung.link_count(); ++li) EXPECT_GT(hung.m_links[li].m_c0, 0) << "link " << li;
  EXPECT_TRUE(hung.validate().ok()) << hung.validate().summary();
}

TEST(TcInterfaces, ValidateCatchesABrokenConstraint) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), hanging());
  coarsen_one_block(tc);
  ASSERT_TRUE(tc.validate().ok()) << tc.validate().summary();
  const int handle = tc.impl().interface_constraints()[0].links[0];
  tc.m_links[handle].m_c0 = 1;  // Bullet's link solver would now pull the fan again
  const Validation broken = tc.validate();
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.summary().find("Bullet's link solver would solve it"), std::string::npos) << broken.summary();
}

TEST(TcInterfaces, ValidateReportsAWorldWhoseSolverCannotProjectThem) {
  // What btSoftRigidDynamicsWorld::addSoftBody does: hand the body the world's soft-body solver.
  const auto net = testing::square_net(9);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), hanging());
  btDefaultSoftBodySolver bullets;
  tc.setSoftBodySolver(&bullets);
  const Validation v = tc.validate();
  ASSERT_FALSE(v.ok());
  EXPECT_NE(v.summary().find("not a tcsb::TcSoftBodySolver"), std::string::npos) << v.summary();
  TcSoftBodySolver ours;
  tc.setSoftBodySolver(&ours);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  // With the paper's fans Bullet's own solver is the right one.
  TcSoftBody fans(world.info(), net, testing::test_solver(), {});
  fans.setSoftBodySolver(&bullets);
  EXPECT_TRUE(fans.validate().ok()) << fans.validate().summary();
}

TEST(TcInterfaces, TheProjectionConservesLinearMomentum) {
  const auto net = testing::square_net(17, 0);  // no pins: momentum is conserved only away from anchors
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), hanging());
  coarsen_one_block(tc);
  // Give the cloth a shear so the constraints have work to do, then step without gravity's impulse in the sum.
  for (int i = 0; i < tc.m_nodes.size(); ++i) tc.m_nodes[i].m_v = btVector3(0, tc.m_nodes[i].m_x.x(), 0);
  const Eigen::Vector3d before = tc.linear_momentum();
  const double weight = tc.total_mass() * 9.81 * kDt;  // what gravity adds per step, along -y
  for (int s = 0; s < 10; ++s) tc.simulate_step(kDt);
  const Eigen::Vector3d after = tc.linear_momentum() + Eigen::Vector3d(0, 10 * weight, 0);
  EXPECT_LT((after - before).norm(), 1e-4 * std::max(1.0, before.norm()));
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

/// How far the coarse node of `tc`'s first interface constraint lies from its rest distance to the fine midpoint,
/// as a fraction of that distance.
double interface_strain(const TcSoftBody& tc) {
  const InterfaceConstraint& c = tc.impl().interface_constraints()[0];
  const btVector3 mid =
      (tc.m_nodes[tc.bullet_index(c.fine[0])].m_x + tc.m_nodes[tc.bullet_index(c.fine[1])].m_x) * btScalar(0.5);
  return std::abs((mid - tc.m_nodes[tc.bullet_index(c.coarse)].m_x).length() - c.rest) / c.rest;
}

TEST(TcInterfaces, APreparationKeptFromTheLastStepIsTheOneMadeAfresh) {
  // prepare_interfaces() keeps the last step's constants on a body no operation touched since: after every step of
  // random operations, with pauses between them, a preparation made afresh must be the one the step used, bit for
  // bit, whether it was kept or made.
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), hanging());
  RandomPolicy policy(4);
  int kept = 0;
  for (int s = 0; s < 240; ++s) {
    tc.advance_blends();
    if ((s / 12) % 2 == 0) policy.apply(tc, (s / 48) % 2 == 0 ? 17 * 17 / 3 : 17 * 17 * 2 / 3, 8);
    kept += tc.impl().interfaces_prepared_ ? 1 : 0;
    tc.simulate_step(kDt);
    const auto used = tc.impl().prepared_interfaces_;
    tc.impl().interfaces_prepared_ = false;
    tc.impl().prepare_interfaces();
    const auto& fresh = tc.impl().prepared_interfaces_;
    ASSERT_EQ(used.size(), fresh.size()) << "step " << s;
    for (std::size_t i = 0; i < used.size(); ++i) {
      ASSERT_EQ(used[i].coarse, fresh[i].coarse) << "step " << s << ", interface " << i;
      ASSERT_EQ(used[i].fine[0], fresh[i].fine[0]) << "step " << s << ", interface " << i;
      ASSERT_EQ(used[i].fine[1], fresh[i].fine[1]) << "step " << s << ", interface " << i;
      ASSERT_EQ(std::memcmp(&used[i].c0, &fresh[i].c0, sizeof(btScalar)), 0) << "step " << s << ", interface " << i;
      ASSERT_EQ(std::memcmp(&used[i].c1, &fresh[i].c1, sizeof(btScalar)), 0) << "step " << s << ", interface " << i;
      ASSERT_EQ(std::memcmp(used[i].inverse_mass.data(), fresh[i].inverse_mass.data(), sizeof(used[i].inverse_mass)), 0)
          << "step " << s << ", interface " << i;
      if (used[i].c0 > 0) {
        ASSERT_EQ(used[i].inverse_mass[0], used[i].coarse->m_im) << "step " << s;
      }
    }
  }
  EXPECT_GT(kept, 40);   // (the pauses: kept often)
  EXPECT_LT(kept, 200);  // (the operations: made often)
  EXPECT_GT(tc.impl().interfaces_.size(), 0u);
}

TEST(TcInterfaces, BothSteppingPathsProjectTheConstraints) {
  // The coarse node's only links to the cloth are handles (m_c0 = 0): if a path skipped the projection, it would fall
  // freely away from the cloth.
  const auto net = testing::square_net(17);
  SceneSettings scene;
  Collider far_away;
  far_away.shape = ColliderShape::kSphere;
  far_away.position = {0, -100, 0};
  far_away.radius = 0.5;
  scene.colliders.push_back(far_away);
  SceneWorld solo({});
  SceneWorld with_world({}, scene);
  ASSERT_NE(with_world.dynamics(), nullptr);
  TcSoftBody a(solo.info(), net, testing::test_solver(), hanging());
  TcSoftBody b(with_world.info(), net, testing::test_solver(), hanging());
  const SceneWorld::Attachment in_solo = solo.attach(a);
  const SceneWorld::Attachment in_world = with_world.attach(b);
  for (TcSoftBody* tc : {&a, &b}) tc->begin_coarse(tc->tree().at(1, 3, 3));
  for (int s = 0; s < 120; ++s) {
    a.advance_blends();
    b.advance_blends();
    solo.step(kDt);
    with_world.step(kDt);
  }
  ASSERT_EQ(a.impl().interface_constraints().size(), 4u);
  ASSERT_EQ(b.impl().interface_constraints().size(), 4u);
  EXPECT_LT(interface_strain(a), 0.1);
  EXPECT_LT(interface_strain(b), 0.1);
  EXPECT_TRUE(a.validate().ok()) << a.validate().summary();
  EXPECT_TRUE(b.validate().ok()) << b.validate().summary();
}

}  // namespace
}  // namespace tcsb
