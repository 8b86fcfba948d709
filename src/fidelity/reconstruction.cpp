#include "fidelity/reconstruction.h"

#include <stdexcept>

#include "softbody/vector_conversion.h"

namespace tcsb {

namespace {

/// Where simulated node `id` (at x, local fit f) puts `leaf` of its block: exactly x for itself (not x + F * 0,
/// which could differ in the last bit), else x + F (r_leaf - r_id) in the net's plane.
Eigen::Vector3d block_point(const LodTree& tree, TreeId id, const Eigen::Vector3d& x,
                            const Eigen::Matrix<double, 3, 2>& f, TreeId leaf) {
  if (leaf == id) return x;
  const Eigen::Vector3d d = tree.rest(leaf) - tree.rest(id);
  return x + f * Eigen::Vector2d(d.x(), d.z());
}

/// Writes what node `from` (at x, local fit f) says about the leaves of `block` (its own block, or a part of it).
void fill_leaves(const LodTree& tree, TreeId from, const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& f,
                 TreeId block, std::span<Eigen::Vector3d> leaves) {
  for_each_leaf(tree, block,
                [&](TreeId leaf) { leaves[static_cast<std::size_t>(leaf)] = block_point(tree, from, x, f, leaf); });
}

}  // namespace

void fill_block(const LodTree& tree, TreeId id, const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& f,
                std::span<Eigen::Vector3d> leaves) {
  fill_leaves(tree, id, x, f, id, leaves);
}

void reconstruct_leaves(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves) {
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
}

void committed_leaf_levels(const TcSoftBody& body, std::vector<int>& levels) {
  const LodTree& tree = body.tree();
  levels.resize(tree.leaf_count());
  for (int i = 0; i < body.node_count(); ++i) {
    const TreeId id = body.tree_id(i);
    if (!body.committed(id)) continue;  // leaving nodes belong to the old cut
    const int level = tree.node(id).level;
    for_each_leaf(tree, id, [&](TreeId leaf) { levels[static_cast<std::size_t>(leaf)] = level; });
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
