#include "feedback/interface_balance.h"

#include <cmath>

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

int budget_level(const LodTree& tree, int budget) {
  const auto count = [&](int level) { return static_cast<double>(tree.level_width(level)) * tree.level_height(level); };
  for (int level = 0; level + 1 < tree.level_count(); ++level) {
    const double fine = count(level), coarse = count(level + 1);
    if (budget >= fine) return level;
    if (budget > coarse) return (budget - coarse) / (fine - coarse) >= 0.5 ? level : level + 1;
  }
  return tree.level_count() - 1;
}

double InterfaceCharge::factor(const CutView& cut, TreeId id) const {
  if (!(per_boundary > 0)) return 1.0;
  const double w = weight.empty() ? 1.0 : static_cast<double>(weight[static_cast<std::size_t>(id)]);
  double exponent = -per_boundary * w * neighbour_balance(cut, id);
  if (pull > 0 && w > 1)
    exponent -= per_boundary * pull * (w - 1) * (budget_level >= cut.tree->node(id).level ? 1 : -1);
  return std::exp(exponent / 4.0);
}

}  // namespace tcsb
