// Reconstruction of every grid node from a TC-SB cut, and popping measured with it: exact where it must be exact
// (the finest cut, leaves in the cut, affine fields, a net at rest), and able to see a jump where there is one.
#include "fidelity/reconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/fidelity_metrics.h"
#include "feedback/random_policy.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"

#include "../softbody/test_bodies.h"
#include "scene/scene_world.h"

namespace tcsb {
namespace {

using testing::kDt;

using testing::square_net;
using testing::test_solver;

WorldSettings world_settings(double gravity) {
  WorldSettings w;
  w.gravity = gravity;
  return w;
}

/// Drives the cut down towards `target` committed nodes with random operations, without stepping Bullet (blends
/// advance at each boundary as the runner does), then lets every blend end. Leaves a multi-level cut.
void coarsen_to(TcSoftBody& body, int target, std::uint64_t seed) {
  RandomPolicy policy(seed);
  for (int round = 0; round < 400 && body.committed_count() > target + 2; ++round) {
    body.advance_blends();
    policy.apply(body, target, 16);
  }
  while (body.interpolations() > 0) body.advance_blends();
}

/// x' = b + A (x, z): an affine deformation of the net's plane into space (a stretch, a shear and a tilt).
Eigen::Vector3d affine(const Eigen::Vector3d& rest) {
  return Eigen::Vector3d(0.3 + 1.2 * rest.x() + 0.1 * rest.z(), 7.0 - 0.4 * rest.x() + 0.25 * rest.z(),
                         -0.2 + 0.05 * rest.x() + 0.9 * rest.z());
}

/// Moves every simulated node onto the affine image of its own rest position.
void deform_affinely(TcSoftBody& body) {
  for (int i = 0; i < body.node_count(); ++i) {
    const Eigen::Vector3d p = affine(body.tree().rest(body.tree_id(i)));
    body.m_nodes[i].m_x =
        btVector3(static_cast<btScalar>(p.x()), static_cast<btScalar>(p.y()), static_cast<btScalar>(p.z()));
  }
}

TEST(Reconstruction, FinestCutEqualsThePlainBodyExactly) {
  for (const RestPlacement rest : {RestPlacement::kCentroid, RestPlacement::kVertex}) {
    SCOPED_TRACE(rest == RestPlacement::kVertex ? "vertex rest" : "centroid rest");
    const auto net = square_net(33, kAllCorners, rest);
    SceneWorld world(world_settings(9.81));
    TcSoftBody tc(world.info(), net, test_solver(), {});
    auto plain = make_plain_softbody(world.info(), *net, test_solver());
    for (int s = 0; s < 60; ++s) {
      tc.advance_blends();
      tc.simulate_step(kDt);
      step_soft_body(*plain, kDt);
    }
    std::vector<Eigen::Vector3d> leaves, positions;
    reconstruct_leaves(tc, leaves);
    copy_positions(*plain, positions);
    ASSERT_EQ(leaves.size(), positions.size());
    for (std::size_t i = 0; i < leaves.size(); ++i) ASSERT_EQ(leaves[i], positions[i]) << "leaf " << i;
    EXPECT_LT(positions[16 * 33 + 16].y(), 7.0);  // the net did fall: the equality is not of two resting nets
  }
}

TEST(Reconstruction, LeavesInTheCutMapToThemselvesExactly) {
  const auto net = square_net(33);
  SceneWorld world(world_settings(9.81));
  TcSoftBody tc(world.info(), net, test_solver(), {});
  RandomPolicy policy(5);
  for (int s = 0; s < 80; ++s) {
    tc.advance_blends();
    policy.apply(tc, 33 * 33 / 2, 16);
    tc.simulate_step(kDt);
  }
  std::vector<Eigen::Vector3d> leaves;
  reconstruct_leaves(tc, leaves);
  int in_cut = 0;
  for (TreeId leaf = 0; leaf < static_cast<TreeId>(net->node_count()); ++leaf) {
    if (!tc.committed(leaf)) continue;
    const btVector3& x = tc.m_nodes[tc.bullet_index(leaf)].m_x;
    ASSERT_EQ(leaves[static_cast<std::size_t>(leaf)], Eigen::Vector3d(x.x(), x.y(), x.z())) << "leaf " << leaf;
    ++in_cut;
  }
  EXPECT_GT(in_cut, 50);
  EXPECT_LT(in_cut, static_cast<int>(net->node_count()));  // and some leaves were reconstructed from coarser nodes
}

TEST(Reconstruction, ReproducesAnAffineFieldFromAnyCutWhateverThePlacement) {
  for (const RestPlacement rest : {RestPlacement::kCentroid, RestPlacement::kVertex})
    for (const Placement placement : {Placement::kAffine, Placement::kRigid}) {
      SCOPED_TRACE(rest == RestPlacement::kVertex ? "vertex rest" : "centroid rest");
      const auto net = square_net(33, kAllCorners, rest);
      SceneWorld world(world_settings(0.0));
      TcSettings settings;
      settings.placement = placement;
      TcSoftBody tc(world.info(), net, test_solver(), settings);
      coarsen_to(tc, 33 * 33 / 4, 11);
      ASSERT_LT(tc.committed_count(), 33 * 33 / 3);
      deform_affinely(tc);
      std::vector<Eigen::Vector3d> leaves;
      reconstruct_leaves(tc, leaves);
      double worst = 0;
      for (TreeId leaf = 0; leaf < static_cast<TreeId>(net->node_count()); ++leaf)
        worst = std::max(worst, (leaves[static_cast<std::size_t>(leaf)] - affine(net->lod().rest(leaf))).norm());
      EXPECT_LT(worst, 2e-5) << (placement == Placement::kRigid ? "rigid" : "affine");  // float positions
    }
}

TEST(Reconstruction, CoversTheNetWhileOperationsBlend) {
  const auto net = square_net(17);
  SceneWorld world(world_settings(0.0));
  TcSoftBody tc(world.info(), net, test_solver(), {});
  coarsen_to(tc, 17 * 17 / 3, 3);
  RandomPolicy policy(8);
  tc.advance_blends();
  ASSERT_GT(policy.apply(tc, 17 * 17 / 3, 8), 0);
  ASSERT_GT(tc.interpolations(), 0);
  deform_affinely(tc);
  std::vector<Eigen::Vector3d> leaves;
  reconstruct_leaves(tc, leaves);  // throws if the committed cut failed to cover every leaf once
  for (TreeId leaf = 0; leaf < static_cast<TreeId>(net->node_count()); ++leaf)
    ASSERT_LT((leaves[static_cast<std::size_t>(leaf)] - affine(net->lod().rest(leaf))).norm(), 2e-5) << leaf;
}

/// The largest jump of the reconstructed surface over `boundaries` step boundaries of random operations on a body
/// that never steps (no simulated time passes, so every jump is popping).
double popping_over_operations(TcSoftBody& tc, int boundaries, int target) {
  RandomPolicy policy(17);
  std::vector<Eigen::Vector3d> before, after;
  double worst = 0;
  int operations = 0;
  for (int b = 0; b < boundaries; ++b) {
    reconstruct_leaves(tc, before);
    tc.advance_blends();
    operations += policy.apply(tc, target, 8);
    reconstruct_leaves(tc, after);
    worst = std::max(worst, max_displacement(before, after));
  }
  EXPECT_GT(operations, boundaries);
  return worst;
}

TEST(Reconstruction, ANetAtRestReconstructsAtRestWhereverItsBlocksRest) {
  // A multi-level cut of a flat net without gravity: every leaf reconstructs onto its rest position, whether the
  // blocks rest at their centroids or on their first leaves (LodTree::rest()).
  for (const RestPlacement rest : {RestPlacement::kCentroid, RestPlacement::kVertex}) {
    SCOPED_TRACE(rest == RestPlacement::kVertex ? "vertex rest" : "centroid rest");
    const auto net = square_net(33, kAllCorners, rest);
    SceneWorld world(world_settings(0.0));
    TcSoftBody tc(world.info(), net, test_solver(), {});
    coarsen_to(tc, 33 * 33 / 5, 3);
    ASSERT_LT(tc.committed_count(), 33 * 33 / 3);
    for (int s = 0; s < 10; ++s) tc.simulate_step(kDt);
    std::vector<Eigen::Vector3d> leaves;
    reconstruct_leaves(tc, leaves);
    double worst = 0;
    for (TreeId leaf = 0; leaf < static_cast<TreeId>(net->node_count()); ++leaf)
      worst = std::max(worst, (leaves[static_cast<std::size_t>(leaf)] - net->lod().rest(leaf)).norm());
    EXPECT_LT(worst, 1e-5 * net->extent());
  }
}

TEST(Popping, IsZeroForOperationsOnANetAtRest) {
  for (const RestPlacement rest : {RestPlacement::kCentroid, RestPlacement::kVertex})
    for (const Placement placement : {Placement::kAffine, Placement::kRigid}) {
      const auto net = square_net(33, kAllCorners, rest);
      SceneWorld world(world_settings(0.0));
      TcSettings settings;
      settings.placement = placement;
      TcSoftBody tc(world.info(), net, test_solver(), settings);
      // Down to a quarter and back up to three quarters: coarse, refine and both end operations.
      EXPECT_LT(popping_over_operations(tc, 60, 33 * 33 / 4), 1e-5);
      EXPECT_LT(popping_over_operations(tc, 60, 3 * 33 * 33 / 4), 1e-5);
    }
}

TEST(Popping, AffinePlacementDoesNotPopOnAnAffineFieldButRigidPlacementDoes) {
  double jump[2] = {0, 0};
  for (const Placement placement : {Placement::kAffine, Placement::kRigid}) {
    // No pins: an affine map that kept four pinned corners in place would be the identity.
    const auto net = square_net(33, 0);
    SceneWorld world(world_settings(0.0));
    TcSettings settings;
    settings.placement = placement;
    TcSoftBody tc(world.info(), net, test_solver(), settings);
    coarsen_to(tc, 33 * 33 / 4, 23);
    deform_affinely(tc);
    jump[placement == Placement::kRigid] = popping_over_operations(tc, 40, 3 * 33 * 33 / 4);  // refines
  }
  EXPECT_LT(jump[0], 2e-5);  // children placed by the local fit land on the field
  EXPECT_GT(jump[1], 0.01);  // rigid offsets ignore the stretch and tilt: the surface jumps, and the metric sees it
}

TEST(Popping, CoarseningATwistedBlockJumpsByItsTwist) {
  const auto net = square_net(17);
  SceneWorld world(world_settings(0.0));
  TcSoftBody tc(world.info(), net, test_solver(), {});
  // A saddle, y = 8 - 0.3 x z: inside a 2x2 block its twist is not affine (a bowl's curvature would be: the
  // block's four nodes sit at the same distance from its centre, so a bowl only shifts them all alike).
  for (int i = 0; i < tc.node_count(); ++i) {
    const Eigen::Vector3d r = net->lod().rest(tc.tree_id(i));
    tc.m_nodes[i].m_x.setY(static_cast<btScalar>(8.0 - 0.3 * r.x() * r.z()));
  }
  std::vector<Eigen::Vector3d> before, after;
  reconstruct_leaves(tc, before);
  const TreeId parent = net->lod().at(1, 5, 2);  // an off-centre 2x2 block
  ASSERT_TRUE(tc.can_coarsen(parent).ok);
  tc.begin_coarse(parent);
  reconstruct_leaves(tc, after);
  // 0.3 x (0.25 m)^2 = 0.019 m: each child's twist offset, which the parent's affine reconstruction cannot hold.
  EXPECT_NEAR(max_displacement(before, after), 0.3 * 0.25 * 0.25, 0.005);
}

}  // namespace
}  // namespace tcsb
