// Local edits of Bullet's node DBVT, so adding or removing a TC-SB node costs O(1) amortised instead of a
// descent from the root. The insertion's walk up stops at the first ancestor whose box already holds the new
// leaf: beside a moving cloth's own neighbour that is its parent or grandparent nearly always, but its worst case
// is the tree's depth (OpWork::dbvt_ancestors counts them; the op_work claims check that their mean over interior
// operations does not grow with the net).
//
// btDbvt::insert always descends from the root (O(log N), one cache miss per level on a large net) and
// btDbvt::remove refits every ancestor whose box shrinks. A TreeCut operation knows where its new node belongs —
// beside the leaf of the node it refines or coarsens — and a removal may leave ancestors' boxes loose (still
// containing everything below them: a valid hierarchy that Bullet's per-step refits and optimizeIncremental tighten).
// Both functions use only btDbvt's public members and Bullet's own node allocation (btAlignedAlloc/btAlignedFree,
// as btDbvt.cpp's createnode/deletenode, through DbvtNodeCache), so Bullet can update, optimise and free these nodes
// as its own.
#pragma once

#include <BulletCollision/BroadphaseCollision/btDbvt.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tcsb {

/// Spare DBVT nodes for the local edits. Adding a TC-SB node takes two tree nodes (its leaf and the pair above it)
/// and removing one gives two back; recycling them instead of calling btAlignedAlloc/btAlignedFree each time saves
/// about 150 instructions per allocation (a refine adds four nodes: 7 800 -> 6 400 instructions with the in-place
/// zeroing of tc_softbody.cpp, callgrind at 33^2), and a recycled node is usually still in cache. Every node is
/// still a block of its own from btAlignedAlloc, so Bullet may free a node that came from here, and a node Bullet
/// allocated may come back here, without harm.
class DbvtNodeCache {
 public:
  /// At most this many spare nodes are kept; more are freed.
  static constexpr std::size_t kMaxSpare = 1024;

  DbvtNodeCache() { spare_.reserve(kMaxSpare); }
  DbvtNodeCache(const DbvtNodeCache&) = delete;
  DbvtNodeCache& operator=(const DbvtNodeCache&) = delete;
  ~DbvtNodeCache();

  /// A node with this parent, no children and an empty box: a spare one when there is one.
  btDbvtNode* take(btDbvtNode* parent);
  /// Takes back a node that is no longer in any tree.
  void give(btDbvtNode* node);
  std::size_t spare() const { return spare_.size(); }
  /// Frees every spare node (before the tree is rebuilt elsewhere in memory).
  void release();

 private:
  std::vector<void*> spare_;  // storage from btAlignedAlloc, no node living in it
};

/// Inserts a new leaf (volume, data) as the sibling of the existing leaf `beside`, then enlarges ancestors' boxes
/// until one already contains the new pair (as btDbvt's insertleaf does after its descent). Returns the leaf. When
/// `ancestors` is given, adds to it the number of ancestor boxes the walk up visited (enlarged, or found containing).
btDbvtNode* insert_leaf_beside(btDbvt& tree, DbvtNodeCache& nodes, btDbvtNode* beside, const btDbvtVolume& volume,
                               void* data, std::int32_t* ancestors = nullptr);

/// Removes a leaf without shrinking its ancestors' boxes (they stay valid, only looser).
void remove_leaf_lazily(btDbvt& tree, DbvtNodeCache& nodes, btDbvtNode* leaf);

/// Checks the tree's structure: parent links, leaf count, and every internal box containing its children's.
/// Returns an empty string when sound, else the first problem. O(tree size); for validate().
const char* check_dbvt(const btDbvt& tree);

}  // namespace tcsb
