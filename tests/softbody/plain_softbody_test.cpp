#include "softbody/plain_softbody.h"

#include <gtest/gtest.h>

#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/divergence.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

TEST(PlainSoftBody, HasTheNetsNodesLinksAndPins) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  auto body = make_plain_softbody(world.info(), *net, testing::test_solver());
  EXPECT_EQ(body->m_nodes.size(), 17 * 17);
  EXPECT_EQ(body->m_links.size(), 2 * 17 * 16);
  EXPECT_EQ(body->m_faces.size(), 0);
  EXPECT_FALSE(body->m_bUpdateRtCst);
  EXPECT_EQ(body->m_nodes[0].m_im, 0);
  EXPECT_EQ(body->m_nodes[16].m_im, 0);
  EXPECT_GT(body->m_nodes[1].m_im, 0);
  EXPECT_EQ(body->m_cfg.piterations, 2);
  EXPECT_EQ(body->m_cfg.collisions, 0);
}

TEST(PlainSoftBody, MatchesStockCreatePatchTrajectory) {
  // Same grid, pins, link order and solver: the plain baseline and stock CreatePatch must swing the same way
  // (CreatePatch computes positions by a different lerp, hence a tolerance).
  const auto net = testing::square_net(17);
  SceneWorld world({});
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  auto patch = make_bullet_patch(world.info(), *net, testing::test_solver());
  ASSERT_EQ(plain->m_nodes.size(), patch->m_nodes.size());
  ASSERT_EQ(plain->m_links.size(), patch->m_links.size());
  for (int s = 0; s < 100; ++s) {
    step_soft_body(*plain, 1.0f / 60);
    step_soft_body(*patch, 1.0f / 60);
  }
  double worst = 0;
  for (int i = 0; i < plain->m_nodes.size(); ++i)
    worst = std::max<double>(worst, (plain->m_nodes[i].m_x - patch->m_nodes[i].m_x).length());
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT((plain->m_nodes[8 * 17 + 8].m_x - btVector3(0, 8, 0)).length(), 0.1) << "the net must have sagged";
}

TEST(Divergence, QuickAndFullChecksCatchNaNAndStretch) {
  const auto net = testing::square_net(9);
  SceneWorld world({});
  auto body = make_plain_softbody(world.info(), *net, testing::test_solver());
  step_soft_body(*body, 1.0f / 60);
  EXPECT_FALSE(quick_divergence_check(*body, 80.0));
  EXPECT_FALSE(full_divergence_check(*body, 16.0));
  body->m_nodes[40].m_x.setX(1e6f);
  EXPECT_TRUE(full_divergence_check(*body, 16.0));
  body->m_nodes[40].m_x.setX(std::numeric_limits<float>::quiet_NaN());
  EXPECT_TRUE(full_divergence_check(*body, 16.0));
}

}  // namespace
}  // namespace tcsb
