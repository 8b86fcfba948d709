#include "world/cut_churn.h"

namespace tcsb {

CutChurn::CutChurn(std::size_t tree_size, int window_steps, int first_step)
    : window_steps_(window_steps), first_step_(first_step), last_op_(tree_size) {}

void CutChurn::cut_changed(OpKind kind, TreeId block) {
  if (kind != OpKind::kRefine && kind != OpKind::kCoarse) return;  // their ends undo nothing
  BlockOp& last = last_op_[static_cast<std::size_t>(block)];
  if (counting()) {
    ++(kind == OpKind::kRefine ? counts_.refines : counts_.coarsens);
    if (last.any && last.kind != kind && recent(last.step)) ++counts_.undone;
  }
  last = {true, kind, step_};
}

void CutChurn::end_boundary(int committed_nodes) {
  const int before = committed_;
  committed_ = committed_nodes;
  if (before < 0 || committed_nodes == before) return;
  const int move = committed_nodes > before ? 1 : -1;
  if (counting()) counts_.nodes_moved += move * (committed_nodes - before);
  if (counting() && last_move_ == -move && recent(last_move_step_)) ++counts_.reversals;
  last_move_ = move;
  last_move_step_ = step_;
}

}  // namespace tcsb
