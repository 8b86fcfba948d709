// Resolution-consistent material: with TcSettings::level_stiffness every link uses the material of its coarser
// endpoint's level, fading links fade from that constant, the invariants hold through random operations, and a
// calibration of all 1s is the uncalibrated body exactly (the materials change nothing but the constants).
#include <gtest/gtest.h>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody_impl.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

/// Node positions and velocities equal bit for bit.
bool same_state(const btSoftBody& a, const btSoftBody& b) {
  if (a.m_nodes.size() != b.m_nodes.size()) return false;
  for (int i = 0; i < a.m_nodes.size(); ++i)
    if (a.m_nodes[i].m_x != b.m_nodes[i].m_x || a.m_nodes[i].m_v != b.m_nodes[i].m_v) return false;
  return true;
}

void run_random(TcSoftBody& body, std::uint64_t seed, int steps) {
  RandomPolicy policy(seed);
  for (int s = 0; s < steps; ++s) {
    body.advance_blends();
    policy.apply(body, 200, 24);
    body.simulate_step(kDt);
  }
}

TEST(TcLevelStiffness, UncalibratedUsesTheOneMaterial) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  EXPECT_FALSE(tc.impl().calibrated());
  run_random(tc, 5, 40);
  EXPECT_EQ(tc.m_materials.size(), 1);
  for (int i = 0; i < tc.link_count(); ++i) EXPECT_EQ(tc.m_links[i].m_material, tc.m_materials[0]);
}

TEST(TcLevelStiffness, EveryLinkUsesItsCoarserEndpointsLevelAndFadesFromIt) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSettings settings;
  settings.level_stiffness = {0.5, 0.25};  // level 1, then level 2 and beyond
  TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
  ASSERT_TRUE(tc.impl().calibrated());
  RandomPolicy policy(11);
  int checked_blends = 0, coarse_links = 0;
  for (int s = 0; s < 120; ++s) {
    tc.advance_blends();
    policy.apply(tc, 250, 32);
    for (int i = 0; i < tc.link_count(); ++i) {
      const CutLink& meta = tc.cut_links()[static_cast<std::size_t>(i)];
      const int level = std::max(net->lod().node(meta.a).level, net->lod().node(meta.b).level);
      const double expected = level == 0 ? 1.0 : level == 1 ? 0.5 : 0.25;
      const btSoftBody::Link& l = tc.m_links[i];
      ASSERT_EQ(l.m_material->m_kLST, static_cast<btScalar>(expected)) << "link " << i << " level " << level;
      if (level > 0) ++coarse_links;
      if (meta.role == LinkRole::kFadeIn && level > 0) {
        // c0 = (im_a + im_b) / (kLST_level alpha): the fade starts from the level's own constant.
        const btScalar steady = (l.m_n[0]->m_im + l.m_n[1]->m_im) / static_cast<btScalar>(expected);
        EXPECT_GT(l.m_c0, steady);
        ++checked_blends;
      }
    }
    tc.simulate_step(kDt);
    if (s % 20 == 0) {
      ASSERT_TRUE(tc.validate().ok()) << tc.validate().summary();
    }
  }
  EXPECT_GT(coarse_links, 0);
  EXPECT_GT(checked_blends, 0);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

TEST(TcLevelStiffness, AllOnesIsTheUncalibratedBodyBitForBit) {
  const auto net = testing::square_net(33);
  SceneWorld world_a({}), world_b({});
  TcSoftBody plain_material(world_a.info(), net, testing::test_solver(), {});
  TcSettings ones;
  ones.level_stiffness = {1.0};
  TcSoftBody calibrated(world_b.info(), net, testing::test_solver(), ones);
  run_random(plain_material, 9, 80);
  run_random(calibrated, 9, 80);
  EXPECT_TRUE(same_state(plain_material, calibrated));
}

TEST(TcLevelStiffness, ASofterLevelChangesTheMotion) {
  const auto net = testing::square_net(33);
  SceneWorld world_a({}), world_b({});
  TcSoftBody plain_material(world_a.info(), net, testing::test_solver(), {});
  TcSettings soft;
  soft.level_stiffness = {0.4};
  TcSoftBody calibrated(world_b.info(), net, testing::test_solver(), soft);
  run_random(plain_material, 9, 80);
  run_random(calibrated, 9, 80);
  EXPECT_FALSE(same_state(plain_material, calibrated));
}

TEST(TcLevelStiffness, RefusesAStiffnessOutsideZeroToOne) {
  const auto net = testing::square_net(9);
  SceneWorld world({});
  for (const double bad : {0.0, -0.5, 1.5}) {
    TcSettings settings;
    settings.level_stiffness = {0.5, bad};
    EXPECT_THROW(TcSoftBody(world.info(), net, testing::test_solver(), settings), std::invalid_argument) << bad;
  }
}

}  // namespace
}  // namespace tcsb
