// The geomorphed surface: an operation's jump spread evenly over its blend, frozen so that the leaving nodes' drift
// does not leak in, and nothing at all without operations.
#include "fidelity/surface_morph.h"

#include <gtest/gtest.h>

#include <vector>

#include "analysis/fidelity_metrics.h"
#include "fidelity/reconstruction.h"
#include "softbody/bullet_setup.h"

#include "../softbody/test_bodies.h"

namespace tcsb {
namespace {

using testing::square_net;
using testing::test_solver;

constexpr int kBlendSteps = 4;

/// A 17 x 17 net without gravity, shaped as the saddle y = 8 - 0.3 x z: inside a 2x2 block its twist is not
/// affine, so coarsening the block moves the surface by 0.3 x (0.25 m)^2 (reconstruction_test.cpp).
struct SaddleBody {
  SaddleBody() : net(square_net(17)), world(settings()), body(world, net, test_solver(), tc_settings()) {
    for (int i = 0; i < body.node_count(); ++i) {
      const Eigen::Vector3d r = net->lod().rest(body.tree_id(i));
      body.m_nodes[i].m_x.setY(static_cast<btScalar>(8.0 - 0.3 * r.x() * r.z()));
    }
  }
  static WorldSettings settings() {
    WorldSettings w;
    w.gravity = 0;
    return w;
  }
  static TcSettings tc_settings() {
    TcSettings s;
    s.blend_steps = kBlendSteps;
    return s;
  }
  std::shared_ptr<const Net> net;
  SoftBodyWorld world;
  TcSoftBody body;
};

constexpr double kTwist = 0.3 * 0.25 * 0.25;

TEST(SurfaceMorph, WithoutOperationsItIsTheCommittedCut) {
  SaddleBody s;
  SurfaceMorph morph;
  std::vector<Eigen::Vector3d> shown, committed;
  morph.reconstruct(s.body, shown);
  reconstruct_leaves(s.body, committed);
  EXPECT_EQ(shown, committed);
}

TEST(SurfaceMorph, SpreadsACoarsesJumpEvenlyOverItsBlend) {
  SaddleBody s;
  SurfaceMorph morph;
  std::vector<Eigen::Vector3d> before, after, first;
  morph.reconstruct(s.body, before);
  first = before;
  const TreeId parent = s.net->lod().at(1, 5, 2);  // an off-centre 2x2 block
  ASSERT_TRUE(s.body.can_coarsen(parent).ok);
  s.body.begin_coarse(parent);
  // Boundary by boundary, no step in between (so every change is popping): each moves the surface by about a fifth
  // (1/(K+1)) of the twist, until the coarse ends at the fifth.
  for (int boundary = 0; boundary <= kBlendSteps; ++boundary) {
    if (boundary > 0) s.body.advance_blends();
    morph.reconstruct(s.body, after);
    EXPECT_NEAR(max_displacement(before, after), kTwist / (kBlendSteps + 1), 0.002) << boundary;
    before = after;
  }
  EXPECT_EQ(s.body.state(parent), CutState::kActive);
  EXPECT_NEAR(max_displacement(first, after), kTwist, 0.005);  // the whole way is the twist, as without the morph
  std::vector<Eigen::Vector3d> committed;
  reconstruct_leaves(s.body, committed);
  EXPECT_EQ(after, committed);  // and once the operation ended, nothing of it is left
}

TEST(SurfaceMorph, TheJumpIsFrozenWhileTheBodyMoves) {
  SaddleBody s;
  SurfaceMorph morph;
  std::vector<Eigen::Vector3d> shown, moved, committed, moved_committed;
  const TreeId parent = s.net->lod().at(1, 5, 2);
  s.body.begin_coarse(parent);
  morph.reconstruct(s.body, shown);
  reconstruct_leaves(s.body, committed);
  // Everything, the leaving children included, shifts by 1 m: the shown surface follows the committed one exactly,
  // whatever the leaving nodes do (here they move alike; in a run they drift).
  for (int i = 0; i < s.body.node_count(); ++i) s.body.m_nodes[i].m_x += btVector3(0, 1, 0);
  morph.reconstruct(s.body, moved);
  reconstruct_leaves(s.body, moved_committed);
  for (std::size_t l = 0; l < shown.size(); ++l) {
    EXPECT_NEAR(((moved[l] - moved_committed[l]) - (shown[l] - committed[l])).norm(), 0.0, 1e-5) << l;
  }
  // The leaving children alone move 1 m more: with the jump frozen, the shown surface does not move with them.
  const LodNode& block = s.net->lod().node(parent);
  for (int c = 0; c < block.child_count; ++c)
    s.body.m_nodes[s.body.bullet_index(block.children[static_cast<std::size_t>(c)])].m_x += btVector3(0, 1, 0);
  std::vector<Eigen::Vector3d> after_drift;
  morph.reconstruct(s.body, after_drift);
  EXPECT_LT(max_displacement(moved, after_drift), 1e-5);
}

}  // namespace
}  // namespace tcsb
