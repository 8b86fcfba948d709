#include "feedback/saliency.h"

#include <gtest/gtest.h>

#include "feedback/evaluator.h"
#include "scene/scene_world.h"
#include "softbody/plain_softbody.h"

namespace tcsb {
namespace {

/// A 9x9 plain body's snapshot with a velocity field given per grid node.
struct Field {
  std::shared_ptr<const Net> net;
  SceneWorld world{WorldSettings{}};
  std::unique_ptr<btSoftBody> body;
  std::unique_ptr<FinestCut> cut;
  CutSnapshot snapshot;

  explicit Field(int width = 9) {
    NetSpec spec;
    spec.width = spec.height = width;
    net = std::make_shared<const Net>(spec);
    body = make_plain_softbody(world.info(), *net, {});
    cut = std::make_unique<FinestCut>(*net);
  }
  void set(int i, btVector3 v) { body->m_nodes[i].m_v = v; }
  void take(bool positions = false) { take_snapshot(*body, cut->view(), positions, 0, snapshot); }
};

TEST(Saliency, UniformMotionHasNoLocalSaliency) {
  Field f;
  for (int i = 0; i < f.body->m_nodes.size(); ++i) f.set(i, btVector3(0.3f, -1.0f, 0.2f));
  f.take();
  const std::vector<float> s = compute_saliency(f.snapshot, {});
  for (float v : s) EXPECT_FLOAT_EQ(v, 0.0f);
}

TEST(Saliency, ASingleFastNodeIsTheMostSalient) {
  Field f;
  const int fast = 4 * 9 + 4;
  f.set(fast, btVector3(0, -5, 0));
  f.take();
  FeedbackSettings settings;
  settings.global_motion_scale = 1e9;  // no global cap
  const std::vector<float> s = compute_saliency(f.snapshot, settings);
  const auto top = std::max_element(s.begin(), s.end()) - s.begin();
  EXPECT_EQ(top, fast);
  EXPECT_FLOAT_EQ(s[static_cast<std::size_t>(fast)], 1.0f);
  EXPECT_GT(s[static_cast<std::size_t>(fast + 1)], 0.0f) << "its neighbours move relative to it as well";
  EXPECT_FLOAT_EQ(s[0], 0.0f) << "far away nothing moves";
}

TEST(Saliency, GlobalMotionCapsSaliency) {
  EXPECT_DOUBLE_EQ(global_motion_cap(0, 1), 1.0);
  EXPECT_DOUBLE_EQ(global_motion_cap(1, 1), 0.5);
  EXPECT_LT(global_motion_cap(10, 1), global_motion_cap(1, 1));
  Field f;
  for (int i = 0; i < f.body->m_nodes.size(); ++i) f.set(i, btVector3(0, -3, 0));  // whole body falls at 3 m/s
  f.set(40, btVector3(0, -8, 0));
  f.take();
  FeedbackSettings settings;
  settings.global_motion_scale = 1.0;
  const std::vector<float> s = compute_saliency(f.snapshot, settings);
  const double cap = global_motion_cap(global_motion(f.snapshot), 1.0);
  EXPECT_LT(cap, 0.3);
  EXPECT_NEAR(*std::max_element(s.begin(), s.end()), cap, 1e-6);
}

TEST(Saliency, LambertFactorOfAFlatNet) {
  Field f;
  f.set(40, btVector3(0, -1, 0));
  f.take(true);
  EXPECT_NEAR(lambert_factor(f.snapshot, 40, {0, 1, 0}), 1.0, 1e-6);
  EXPECT_NEAR(lambert_factor(f.snapshot, 40, {0, -1, 0}), 0.0, 1e-6);
  EXPECT_NEAR(lambert_factor(f.snapshot, 40, {1, 1, 0}), std::sqrt(0.5), 1e-6);
  FeedbackSettings lit;
  lit.illumination = true;
  lit.light_direction = {0, -1, 0};  // light from below: the top side is dark
  lit.global_motion_scale = 1e9;
  const std::vector<float> s = compute_saliency(f.snapshot, lit);
  for (float v : s) EXPECT_FLOAT_EQ(v, 0.0f);
}

/// A camera 5 m above the 8 x 8 m net's point (2, 8, 0), looking straight down on a 100 x 300 px image with 120
/// degrees of vertical field of view: it sees z in about [-8.7, 8.7] and x in about [-0.9, 4.9], so the grid's
/// columns at x <= -1 are out of view.
ScreenProjection looking_down(double height = 5.0) {
  Camera c;
  c.pose = {{2, 8 + height, 0}, {2, 8, 0}};
  c.up = {0, 0, -1};
  c.fov_deg = 120;
  c.width_px = 100;
  c.height_px = 300;
  return {c, 0.0};
}

TEST(SaliencyView, WhatIsOutOfViewHasNoneAndWhatIsInViewHasSomeEvenAtRest) {
  Field f;
  f.take(true);
  const ScreenProjection view = looking_down();
  FeedbackSettings settings;
  settings.view = true;
  settings.contact_saliency = 1.0;  // not in contact here; and out of view even contact would count for nothing
  const std::vector<float> s = compute_saliency(f.snapshot, settings, &view);
  for (int i = 0; i < 81; ++i) {
    const int column = i % 9;  // x = -4 + column
    SCOPED_TRACE(i);
    if (column <= 3)
      EXPECT_EQ(s[static_cast<std::size_t>(i)], 0.0f);
    else
      EXPECT_GT(s[static_cast<std::size_t>(i)], 0.0f) << "a block in view is worth its apparent size";
  }
  EXPECT_EQ(*std::max_element(s.begin(), s.end()), s[4 * 9 + 6]) << "at rest, everything in view ranks alike";
}

TEST(SaliencyView, MotionOutOfViewCountsForNothingAndInViewRanksTheNodes) {
  Field f;
  f.set(4 * 9 + 1, btVector3(0, -5, 0));  // x = -3: out of view
  f.set(4 * 9 + 6, btVector3(0, 0, -1));  // x = 2: in view, moving across the image
  f.take(true);
  const ScreenProjection view = looking_down();
  FeedbackSettings settings;
  settings.view = true;
  settings.view_motion_scale = 1e9;  // no global cap
  const std::vector<float> s = compute_saliency(f.snapshot, settings, &view);
  EXPECT_EQ(s[4 * 9 + 1], 0.0f);
  const auto top = std::max_element(s.begin(), s.end()) - s.begin();
  EXPECT_EQ(top, 4 * 9 + 6);
  EXPECT_GT(s[4 * 9 + 6], s[4 * 9 + 8]) << "motion ranks nodes that look alike";
  // Motion-only, the faster node out of view would be the most salient: the view terms changed the ranking.
  const std::vector<float> motion_only = compute_saliency(f.snapshot, settings);
  EXPECT_EQ(std::max_element(motion_only.begin(), motion_only.end()) - motion_only.begin(), 4 * 9 + 1);
}

TEST(SaliencyView, DetailTooSmallToSeeWeighsLess) {
  Field f;
  f.take(true);
  FeedbackSettings settings;
  settings.view = true;
  settings.view_detail_px = 50;  // a grid cell (1 m) must look 50 px wide to count fully
  const ScreenProjection near = looking_down(2.0), far = looking_down(40.0);
  const std::vector<float> s_near = compute_saliency(f.snapshot, settings, &near);
  const std::vector<float> s_far = compute_saliency(f.snapshot, settings, &far);
  EXPECT_GT(s_near[4 * 9 + 6], s_far[4 * 9 + 6]);
  EXPECT_GT(s_far[4 * 9 + 6], 0.0f);
}

TEST(SaliencyView, TheStaticShareWeighsApparentSizeAgainstMotion) {
  Field quiet, moving;
  quiet.take(true);
  moving.set(4 * 9 + 6, btVector3(0, 0, -1));  // in view, moving across the image
  moving.take(true);
  const ScreenProjection view = looking_down();
  FeedbackSettings settings;
  settings.view = true;
  settings.view_motion_scale = 1e9;  // no global cap
  const auto saliency = [&](const Field& f, double share) {
    settings.view_static_share = share;
    return compute_saliency(f.snapshot, settings, &view);
  };
  // All static: apparent size alone, so motion changes nothing.
  EXPECT_EQ(saliency(moving, 1.0), saliency(quiet, 1.0));
  const std::vector<float> size_only = saliency(quiet, 1.0);
  // No static share: the projected motion alone, so a cloth at rest has none anywhere.
  for (float v : saliency(quiet, 0.0)) EXPECT_EQ(v, 0.0f);
  const std::vector<float> motion_only = saliency(moving, 0.0);
  EXPECT_GT(motion_only[4 * 9 + 6], 0.0f);
  EXPECT_EQ(motion_only[8], 0.0f) << "a node in view moving with its neighbours";
  // A small share keeps a quiet node in view above the nodes out of view, in proportion to its apparent size.
  const std::vector<float> small = saliency(quiet, 0.001);
  for (int i = 0; i < 81; ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(small[static_cast<std::size_t>(i)], 0.001f * size_only[static_cast<std::size_t>(i)], 1e-9f);
    if (i % 9 > 3) {
      EXPECT_GT(small[static_cast<std::size_t>(i)], 0.0f);
    }
  }
}

TEST(SaliencyView, WhatIsUnseenKeepsItsShareOfHowLargeItWouldLook) {
  Field f;
  f.set(4 * 9 + 1, btVector3(0, -5, 0));  // x = -3: out of view, moving (unseen motion counts for nothing)
  f.take(true);
  const ScreenProjection view = looking_down();
  FeedbackSettings settings;
  settings.view = true;
  settings.view_detail_px = 1e4;  // nothing reaches the cap: every worth is in proportion to its size
  settings.view_offscreen_share = 0.25;
  const std::vector<float> s = compute_saliency(f.snapshot, settings, &view);
  // Out of view, the columns x = -4 .. -1: a quarter of the block's size facing the camera, over view_detail_px.
  const LodTree& tree = *f.snapshot.cut.tree;
  const double side = block_side(tree, f.snapshot.cut.tree_of[4 * 9 + 1], grid_spacing(tree));
  const Eigen::Vector3d x(f.snapshot.position[4 * 9 + 1][0], f.snapshot.position[4 * 9 + 1][1],
                          f.snapshot.position[4 * 9 + 1][2]);
  EXPECT_NEAR(s[4 * 9 + 1], 0.25 * view.facing_size_px(x, side) / 1e4, 1e-7);
  EXPECT_GT(s[4 * 9 + 1], 0.0f);
  EXPECT_GT(s[4 * 9 + 1], s[4 * 9 + 0]) << "nearer the camera, it would look larger";
  EXPECT_GT(s[4 * 9 + 6], s[4 * 9 + 1]) << "seen, the same block is worth more";
  settings.view_offscreen_share = 0;  // the default: nothing, as before
  EXPECT_EQ(compute_saliency(f.snapshot, settings, &view)[4 * 9 + 1], 0.0f);
}

TEST(Evaluator, RanksRefinesHighFirstAndCoarsensLowFirst) {
  Field f(17);
  f.take();
  std::vector<float> s(f.snapshot.size(), 0.0f);
  s[5 * 17 + 5] = 0.9f;  // inside the level-1 block (2, 2)
  Evaluation e;
  rank_candidates(f.snapshot, s, 1000, e);
  EXPECT_TRUE(e.refine.empty()) << "leaves cannot be refined";
  ASSERT_EQ(e.coarse.size(), 81u);  // every level-1 block of a 17x17 grid (9 x 9) has all children active
  EXPECT_EQ(e.coarse.back().id, f.net->lod().at(1, 2, 2)) << "the salient block is the last to coarsen";
  for (std::size_t i = 1; i < e.coarse.size(); ++i) EXPECT_LE(e.coarse[i - 1].priority, e.coarse[i].priority);
  Evaluation again;
  rank_candidates(f.snapshot, s, 10, again);
  ASSERT_EQ(again.coarse.size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(again.coarse[i].id, e.coarse[i].id);
}

}  // namespace
}  // namespace tcsb
