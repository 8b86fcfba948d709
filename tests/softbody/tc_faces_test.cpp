// Faces and wind: a windy scene gives every body faces (SceneWorld::attach). A plain body gets its grid cells', a
// TC-SB body the faces of its committed cut, rebuilt as the cut changes; on the finest cut the two are the same faces
// and the two bodies step alike in the wind. validate() checks a TC-SB body's faces against its cut and their total
// area at rest against the net's.
#include <gtest/gtest.h>

#include <cmath>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody_impl.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

SceneSettings windy(AeroModel model = AeroModel::kVTwoSided) {
  SceneSettings scene;
  scene.wind = Wind{model, {4.0, 0.0, 2.0}, 0.5, 1.0, 1.2};
  return scene;
}

/// The node indices of a body's faces, in order.
std::vector<std::array<long, 3>> face_indices(const btSoftBody& body) {
  std::vector<std::array<long, 3>> out;
  for (int i = 0; i < body.m_faces.size(); ++i) {
    const btSoftBody::Face& f = body.m_faces[i];
    out.push_back({f.m_n[0] - &body.m_nodes[0], f.m_n[1] - &body.m_nodes[0], f.m_n[2] - &body.m_nodes[0]});
  }
  return out;
}

double mean_x(const btSoftBody& body) {
  double sum = 0;
  for (int i = 0; i < body.m_nodes.size(); ++i) sum += static_cast<double>(body.m_nodes[i].m_x.x());
  return sum / body.m_nodes.size();
}

TEST(TcFaces, NoWindNoFaces) {
  const auto net = testing::square_net(9);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  const SceneWorld::Attachment a = world.attach(tc), b = world.attach(*plain);
  EXPECT_FALSE(tc.faces_enabled());
  EXPECT_EQ(tc.m_faces.size(), 0);
  EXPECT_EQ(plain->m_faces.size(), 0);
}

TEST(TcFaces, OnTheFinestCutAPlainBodysCellFacesAndTheSameStepsInTheWind) {
  for (const AeroModel model : {AeroModel::kVTwoSided, AeroModel::kVTwoSidedLiftDrag, AeroModel::kFTwoSided}) {
    const auto net = testing::square_net(17, kCornerMinMin | kCornerMinMax);  // a flag on two corners of one edge
    SceneWorld world({}, windy(model));
    TcSoftBody tc(world.info(), net, testing::test_solver(), {});
    auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
    const SceneWorld::Attachment a = world.attach(tc), b = world.attach(*plain);
    ASSERT_EQ(plain->m_faces.size(), 2 * 16 * 16);
    ASSERT_EQ(face_indices(tc), face_indices(*plain));
    for (int i = 0; i < plain->m_nodes.size(); ++i) ASSERT_EQ(tc.m_nodes[i].m_area, plain->m_nodes[i].m_area);
    for (int s = 0; s < 60; ++s) world.step(kDt);
    for (int i = 0; i < plain->m_nodes.size(); ++i) ASSERT_EQ(tc.m_nodes[i].m_x, plain->m_nodes[i].m_x) << i;
    EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  }
}

TEST(TcFaces, TheWindPushesTheClothDownwind) {
  const auto net = testing::square_net(17, kCornerMinMin | kCornerMinMax);
  SceneWorld still({}), windy_world({}, windy());
  auto calm = make_plain_softbody(still.info(), *net, testing::test_solver());
  auto blown = make_plain_softbody(windy_world.info(), *net, testing::test_solver());
  const SceneWorld::Attachment a = still.attach(*calm), b = windy_world.attach(*blown);
  for (int s = 0; s < 60; ++s) {
    still.step(kDt);
    windy_world.step(kDt);
  }
  EXPECT_GT(mean_x(*blown), mean_x(*calm) + 0.05);  // the wind blows along +x (and +z)
}

TEST(TcFaces, FollowTheCutThroughRandomOperations) {
  // 23 is not 2^k + 1: partial blocks at the far borders.
  for (const int width : {17, 23}) {
    const auto net = testing::square_net(width, kCornerMinMin | kCornerMinMax);
    SceneWorld world({}, windy());
    TcSoftBody tc(world.info(), net, testing::test_solver(), {});
    const SceneWorld::Attachment a = world.attach(tc);
    RandomPolicy policy(5);
    for (int s = 0; s < 300; ++s) {
      tc.advance_blends();
      policy.apply(tc, (s / 60) % 2 == 0 ? width * width / 4 : width * width, 8);
      world.step(kDt);
      const Validation v = tc.validate();
      ASSERT_TRUE(v.ok()) << "width " << width << ", step " << s << ": " << v.summary();
    }
    EXPECT_GT(tc.impl().face_rebuilds(), 10);
    EXPECT_LT(tc.m_faces.size(), 2 * (width - 1) * (width - 1));  // some blocks coarse
    for (int i = 0; i < tc.m_nodes.size(); ++i) ASSERT_TRUE(std::isfinite(tc.m_nodes[i].m_x.x()));
  }
}

TEST(TcFaces, TheCurrentFacesAreTheCutsFacesBuiltOrNot) {
  // current_cut_faces() hands out the triples the faces were built from while no rebuild is pending (the occlusion
  // capture reads them so): they must be what cut_faces() derives afresh, at every boundary, and so must the ones it
  // computes while a rebuild is pending.
  const auto net = testing::square_net(23, kCornerMinMin | kCornerMinMax);
  SceneWorld world({}, windy());
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  const SceneWorld::Attachment a = world.attach(tc);
  RandomPolicy policy(9);
  std::vector<std::array<TreeId, 3>> out, fresh;
  std::vector<TreeId> owner;
  int built = 0, computed = 0;
  const auto check = [&](int s) {
    const std::vector<std::array<TreeId, 3>>& current = tc.impl().current_cut_faces(out, owner);
    (&current == &out ? computed : built) += 1;
    tc.impl().cut_faces(fresh, owner);
    ASSERT_EQ(current, fresh) << "step " << s;
  };
  for (int s = 0; s < 200; ++s) {
    tc.advance_blends();
    check(s);
    policy.apply(tc, (s / 50) % 2 == 0 ? 23 * 23 / 4 : 23 * 23, 8);
    check(s);
    world.step(kDt);
  }
  EXPECT_GT(built, 10);  // (both ways, often)
  EXPECT_GT(computed, 50);
}

TEST(TcFaces, ValidateCatchesAFaceOffTheCut) {
  const auto net = testing::square_net(17);
  SceneWorld world({}, windy());
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  const SceneWorld::Attachment a = world.attach(tc);
  const TreeId parent = net->lod().at(1, 3, 3);
  tc.begin_coarse(parent);
  world.step(kDt);  // the faces follow the coarse: its children leave the committed cut
  ASSERT_TRUE(tc.validate().ok()) << tc.validate().summary();
  const int leaving = tc.bullet_index(net->lod().node(parent).children[0]);
  ASSERT_GE(leaving, 0);
  tc.m_faces[0].m_n[0] = &tc.m_nodes[leaving];
  const Validation broken = tc.validate();
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.summary().find("not over the committed cut's nodes"), std::string::npos) << broken.summary();
}

}  // namespace
}  // namespace tcsb
