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

/// How the surface passes from an operation's old nodes to its new ones.
enum class SurfaceBlend {
  /// A geomorph (Hoppe, "Progressive Meshes", SIGGRAPH 1996, §4.2): while an operation blends, each leaf of its
  /// block is w x (from the new nodes) + (1 - w) x (from the old ones), w = body.arrival_weight(new node), the weight
  /// its fading-in links carry. The surface then moves to the new cut in K + 1 steps of 1/(K + 1) each, as the
  /// physics does, instead of jumping when the operation begins.
  kGeomorph,
  /// The committed cut alone: the surface takes the new nodes' shape as soon as an operation begins.
  kSwitch,
};

/// Every leaf of a TC-SB body reconstructed from its cut, with F = body.local_affine_fit(A) whatever the placement
/// setting, so rigid and affine placement are measured by the same instrument: from the committed cut (active and
/// arriving nodes), geomorphed with the leaving nodes while operations blend unless `blend` is kSwitch. `leaves` is
/// resized to the net's node count. O(N + cut size x degree).
void reconstruct_leaves(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves,
                        SurfaceBlend blend = SurfaceBlend::kGeomorph);

/// The body's node positions as doubles (a stock body built from a net: node i is grid node i).
void copy_positions(const btSoftBody& body, std::vector<Eigen::Vector3d>& out);

/// The body's node velocities as doubles.
void copy_velocities(const btSoftBody& body, std::vector<Eigen::Vector3d>& out);

}  // namespace tcsb
