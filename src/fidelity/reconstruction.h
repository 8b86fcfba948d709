// Reconstruction: a full-resolution surface (one point per grid node) from whatever a body simulates, so bodies of
// any resolution can be compared node by node with the full-resolution reference.
//
// For a TC-SB body every grid node (leaf) takes its position from the node A of the committed cut that covers it,
// by the scheme child placement uses: x_leaf = x_A + F_A (r_leaf - r_A), F_A the least-squares affine fit of A's
// neighbourhood from rest offsets in the net's plane (x, z) to current offsets. A leaf in the cut maps to itself
// exactly, and a pinned leaf inside a coarse block stays exactly on its corner (the block rests on it).
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>

#include <span>
#include <vector>

#include "net/lod_tree.h"
#include "softbody/tc_softbody.h"

namespace tcsb {

/// Writes x + F (r_leaf - r_node) for every leaf in the block of tree node `id` (rest offsets taken in the plane
/// (x, z)) into `leaves`, indexed by leaf id. A leaf node writes exactly x.
void fill_block(const LodTree& tree, TreeId id, const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& f,
                std::span<Eigen::Vector3d> leaves);

/// Every leaf of a TC-SB body reconstructed from its committed cut (active and arriving nodes), with
/// F = body.local_affine_fit(A) whatever the placement setting, so rigid and affine placement are measured by the
/// same instrument. The surface takes an operation's new nodes' shape as soon as it begins; SurfaceMorph
/// (fidelity/surface_morph.h) spreads every such change over the next K + 1 step boundaries. `leaves` is resized to the
/// net's node count. O(N + cut size x degree).
void reconstruct_leaves(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves);

/// Every leaf's LOD level in a TC-SB body: the level of the committed cut's node whose block holds it, the node
/// reconstruct_leaves() places it by (0 where the leaf itself is simulated). `levels` is resized to the net's node
/// count. O(N).
void committed_leaf_levels(const TcSoftBody& body, std::vector<int>& levels);

/// Calls visit(leaf) for every leaf in the block of tree node `id` (the node itself when it is a leaf), row by row.
template <class Visit>
void for_each_leaf(const LodTree& tree, TreeId id, Visit visit) {
  const LodNode& node = tree.node(id);
  if (node.is_leaf()) {
    visit(id);
    return;
  }
  const int width = tree.level_width(0);
  for (int gy = node.leaf_y0; gy < node.leaf_y1; ++gy)
    for (int gx = node.leaf_x0; gx < node.leaf_x1; ++gx) visit(static_cast<TreeId>(gy * width + gx));
}

/// The body's node positions as doubles (a stock body built from a net: node i is grid node i).
void copy_positions(const btSoftBody& body, std::vector<Eigen::Vector3d>& out);

/// The body's node velocities as doubles.
void copy_velocities(const btSoftBody& body, std::vector<Eigen::Vector3d>& out);

}  // namespace tcsb
