// LodTree: the precomputed level-of-detail hierarchy over a grid net. Leaves are the grid nodes (level 0); each
// parent at level k+1 stands for the 2x2 block of level-k nodes below it (partial blocks at the borders of grids
// that are not powers of two). Ids and flat arrays, no pointers, so it can be shared read-only by any number of
// bodies and threads.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "../net/net_spec.h"

namespace tcsb {

/// Index of a node in the LOD tree. Leaves have the same id as their grid node (level 0 comes first).
using TreeId = std::int32_t;
inline constexpr TreeId kNoTreeNode = -1;

/// One node of the LOD tree: what the TreeCut operations and the feedback stage read of it, in one cache line
/// (its rest position and centroid are kept apart, LodTree::rest() and centroid()). An operation reads a block's
/// node and its children's, scattered over two rows of a level; at 64 bytes each costs one line where 112 cost
/// two, and lines are what an operation's time grows with on a large net (src/softbody/tc_prefetch.cpp).
struct alignas(64) LodNode {
  std::int16_t level = 0;             ///< 0 for leaves
  std::int8_t child_count = 0;        ///< 0 for leaves, 1..4 otherwise
  std::int8_t pinned_leaf_count = 0;  ///< pinned grid nodes inside this block
  std::int32_t gx = 0, gy = 0;        ///< coordinates in its level's grid
  TreeId parent = kNoTreeNode;        ///< kNoTreeNode for the root
  double mass = 0.0;                  ///< sum of the leaves' masses
  std::array<TreeId, 4> children{kNoTreeNode, kNoTreeNode, kNoTreeNode, kNoTreeNode};
  std::int32_t leaf_x0 = 0, leaf_y0 = 0;  ///< covered leaves: [leaf_x0, leaf_x1) x [leaf_y0, leaf_y1)
  std::int32_t leaf_x1 = 0, leaf_y1 = 0;
  TreeId anchor_leaf = kNoTreeNode;  ///< the pinned leaf inside, when exactly one; else kNoTreeNode

  bool is_leaf() const { return child_count == 0; }
  bool pinned() const { return pinned_leaf_count > 0; }
  /// A node may be simulated only if it holds at most one pinned leaf (otherwise two fixed corners would have to
  /// share one simulated point).
  bool simulable() const { return pinned_leaf_count <= 1; }
};
static_assert(sizeof(LodNode) == 64, "one LOD node per cache line");

/// The LOD hierarchy of one grid. Built once in O(N), immutable afterwards.
class LodTree {
 public:
  /// Builds the tree over a width x height grid whose leaves have the given rest positions, masses and pins.
  LodTree(int width, int height, std::span<const Eigen::Vector3d> leaf_rest, std::span<const double> leaf_mass,
          std::span<const std::uint8_t> leaf_pinned, RestPlacement placement = RestPlacement::kCentroid);

  /// All nodes, leaves first, then level by level, row-major within a level.
  std::span<const LodNode> nodes() const { return nodes_; }
  const LodNode& node(TreeId id) const { return nodes_[static_cast<std::size_t>(id)]; }
  /// Mass-weighted centroid of the node's leaves' rest positions.
  const Eigen::Vector3d& centroid(TreeId id) const { return centroid_[static_cast<std::size_t>(id)]; }
  /// Where the node rests when simulated. A block holding one pinned leaf rests on that leaf, so a pinned corner
  /// stays exactly fixed whatever level represents it. Otherwise, with RestPlacement::kCentroid, at its centroid,
  /// except that a block touching one border of the net along an axis rests on that border along that axis (x for
  /// the first and last columns, z for the first and last rows), as a uniform grid's edge nodes do; with
  /// RestPlacement::kVertex, on its first leaf, or along an axis where it touches only the last border, on that
  /// border (along an axis where it spans the whole net, at its centroid). Leaves rest where the net puts them.
  const Eigen::Vector3d& rest(TreeId id) const { return rest_[static_cast<std::size_t>(id)]; }
  RestPlacement placement() const { return placement_; }
  /// With RestPlacement::kVertex, the leaf a node rests on: its pinned leaf, else its first leaf, or along an axis
  /// where its block touches only the net's last border the last one (along an axis its block spans whole it rests at
  /// its centroid, and its first leaf stands in). O(1).
  TreeId rest_leaf(TreeId id) const {
    const LodNode& n = node(id);
    if (n.anchor_leaf != kNoTreeNode) return n.anchor_leaf;
    const int width = level_width(0), height = level_height(0);
    return at(0, n.leaf_x1 == width && n.leaf_x0 != 0 ? width - 1 : n.leaf_x0,
              n.leaf_y1 == height && n.leaf_y0 != 0 ? height - 1 : n.leaf_y0);
  }
  /// Whether the node's block touches a border of the net. Reads the node alone (not the rest and centroid arrays,
  /// which an operation avoids).
  bool touches_border(const LodNode& n) const {
    return n.leaf_x0 == 0 || n.leaf_y0 == 0 || n.leaf_x1 == level_width_[0] || n.leaf_y1 == level_height_[0];
  }
  /// Whether a block without a pin may rest away from its centroid: with kCentroid only a block touching a border,
  /// with kVertex every block of more than one leaf. Reads the node alone, as touches_border() does.
  bool may_rest_off_centroid(const LodNode& n) const {
    return placement_ == RestPlacement::kVertex || touches_border(n);
  }
  std::size_t size() const { return nodes_.size(); }
  std::size_t leaf_count() const { return static_cast<std::size_t>(level_width_[0]) * level_height_[0]; }
  int level_count() const { return static_cast<int>(level_width_.size()); }
  int level_width(int level) const { return level_width_[static_cast<std::size_t>(level)]; }
  int level_height(int level) const { return level_height_[static_cast<std::size_t>(level)]; }
  TreeId root() const { return static_cast<TreeId>(nodes_.size() - 1); }
  /// The node's place in the row-major order of every node's block centre on the net (ties: lower id first), a
  /// permutation of 0..size()-1. Sorting a cut by it puts the finest cut in grid order, and coarser blocks between
  /// the rows and columns of their leaves: how TcSoftBody keeps Bullet's arrays in a plain body's order.
  std::int32_t spatial_rank(TreeId id) const { return spatial_rank_[static_cast<std::size_t>(id)]; }

  /// The leaf at (gx, gy), which must be on the grid (unchecked, unlike at(0, gx, gy): the leaves are the ids
  /// 0 .. leaf_count() - 1, row-major). For the climbs from a leaf that callers bound already. O(1).
  TreeId leaf_at(int gx, int gy) const { return gy * level_width_[0] + gx; }

  /// The node at (gx, gy) of a level, or kNoTreeNode outside the level's grid. O(1).
  TreeId at(int level, int gx, int gy) const {
    if (level < 0 || level >= level_count() || gx < 0 || gy < 0 || gx >= level_width(level) ||
        gy >= level_height(level))
      return kNoTreeNode;
    return level_offset_[static_cast<std::size_t>(level)] + gy * level_width(level) + gx;
  }

 private:
  /// Fills spatial_rank_ once the nodes' leaf ranges are known.
  void rank_block_centres();

  std::vector<LodNode> nodes_;
  std::vector<Eigen::Vector3d> centroid_, rest_;  // per node, beside nodes_: read only when building and measuring
  std::vector<std::int32_t> spatial_rank_;        // per node
  std::vector<int> level_width_, level_height_;
  std::vector<TreeId> level_offset_;
  RestPlacement placement_ = RestPlacement::kCentroid;
};

}  // namespace tcsb
