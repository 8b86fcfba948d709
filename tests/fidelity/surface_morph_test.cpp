// The geomorphed surface: every jump a boundary makes spread evenly over the next K + 1 boundaries (or as many as it
// is given) — an operation's own block, its neighbours' and its end alike — frozen so that the leaving nodes' drift
// does not leak in, and nothing at all without operations.
#include "fidelity/surface_morph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "analysis/fidelity_metrics.h"
#include "fidelity/calibration.h"
#include "fidelity/reconstruction.h"
#include "softbody/bullet_setup.h"

#include "../softbody/test_bodies.h"
#include "scene/scene_world.h"

namespace tcsb {
namespace {

using testing::square_net;
using testing::test_solver;

constexpr int kBlendSteps = 4;

/// A 17 x 17 net without gravity, shaped as the saddle y = 8 - 0.3 x z: inside a 2x2 block its twist is not
/// affine, so coarsening the block moves the surface by 0.3 x (0.25 m)^2 (reconstruction_test.cpp).
struct SaddleBody {
  SaddleBody() : net(square_net(17)), world(settings()), body(world.info(), net, test_solver(), tc_settings()) {
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
  SceneWorld world;
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
  // Boundary by boundary, no step in between (so every change is popping): the coarse's own jump moves the surface
  // by a fifth (1/(K+1)) of the twist at each; its end, when the tethers leave the parent's fit, is spread too.
  double largest = 0;
  for (int boundary = 0; boundary <= 2 * kBlendSteps + 1; ++boundary) {
    if (boundary > 0) s.body.advance_blends();
    morph.boundary(s.body);
    morph.reconstruct(s.body, after);
    largest = std::max(largest, max_displacement(before, after));
    before = after;
  }
  EXPECT_NEAR(largest, kTwist / (kBlendSteps + 1), 0.002);
  EXPECT_EQ(s.body.state(parent), CutState::kActive);
  EXPECT_FALSE(morph.morphing());
  EXPECT_NEAR(max_displacement(first, after), kTwist, 0.005);  // the whole way is the twist, as without the morph
  std::vector<Eigen::Vector3d> committed;
  reconstruct_leaves(s.body, committed);
  EXPECT_EQ(after, committed);  // and once every jump is spent, nothing of it is left
}

TEST(SurfaceMorph, SpreadsOverTheBoundariesItIsGivenInsteadOfTheBlends) {
  // fidelity.geomorph_boundaries: the shown surface's morph, longer than the physical blend.
  constexpr int kBoundaries = 12;
  SaddleBody s;
  SurfaceMorph morph(kBoundaries);
  std::vector<Eigen::Vector3d> before, after, first;
  morph.reconstruct(s.body, before);
  first = before;
  const TreeId parent = s.net->lod().at(1, 5, 2);
  ASSERT_TRUE(s.body.can_coarsen(parent).ok);
  s.body.begin_coarse(parent);
  double largest = 0;
  for (int boundary = 0; boundary <= kBlendSteps + kBoundaries; ++boundary) {
    if (boundary > 0) s.body.advance_blends();
    morph.boundary(s.body);
    morph.reconstruct(s.body, after);
    largest = std::max(largest, max_displacement(before, after));
    before = after;
    if (boundary == kBoundaries - 2) {
      EXPECT_TRUE(morph.morphing()) << "the coarse's own jump is not spent yet";
    }
  }
  EXPECT_FALSE(morph.morphing());
  EXPECT_NEAR(largest, kTwist / kBoundaries, 0.001);
  EXPECT_LT(largest, 0.5 * kTwist / (kBlendSteps + 1)) << "smaller steps than the blend's own morph";
  EXPECT_NEAR(max_displacement(first, after), kTwist, 0.005);
  std::vector<Eigen::Vector3d> committed;
  reconstruct_leaves(s.body, committed);
  EXPECT_EQ(after, committed);
}

TEST(SurfaceMorph, TheJumpIsFrozenWhileTheBodyMoves) {
  SaddleBody s;
  SurfaceMorph morph;
  std::vector<Eigen::Vector3d> shown, moved, committed, moved_committed;
  const TreeId parent = s.net->lod().at(1, 5, 2);
  morph.reconstruct(s.body, shown);
  s.body.begin_coarse(parent);
  morph.boundary(s.body);
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

TEST(SurfaceMorph, SpreadsTheNeighboursJumpsAndTheEndsToo) {
  // On a level-1 cut, coarsening a level-2 block changes the fits of the level-1 blocks around it when it begins and
  // again when it ends (their links to the children go), and the parent's own fit when its tethers go: raw, those
  // jump at once; the morph spreads them as it spreads the block's own jump.
  SaddleBody s;
  s.body.coarsen_to_level(1);
  SurfaceMorph morph;
  std::vector<Eigen::Vector3d> shown_before, shown, raw_before, raw;
  morph.reconstruct(s.body, shown_before);
  const TreeId parent = s.net->lod().at(2, 2, 1);
  ASSERT_TRUE(s.body.can_coarsen(parent).ok);
  const LodNode& block = s.net->lod().node(parent);
  const auto outside = [&](std::size_t leaf) {
    const int gx = static_cast<int>(leaf) % 17, gy = static_cast<int>(leaf) / 17;
    return gx < block.leaf_x0 || gx >= block.leaf_x1 || gy < block.leaf_y0 || gy >= block.leaf_y1;
  };
  double raw_largest = 0, raw_outside = 0, shown_largest = 0;
  for (int boundary = 0; boundary <= 2 * kBlendSteps + 1; ++boundary) {
    reconstruct_leaves(s.body, raw_before);
    if (boundary == 0)
      s.body.begin_coarse(parent);
    else
      s.body.advance_blends();
    reconstruct_leaves(s.body, raw);
    for (std::size_t l = 0; l < raw.size(); ++l) {
      const double d = (raw[l] - raw_before[l]).norm();
      raw_largest = std::max(raw_largest, d);
      if (outside(l)) raw_outside = std::max(raw_outside, d);
    }
    morph.boundary(s.body);
    morph.reconstruct(s.body, shown);
    shown_largest = std::max(shown_largest, max_displacement(shown_before, shown));
    shown_before = shown;
  }
  EXPECT_GT(raw_outside, 1e-3) << "the neighbours' fits change";
  EXPECT_LT(shown_largest, 0.5 * raw_largest);
  EXPECT_FALSE(morph.morphing());
}

}  // namespace
}  // namespace tcsb
