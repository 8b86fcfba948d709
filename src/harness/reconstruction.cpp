#include "harness/reconstruction.h"

#include <stdexcept>

#include "softbody/vector_conversion.h"

namespace tcsb {

namespace {

/// Calls visit(leaf) for every leaf in the block of tree node `id` (the node itself when it is a leaf).
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

/// Where simulated node `id` (at x, local fit f) puts `leaf` of its block: exactly x for itself (not x + F * 0,
/// which could differ in the last bit), else x + F (r_leaf - r_id) in the net's plane.
Eigen::Vector3d block_point(const LodTree& tree, TreeId id, const Eigen::Vector3d& x,
                            const Eigen::Matrix<double, 3, 2>& f, TreeId leaf) {
  if (leaf == id) return x;
  const Eigen::Vector3d d = tree.rest(leaf) - tree.rest(id);
  return x + f * Eigen::Vector2d(d.x(), d.z());
}

/// Mixes into the leaves of `from`'s block what simulated node `from` says about them, with weight `weight`.
void mix_in(const TcSoftBody& body, TreeId from, double weight, std::span<Eigen::Vector3d> leaves) {
  const LodTree& tree = body.tree();
  const Eigen::Vector3d x = to_eigen(body.m_nodes[body.bullet_index(from)].m_x);
  const Eigen::Matrix<double, 3, 2> f = body.local_affine_fit(from);
  for_each_leaf(tree, from, [&](TreeId leaf) {
    Eigen::Vector3d& p = leaves[static_cast<std::size_t>(leaf)];
    p = (1.0 - weight) * p + weight * block_point(tree, from, x, f, leaf);
  });
}

/// Geomorphs the block of an arriving node: its leaves, which hold the new surface, take (1 - w) of the old one.
/// A refine's old node is the arriving child's leaving parent; a coarse's are the arriving parent's leaving children.
void geomorph(const TcSoftBody& body, TreeId arriving, std::span<Eigen::Vector3d> leaves) {
  const double w = body.arrival_weight(arriving);
  if (w >= 1.0) return;
  const LodTree& tree = body.tree();
  const LodNode& node = tree.node(arriving);
  if (node.parent != kNoTreeNode && body.state(node.parent) == CutState::kLeaving) {
    // The parent's block is larger than this child's: mix it into this child's leaves only.
    const TreeId parent = node.parent;
    const Eigen::Vector3d x = to_eigen(body.m_nodes[body.bullet_index(parent)].m_x);
    const Eigen::Matrix<double, 3, 2> f = body.local_affine_fit(parent);
    for_each_leaf(tree, arriving, [&](TreeId leaf) {
      Eigen::Vector3d& p = leaves[static_cast<std::size_t>(leaf)];
      p = w * p + (1.0 - w) * block_point(tree, parent, x, f, leaf);
    });
    return;
  }
  for (int i = 0; i < node.child_count; ++i) mix_in(body, node.children[static_cast<std::size_t>(i)], 1.0 - w, leaves);
}

}  // namespace

void fill_block(const LodTree& tree, TreeId id, const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& f,
                std::span<Eigen::Vector3d> leaves) {
  for_each_leaf(tree, id,
                [&](TreeId leaf) { leaves[static_cast<std::size_t>(leaf)] = block_point(tree, id, x, f, leaf); });
}

void reconstruct_leaves(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves, SurfaceBlend blend) {
  const LodTree& tree = body.tree();
  leaves.resize(tree.leaf_count());
  std::size_t covered = 0;
  for (int i = 0; i < body.node_count(); ++i) {
    const TreeId id = body.tree_id(i);
    if (!body.committed(id)) continue;  // leaving nodes belong to the old cut
    const LodNode& n = tree.node(id);
    if (n.is_leaf()) {
      leaves[static_cast<std::size_t>(id)] = to_eigen(body.m_nodes[i].m_x);  // no fit needed: it maps to itself
      ++covered;
      continue;
    }
    fill_block(tree, id, to_eigen(body.m_nodes[i].m_x), body.local_affine_fit(id), leaves);
    covered += static_cast<std::size_t>(n.leaf_x1 - n.leaf_x0) * static_cast<std::size_t>(n.leaf_y1 - n.leaf_y0);
  }
  // The committed cut covers every leaf exactly once (validate() checks it); a count that disagrees means some
  // leaf kept a stale value, and an error figure computed from it would be wrong.
  if (covered != tree.leaf_count())
    throw std::logic_error("reconstruct_leaves: the committed cut does not cover the net");
  if (blend == SurfaceBlend::kSwitch || body.interpolations() == 0) return;
  for (int i = 0; i < body.node_count(); ++i) {
    const TreeId id = body.tree_id(i);
    if (body.state(id) == CutState::kArriving) geomorph(body, id, leaves);
  }
}

void copy_positions(const btSoftBody& body, std::vector<Eigen::Vector3d>& out) {
  out.resize(static_cast<std::size_t>(body.m_nodes.size()));
  for (int i = 0; i < body.m_nodes.size(); ++i) out[static_cast<std::size_t>(i)] = to_eigen(body.m_nodes[i].m_x);
}

void copy_velocities(const btSoftBody& body, std::vector<Eigen::Vector3d>& out) {
  out.resize(static_cast<std::size_t>(body.m_nodes.size()));
  for (int i = 0; i < body.m_nodes.size(); ++i) out[static_cast<std::size_t>(i)] = to_eigen(body.m_nodes[i].m_v);
}

}  // namespace tcsb
