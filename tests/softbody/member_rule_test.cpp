// The rule for btSoftBody's members (include/tcsb/tc_softbody.h): a caller may write node positions, velocities
// and forces between steps; every structural write is TcSoftBody's, and validate() names each one a caller makes.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

/// A 33 x 33 body in the middle of its operations: blends in flight, so fading links and half masses exist.
class MemberRule : public ::testing::Test {
 protected:
  MemberRule() : world_(WorldSettings{}), body_(world_.info(), testing::square_net(33), testing::test_solver(), {}) {
    RandomPolicy policy(7);
    for (int step = 0; step < 12; ++step) {
      body_.advance_blends();
      policy.apply(body_, 600, 8);
      body_.simulate_step(kDt);
    }
  }
  /// An unpinned Bullet node.
  int free_node() const {
    for (int i = 0; i < body_.m_nodes.size(); ++i)
      if (body_.m_nodes[i].m_im > 0) return i;
    return -1;
  }
  /// Whether validate() fails with a problem containing `words`.
  ::testing::AssertionResult reports(const std::string& words) const {
    const Validation v = body_.validate();
    if (v.ok()) return ::testing::AssertionFailure() << "validate() found nothing";
    for (const std::string& p : v.problems)
      if (p.find(words) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "validate() said: " << v.summary();
  }

  SceneWorld world_;
  TcSoftBody body_;
};

TEST_F(MemberRule, TheBodyIsMidOperation) {
  EXPECT_GT(body_.interpolations(), 0);
  EXPECT_TRUE(body_.validate().ok()) << body_.validate().summary();
}

TEST_F(MemberRule, WritingPositionsVelocitiesAndForcesIsAllowedAndTheBodyStepsOn) {
  const int i = free_node();
  ASSERT_GE(i, 0);
  body_.m_nodes[i].m_x += btVector3(0, 0.01f, 0);
  body_.m_nodes[i].m_q = body_.m_nodes[i].m_x;
  body_.m_nodes[i].m_v = btVector3(0.5f, 0, 0);
  body_.addForce(btVector3(0, 1, 0), i);
  body_.addVelocity(btVector3(0, 0, 0.1f));
  EXPECT_TRUE(body_.validate().ok()) << body_.validate().summary();
  body_.advance_blends();
  body_.simulate_step(kDt);
  EXPECT_TRUE(body_.validate().ok()) << body_.validate().summary();
}

TEST_F(MemberRule, AnInverseMassWrittenIsReported) {
  body_.m_nodes[free_node()].m_im *= 2;
  EXPECT_TRUE(reports("inverse mass"));
}

TEST_F(MemberRule, ARestLengthWrittenIsReported) {
  body_.m_links[0].m_rl *= 1.5f;
  EXPECT_TRUE(reports("rest length changed"));
}

TEST_F(MemberRule, ALinkRemovedBehindItsBackIsReported) {
  body_.m_links.pop_back();
  EXPECT_TRUE(reports("link_meta_ size differs"));
}

TEST_F(MemberRule, ALinkMaterialReplacedIsReported) {
  body_.m_links[0].m_material = body_.appendMaterial();
  EXPECT_TRUE(reports("material"));
}

TEST_F(MemberRule, APinnedNodeMovedIsReported) {
  for (int i = 0; i < body_.m_nodes.size(); ++i)
    if (body_.m_nodes[i].m_im == 0) {
      body_.m_nodes[i].m_x += btVector3(0.1f, 0, 0);
      break;
    }
  EXPECT_TRUE(reports("pinned node moved"));
}

TEST_F(MemberRule, AskingBulletToResetRestLengthsIsReported) {
  body_.m_bUpdateRtCst = true;
  EXPECT_TRUE(reports("m_bUpdateRtCst"));
}

}  // namespace
}  // namespace tcsb
