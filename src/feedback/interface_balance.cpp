#include "feedback/interface_balance.h"

namespace tcsb {

namespace {

/// +1 when the cloth at `q`'s place is simulated at q's level or coarser, -1 when finer, 0 when q does not exist.
int coarser_or_equal(const CutView& cut, TreeId q) {
  if (q == kNoTreeNode) return 0;
  const LodTree& tree = *cut.tree;
  for (TreeId a = q; a != kNoTreeNode; a = tree.node(a).parent)
    if (cut.committed(a)) return 1;
  return -1;
}

}  // namespace

int neighbour_balance(const CutView& cut, TreeId id) {
  const LodTree& tree = *cut.tree;
  const LodNode& n = tree.node(id);
  return coarser_or_equal(cut, tree.at(n.level, n.gx - 1, n.gy)) +
         coarser_or_equal(cut, tree.at(n.level, n.gx + 1, n.gy)) +
         coarser_or_equal(cut, tree.at(n.level, n.gx, n.gy - 1)) +
         coarser_or_equal(cut, tree.at(n.level, n.gx, n.gy + 1));
}

}  // namespace tcsb
