// The evaluator's estimate of a coarsen's jump (feedback/coarse_jump.h) is the jump the fidelity pass's
// reconstruction makes when that coarsen begins: the committed cut's surface before against after, over the block.
#include <gtest/gtest.h>

#include <cmath>

#include "feedback/coarse_jump.h"
#include "fidelity/calibration.h"
#include "fidelity/reconstruction.h"
#include "scene/scene_world.h"
#include "softbody/vector_conversion.h"

namespace tcsb {
namespace {

/// The largest distance between two surfaces over the leaves of `block`.
double block_distance(const LodTree& tree, TreeId block, const std::vector<Eigen::Vector3d>& a,
                      const std::vector<Eigen::Vector3d>& b) {
  double d = 0;
  for_each_leaf(tree, block, [&](TreeId leaf) {
    d = std::max(d, (a[static_cast<std::size_t>(leaf)] - b[static_cast<std::size_t>(leaf)]).norm());
  });
  return d;
}

TEST(CoarseJump, IsTheJumpTheReconstructionMakesWhenTheCoarsenBegins) {
  for (const int level : {1, 2}) {  // a parent of leaves, and of level-1 blocks
    NetSpec spec;
    spec.width = spec.height = 17;
    const auto net = std::make_shared<const Net>(spec);
    SceneWorld world{WorldSettings{}};
    TcSoftBody body(world.info(), net, SolverSettings{}, TcSettings{});
    body.coarsen_to_level(level - 1);
    for (int i = 0; i < body.node_count(); ++i) {  // a saddle, tilted
      const Eigen::Vector3d r = body.tree().rest(body.tree_id(i));
      if (body.tree().node(body.tree_id(i)).pinned()) continue;  // pinned nodes stay at rest
      body.m_nodes[i].m_x = to_bullet(Eigen::Vector3d(
          r.x(), r.y() + 0.1 * r.x() - 0.06 * r.x() * r.x() + 0.04 * r.z() * r.z() + 0.03 * r.x() * r.z(), r.z()));
    }
    CutSnapshot snapshot;
    CutNeighbours neighbours;
    take_snapshot(body, cut_view(body), true, 0, snapshot);
    cut_neighbours(snapshot.cut, neighbours);
    for (const auto& [gx, gy] : {std::pair{1, 1}, std::pair{2, 1}, std::pair{0, 0}}) {  // interior, and a pinned corner
      const TreeId parent = body.tree().at(level, gx, gy);
      ASSERT_TRUE(body.can_coarsen(parent).ok) << "level " << level << " (" << gx << ", " << gy << ")";
      const double estimate = coarse_jump(snapshot, neighbours, parent);
      std::vector<Eigen::Vector3d> before, after;
      reconstruct_leaves(body, before);
      body.begin_coarse(parent);
      reconstruct_leaves(body, after);
      const double actual = block_distance(body.tree(), parent, before, after);
      EXPECT_GT(actual, 1e-3) << "level " << level;
      EXPECT_NEAR(estimate, actual, 1e-4 * actual + 1e-6) << "level " << level << " (" << gx << ", " << gy << ")";
      while (body.interpolations() > 0) body.advance_blends();  // positions unchanged: the next block sees the same
      take_snapshot(body, cut_view(body), true, 0, snapshot);
      cut_neighbours(snapshot.cut, neighbours);
    }
  }
}

}  // namespace
}  // namespace tcsb
