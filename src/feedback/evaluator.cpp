#include "feedback/evaluator.h"

#include <algorithm>
#include <cmath>

#include "feedback/interface_balance.h"

namespace tcsb {

namespace {

/// Nodes with equal saliency (a cloth at rest: all zero) would otherwise be taken in id order, sweeping the net
/// from one corner. A small floor makes finer blocks go first and a hash of the id spreads ties over the net.
constexpr double kSaliencyFloor = 1e-3;
std::uint32_t spread(TreeId id) { return static_cast<std::uint32_t>(id) * 2654435761u; }

/// Keeps the `limit` best of `all` under `better` (a strict total order, so the result does not depend on the
/// order the candidates were found in), best first. O(n + limit log limit): a selection, then a sort of the kept.
template <class Better>
void keep_best(std::vector<Candidate>& all, int limit, Better better) {
  const auto keep = static_cast<std::size_t>(std::max(limit, 0));
  if (all.size() > keep) {
    std::nth_element(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(keep), all.end(), better);
    all.resize(keep);
  }
  std::sort(all.begin(), all.end(), better);
}

}  // namespace

void rank_candidates(const CutSnapshot& snapshot, std::span<const float> saliency, int limit, Evaluation& out,
                     const JumpCharge& charge, const InterfaceCharge& interface) {
  const LodTree& tree = *snapshot.cut.tree;
  out.snapshot_step = snapshot.step;
  const auto higher = [](const Candidate& a, const Candidate& b) {
    return a.priority != b.priority ? a.priority > b.priority : spread(a.id) < spread(b.id);
  };
  const auto lower = [](const Candidate& a, const Candidate& b) {
    return a.priority != b.priority ? a.priority < b.priority : spread(a.id) < spread(b.id);
  };
  out.refine.clear();
  out.coarse.clear();
  // Tree order rather than simulation order: the tree's nodes are then read front to back instead of at random,
  // which was most of the evaluation's cost (a cache miss per cut node). The ranking is the same either way.
  const std::span<const LodNode> nodes = tree.nodes();
  for (std::size_t id = 0; id < nodes.size(); ++id) {
    if (snapshot.cut.state[id] != CutState::kActive) continue;
    const LodNode& node = nodes[id];
    const float s = saliency[static_cast<std::size_t>(snapshot.cut.index[id])];
    if (!node.is_leaf()) {
      double priority = (s + kSaliencyFloor) * static_cast<double>(1u << node.level);
      // A refine adds a level boundary towards every neighbour at its level or coarser and removes one towards every
      // finer neighbour: a positive balance lowers the priority.
      priority *= interface.factor(snapshot.cut, static_cast<TreeId>(id));
      out.refine.push_back({priority, static_cast<TreeId>(id)});
    }
    // Each parent once: from its first child (the even-even corner of the block, so the parent is read only for a
    // quarter of the nodes), when every child is active.
    const TreeId parent = node.parent;
    if (parent == kNoTreeNode || (node.gx & 1) != 0 || (node.gy & 1) != 0) continue;
    const LodNode& p = tree.node(parent);
    if (!p.simulable()) continue;
    double worst = 0;
    bool all_active = true;
    for (int c = 0; c < p.child_count && all_active; ++c) {
      const TreeId child = p.children[static_cast<std::size_t>(c)];
      all_active = snapshot.cut.state[static_cast<std::size_t>(child)] == CutState::kActive;
      if (all_active) {
        const auto index = static_cast<std::size_t>(snapshot.cut.index[static_cast<std::size_t>(child)]);
        worst = std::max<double>(worst, saliency[index]);
      }
    }
    if (!all_active) continue;
    double priority = (worst + kSaliencyFloor) * static_cast<double>(1u << p.level);
    // A coarsen removes the boundary towards every neighbour at the parent's level or coarser and adds one towards
    // every finer neighbour: a positive balance lowers the priority (lower coarsens sooner).
    priority *= interface.factor(snapshot.cut, parent);
    if (charge.per_pct > 0)
      priority += charge.per_pct * 100.0 * coarse_jump(snapshot, *charge.neighbours, parent) / charge.extent;
    if (charge.per_px > 0)
      priority += charge.per_px * coarse_jump_px(snapshot, *charge.neighbours, parent, *charge.view);
    out.coarse.push_back({priority, parent});
  }
  keep_best(out.refine, limit, higher);
  keep_best(out.coarse, limit, lower);
}

}  // namespace tcsb
