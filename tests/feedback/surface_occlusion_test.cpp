#include "feedback/surface_occlusion.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "feedback/saliency.h"
#include "feedback/saliency_controller.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody.h"

#include "../softbody/test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;
using testing::square_net;  // 8 x 8 m at y = 8 m, pinned at its corners

/// The body's snapshot with its surface, and which nodes `camera` sees of it (cells of one pixel).
struct SeenBody {
  CutSnapshot snapshot;
  SurfaceOcclusion occlusion;
  std::vector<std::uint8_t> seen;

  SeenBody(const TcSoftBody& body, const ScreenProjection& view) {
    take_snapshot(body, cut_view(body), true, 0, snapshot);
    occlusion.capture(body, snapshot);
    const std::span<const std::uint8_t> s = occlusion.seen(snapshot, view, 1);
    seen.assign(s.begin(), s.end());
  }
};

/// Looking straight down on the sheet from 12 m above its centre: the whole sheet is in view.
ScreenProjection from_above() {
  Camera c;
  c.pose = {{0, 20, 0}, {0, 8, 0}};
  c.up = {0, 0, -1};
  c.fov_deg = 90;
  c.width_px = c.height_px = 200;
  return {c, 0.0};
}

/// Below the sheet's corners and beside it, looking up at it (as the fidelity pass's occlusion test does).
Camera from_below() {
  Camera c;
  c.pose = {{0, 5.5, 14}, {0, 7, 0}};
  c.fov_deg = 60;
  c.width_px = 320;
  c.height_px = 240;
  return c;
}

TEST(SurfaceOcclusion, AFoldedSheetHidesItsLowerLayerAndItsSaliencyIsZero) {
  // The half at z > 0 folded over the other half, 2 m above it (two links of the 9 x 9 net): seen from above, the
  // lower layer's nodes lie behind the upper layer.
  const auto net = square_net(9);
  SceneWorld world({});
  TcSoftBody body(world.info(), net, {}, {});
  const LodTree& tree = net->lod();
  for (int i = 0; i < body.node_count(); ++i) {
    const Eigen::Vector3d r = tree.rest(body.tree_ids()[static_cast<std::size_t>(i)]);
    if (r.z() > 0) body.m_nodes[i].m_x = btVector3(r.x(), r.y() + 2, -r.z());
  }
  const ScreenProjection view = from_above();
  const SeenBody seen(body, view);
  EXPECT_FALSE(seen.snapshot.faces.empty());
  FeedbackSettings settings;
  settings.view = true;
  const std::vector<float> occluded = compute_saliency(seen.snapshot, settings, &view, seen.seen);
  const std::vector<float> see_through = compute_saliency(seen.snapshot, settings, &view);
  int hidden = 0;
  for (std::size_t i = 0; i < seen.snapshot.size(); ++i) {
    const Eigen::Vector3d r = tree.rest(body.tree_ids()[i]);
    SCOPED_TRACE(i);
    EXPECT_TRUE(view.project(r).in_view);
    EXPECT_GT(see_through[i], 0.0f) << "without occlusion every node in view counts";
    if (r.z() > 0) {
      EXPECT_EQ(seen.seen[i], 1) << "the upper layer";
      EXPECT_GT(occluded[i], 0.0f);
    }
    // The lower layer away from the fold and the upper layer's edges, where a cell may go either way.
    if (r.z() <= -2 && std::abs(r.x()) <= 3) {
      EXPECT_EQ(seen.seen[i], 0) << "under the upper layer";
      EXPECT_EQ(occluded[i], 0.0f) << "hidden: the lowest saliency";
      ++hidden;
    }
  }
  EXPECT_EQ(hidden, 7 * 3);
}

TEST(SurfaceOcclusion, AFlatSheetSeenObliquelyHidesNothingAtAnyLevel) {
  // Seen at about 10 degrees, a flat surface's triangles around a node lie up to a fraction of a block nearer than it
  // within its cell: the tolerance of the node's own block side keeps the surface from hiding itself, fine or coarse.
  const auto net = square_net(17);
  const ScreenProjection view(from_below(), 0.0);
  for (const int level : {0, 2}) {
    SCOPED_TRACE(level);
    SceneWorld world({});
    TcSettings tc;
    tc.start_level = level;
    TcSoftBody body(world.info(), net, {}, tc);
    const SeenBody seen(body, view);
    EXPECT_FALSE(seen.snapshot.faces.empty());
    int in_view = 0;
    for (std::size_t i = 0; i < seen.snapshot.size(); ++i) {
      const auto& x = seen.snapshot.position[i];
      const bool shown = view.project(Eigen::Vector3d(x[0], x[1], x[2])).in_view;
      in_view += shown;
      EXPECT_EQ(seen.seen[i], shown ? 1 : 0) << "node " << i;
    }
    EXPECT_GT(in_view, 0);
  }
}

/// Mean z of the leaves the controller simulates after `steps` steps of the sheet sagging between its pinned
/// corners, seen from below and beside it (+z) by a camera that does or does not model occlusion.
double mean_leaf_z(int occlusion_cell_px, int steps, bool parallel = false) {
  const auto net = square_net(17);
  SceneWorld world({});
  TcSoftBody body(world.info(), net, {}, {});
  FeedbackSettings settings;
  settings.view = true;
  settings.max_ops_per_step = 16;
  settings.parallel = parallel;
  settings.threads = 2;
  Camera camera = from_below();
  camera.occlusion_cell_px = occlusion_cell_px;
  SaliencyController controller(settings, 120, Spectator{camera, kDt});
  for (int s = 0; s < steps; ++s) {
    body.advance_blends();
    controller.before_step(body);
    body.simulate_step(kDt);
    controller.after_step(body);
  }
  EXPECT_LE(body.node_count(), 120);
  double z = 0;
  int leaves = 0;
  for (const TreeId id : body.tree_ids())
    if (net->lod().node(id).level == 0) {
      z += net->lod().rest(id).z();
      ++leaves;
    }
  EXPECT_GT(leaves, 0);
  return leaves > 0 ? z / leaves : 0.0;
}

TEST(SurfaceOcclusion, TheControllerKeepsDetailOnTheSideTheCameraSees) {
  // The sagging sheet's far side hides behind its near side (z > 0, towards the camera): with occlusion its leaves
  // move towards the camera.
  const double see_through = mean_leaf_z(0, 90), occluded = mean_leaf_z(1, 90);
  EXPECT_GT(occluded, see_through + 0.5) << "see-through " << see_through << ", occluded " << occluded;
  // The depth buffer is drawn on the worker in parallel mode: the same decisions.
  EXPECT_EQ(mean_leaf_z(1, 90, true), occluded);
}

}  // namespace
}  // namespace tcsb
