// Cut adjacency: which nodes of a cut through the LOD tree touch a given node's block along an edge. Pure tree
// arithmetic, O(1): a balanced cut (neighbours at most one level apart) has at most two neighbours per side.
#pragma once

#include "../net/lod_tree.h"

namespace tcsb {

/// The four sides of a block, as grid steps.
inline constexpr int kSideDx[4] = {1, -1, 0, 0};
inline constexpr int kSideDy[4] = {0, 0, 1, -1};

/// Calls visit(n) for every cut node n whose block shares an edge with the block of `x` (x itself need not be in
/// the cut). `in_cut(id)` tells membership. Looks at the same level, one level up and one level down across each
/// side; returns false if some side holds no cut node within one level — the cut is then not balanced.
template <class InCut, class Visit>
bool for_each_cut_neighbour(const LodTree& tree, TreeId x, InCut&& in_cut, Visit&& visit) {
  const LodNode& node = tree.node(x);
  const int level = node.level;
  bool balanced = true;
  for (int side = 0; side < 4; ++side) {
    const int dx = kSideDx[side], dy = kSideDy[side];
    const TreeId across = tree.at(level, node.gx + dx, node.gy + dy);
    if (across == kNoTreeNode) continue;  // net border
    if (in_cut(across)) {
      visit(across);
      continue;
    }
    // Grid arithmetic instead of reading the LodNode of `across` (a node off the cut, so a likely cache miss): a
    // node's parent is the node at half its coordinates one level up.
    const int ax = node.gx + dx, ay = node.gy + dy;
    const TreeId up = tree.at(level + 1, ax >> 1, ay >> 1);
    if (up != kNoTreeNode && up != node.parent && in_cut(up)) {
      visit(up);
      continue;
    }
    if (level == 0) {
      balanced = false;
      continue;
    }
    // The (up to two) children of `across` on the side facing x.
    bool found = false;
    for (int k = 0; k < 2; ++k) {
      const int cx = dx != 0 ? 2 * ax + (dx > 0 ? 0 : 1) : 2 * ax + k;
      const int cy = dy != 0 ? 2 * ay + (dy > 0 ? 0 : 1) : 2 * ay + k;
      const TreeId c = tree.at(level - 1, cx, cy);
      if (c == kNoTreeNode) continue;
      if (!in_cut(c)) {
        balanced = false;
        continue;
      }
      visit(c);
      found = true;
    }
    if (!found) balanced = false;
  }
  return balanced;
}

/// Whether the block of `x` and the eight blocks of its level around it are all whole blocks inside the net: the
/// block's leaf extent grown by one block of its level (2^level leaves) on every side lies inside the grid. Such a
/// block has the same neighbourhood on every net (a full side, full-size neighbours and children all round); a block
/// at the border has fewer. Grid arithmetic on the block's own LodNode, O(1).
inline bool neighbourhood_inside_net(const LodTree& tree, TreeId x) {
  const LodNode& node = tree.node(x);
  const int block = 1 << node.level;
  return node.leaf_x0 - block >= 0 && node.leaf_y0 - block >= 0 && node.leaf_x1 + block <= tree.level_width(0) &&
         node.leaf_y1 + block <= tree.level_height(0);
}

}  // namespace tcsb
