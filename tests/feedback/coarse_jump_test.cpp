// The jump a coarsen would cause, estimated from a snapshot: nothing on flat or affinely deformed cloth (one affine
// map holds it exactly), linear in the bend, larger over a larger block; and the evaluator's charge ranks curved
// blocks after flat ones; seen through a camera, the jump in pixels shrinks with distance and is nothing out of view,
// and that charge ranks the blocks by it. (Its agreement with the reconstruction it predicts: tests/fidelity.)
#include "feedback/coarse_jump.h"

#include <gtest/gtest.h>

#include <cmath>

#include "feedback/evaluator.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody.h"
#include "softbody/vector_conversion.h"
#include "view/screen_projection.h"

namespace tcsb {
namespace {

/// A 17x17 TC-SB body (without pins unless told), optionally coarsened to a whole level-1 cut, whose nodes are put
/// where a shape maps their rest positions.
struct ShapedCut {
  std::shared_ptr<const Net> net;
  SceneWorld world{WorldSettings{}};
  std::unique_ptr<TcSoftBody> body;
  CutSnapshot snapshot;
  CutNeighbours neighbours;

  explicit ShapedCut(bool level1, unsigned pinned_corners = 0) {
    NetSpec spec;
    spec.width = spec.height = 17;
    spec.pinned_corners = pinned_corners;
    net = std::make_shared<const Net>(spec);
    body = std::make_unique<TcSoftBody>(world.info(), net, SolverSettings{}, TcSettings{});
    if (!level1) return;
    const LodTree& tree = body->tree();
    for (bool began = true; began;) {  // rounds: a block cannot coarsen while its neighbour blends
      began = false;
      for (int gy = 0; gy < tree.level_height(1); ++gy)
        for (int gx = 0; gx < tree.level_width(1); ++gx)
          if (body->can_coarsen(tree.at(1, gx, gy)).ok) {
            body->begin_coarse(tree.at(1, gx, gy));
            began = true;
          }
      while (body->interpolations() > 0) body->advance_blends();
    }
  }
  template <class Shape>
  void shape(Shape f) {
    for (int i = 0; i < body->node_count(); ++i)
      body->m_nodes[i].m_x = to_bullet(f(body->tree().rest(body->tree_id(i))));
    take_snapshot(*body, cut_view(*body), true, 0, snapshot);
    cut_neighbours(snapshot.cut, neighbours);
  }
  double jump(TreeId parent) const { return coarse_jump(snapshot, neighbours, parent); }
  /// An interior block of `level` (away from the border, so its neighbourhood is complete).
  TreeId interior(int level) const { return body->tree().at(level, 1, 1); }
};

/// Sag, twisted: a symmetric bend alone would not show over a block of 2 x 2 leaves (each leaf then sits equally
/// far above the mean plane of the four, which the parent's fit reproduces exactly).
Eigen::Vector3d bend(const Eigen::Vector3d& r, double c) {
  return {r.x(), r.y() - c * (r.x() * r.x() + 0.5 * r.z() * r.z() + 0.7 * r.x() * r.z()), r.z()};
}

TEST(CoarseJump, NoJumpOnFlatOrAffinelyDeformedCloth) {
  for (const bool level1 : {false, true}) {
    ShapedCut cut(level1);
    const TreeId parent = cut.interior(level1 ? 2 : 1);
    cut.shape([](const Eigen::Vector3d& r) { return r; });
    EXPECT_LT(cut.jump(parent), 1e-5) << "flat, level1=" << level1;
    cut.shape([](const Eigen::Vector3d& r) {  // sheared, tilted and moved: still one affine map
      return Eigen::Vector3d(1.1 * r.x() + 0.2 * r.z() + 0.3, 0.4 * r.x() - 0.3 * r.z() + 2.0, 0.9 * r.z() - 0.1);
    });
    EXPECT_LT(cut.jump(parent), 1e-4) << "affine, level1=" << level1;
  }
}

TEST(CoarseJump, NoJumpOnAffinelyDeformedClothAtTheBorder) {
  // Blocks on the border rest on it (LodTree::rest()), away from their children's centre of mass: the estimate
  // must put the parent where begin_coarse does, on the children's fit.
  for (const bool level1 : {false, true}) {
    ShapedCut cut(level1);
    const LodTree& tree = cut.body->tree();
    const int level = level1 ? 2 : 1;
    cut.shape([](const Eigen::Vector3d& r) {
      return Eigen::Vector3d(1.1 * r.x() + 0.2 * r.z() + 0.3, 0.4 * r.x() - 0.3 * r.z() + 2.0, 0.9 * r.z() - 0.1);
    });
    // (17 = 16 + 1: the last column's and row's blocks are one leaf wide, on the border already.)
    for (const TreeId parent : {tree.at(level, 0, 1), tree.at(level, 1, 0), tree.at(level, 0, 0)}) {
      ASSERT_NE(tree.rest(parent), tree.centroid(parent)) << parent;
      EXPECT_LT(cut.jump(parent), 1e-4) << "block " << parent << ", level1=" << level1;
    }
  }
}

TEST(CoarseJump, APinnedBlockArrivesWhereThePinsHaveMoved) {
  // begin_coarse puts a pinned parent where the pins are now (its rest position plus the pin path's offset): cloth
  // moved rigidly with its pins is one affine map, and the estimate must see no jump there either.
  ShapedCut cut(false, kAllCorners);
  const LodTree& tree = cut.body->tree();
  const TreeId corner = tree.at(1, 0, 0);
  ASSERT_TRUE(tree.node(corner).pinned());
  const Eigen::Vector3d offset(0.4, -0.3, 0.2);
  cut.body->move_pins(to_bullet(offset), btScalar(1) / 60);
  cut.shape([&](const Eigen::Vector3d& r) { return Eigen::Vector3d(r + offset); });
  EXPECT_LT(cut.jump(corner), 1e-4);
  EXPECT_LT(cut.jump(cut.interior(1)), 1e-4);  // (unpinned blocks never looked at the pins)
}

TEST(CoarseJump, GrowsLinearlyWithTheBendAndWithTheBlock) {
  ShapedCut fine(false), coarse(true);
  fine.shape([](const Eigen::Vector3d& r) { return bend(r, 0.05); });
  coarse.shape([](const Eigen::Vector3d& r) { return bend(r, 0.05); });
  const double small = fine.jump(fine.interior(1)), large = coarse.jump(coarse.interior(2));
  EXPECT_GT(small, 1e-3);
  EXPECT_GT(large, 2 * small) << "a block twice as wide holds four times the sag";
  fine.shape([](const Eigen::Vector3d& r) { return bend(r, 0.1); });
  EXPECT_NEAR(fine.jump(fine.interior(1)), 2 * small, 1e-3 * small) << "every fit is linear in the positions";
}

TEST(CoarseJump, TheChargeRanksCurvedBlocksAfterFlatOnes) {
  ShapedCut cut(false);
  // Flat for x < 0, bent beyond; at rest, so every saliency is the same and only the charge tells blocks apart.
  cut.shape([](const Eigen::Vector3d& r) {
    const double x = std::max(0.0, r.x());
    return Eigen::Vector3d(r.x(), r.y() - 0.2 * x * x, r.z());
  });
  const std::vector<float> saliency(cut.snapshot.size(), 0.0f);
  Evaluation plain, charged;
  rank_candidates(cut.snapshot, saliency, 1000, plain);
  rank_candidates(cut.snapshot, saliency, 1000, charged, {1.0, cut.net->extent(), &cut.neighbours});
  ASSERT_EQ(plain.coarse.size(), charged.coarse.size());
  bool seen_curved = false, curved_before_flat = false, plain_mixes = false;
  for (const Candidate& c : charged.coarse) {
    const bool curved = cut.jump(c.id) > 1e-4;
    curved_before_flat |= seen_curved && !curved;
    seen_curved |= curved;
  }
  EXPECT_TRUE(seen_curved);
  EXPECT_FALSE(curved_before_flat);
  seen_curved = false;
  for (const Candidate& c : plain.coarse) {  // without the charge the order ignores the shape
    const bool curved = cut.jump(c.id) > 1e-4;
    plain_mixes |= seen_curved && !curved;
    seen_curved |= curved;
  }
  EXPECT_TRUE(plain_mixes);
}

/// A camera `distance` metres from `at`, above it and to the side (so the bend's vertical jump crosses the line of
/// sight), looking at it, or with `away` the other way.
ScreenProjection camera_on_block(const Eigen::Vector3d& at, double distance, bool away = false) {
  const Eigen::Vector3d eye = at + distance * Eigen::Vector3d(0.0, 0.6, -0.8);
  const Eigen::Vector3d target = away ? Eigen::Vector3d(2 * eye - at) : at;
  Camera c;
  c.pose = {{eye.x(), eye.y(), eye.z()}, {target.x(), target.y(), target.z()}};
  c.fov_deg = 60;
  c.width_px = 640;
  c.height_px = 360;
  return {c, 0.0};
}

TEST(CoarseJumpPx, ShrinksWithTheDistanceAndIsNothingOutOfView) {
  ShapedCut cut(false);
  cut.shape([](const Eigen::Vector3d& r) { return bend(r, 0.05); });
  const TreeId parent = cut.interior(1);
  const Eigen::Vector3d at = cut.body->tree().rest(parent);
  const auto px = [&](const ScreenProjection& view) {
    return coarse_jump_px(cut.snapshot, cut.neighbours, parent, view);
  };
  // (Far from the metre-wide block against its size, so its corners are about equally deep.)
  const double near = px(camera_on_block(at, 10.0)), far = px(camera_on_block(at, 20.0));
  EXPECT_GT(near, 0.02) << "a jump of millimetres ten metres from the lens";
  EXPECT_NEAR(far / near, 0.5, 0.05) << "a pinhole's image scales with 1 / depth";
  EXPECT_EQ(px(camera_on_block(at, 10.0, true)), 0.0) << "behind the camera: not seen";
  cut.shape([](const Eigen::Vector3d& r) { return r; });
  EXPECT_LT(px(camera_on_block(at, 10.0)), 1e-3) << "flat: no jump to see";
}

TEST(CoarseJumpPx, TheChargeRanksBlocksByTheJumpTheCameraSees) {
  ShapedCut cut(false);
  cut.shape([](const Eigen::Vector3d& r) { return bend(r, 0.05); });
  // Near one corner of the net: the same bend looks larger there, and part of the net is out of view.
  const ScreenProjection view = camera_on_block(cut.body->tree().rest(cut.body->tree().at(1, 0, 0)), 1.0);
  const std::vector<float> saliency(cut.snapshot.size(), 0.0f);
  Evaluation charged;
  JumpCharge charge;
  charge.neighbours = &cut.neighbours;
  charge.per_px = 1.0;
  charge.view = &view;
  rank_candidates(cut.snapshot, saliency, 1000, charged, charge);
  ASSERT_GT(charged.coarse.size(), 4u);
  double previous = 0;
  bool unseen = false, seen = false;
  for (const Candidate& c : charged.coarse) {
    const double jump = coarse_jump_px(cut.snapshot, cut.neighbours, c.id, view);
    EXPECT_GE(jump, previous) << "block " << c.id;
    previous = jump;
    unseen |= jump == 0;
    seen |= jump > 0.1;
  }
  EXPECT_TRUE(unseen && seen) << "the camera sees a part of the net, not all of it";
}

}  // namespace
}  // namespace tcsb
