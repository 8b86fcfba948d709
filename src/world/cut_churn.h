// CutChurn: how many operations a TC-SB body of the world pass begins, and how many of them only undo a recent one —
// the part of its operations that buys no lasting detail, whatever it costs (issue 57: the world budget's bodies
// operate about twice as often as per-body ones).
#pragma once

#include <cstddef>
#include <vector>

#include "softbody/cut_listener.h"
#include "world/world_result.h"

namespace tcsb {

/// Listens to one body's cut (TcSoftBody::set_cut_listener) and is told each boundary's step and the committed
/// nodes after it; counts from `first_step` on (the measured steps), remembering the warm-up's operations. O(1) an
/// operation: the last one of each of the body's `tree_size` blocks is kept.
class CutChurn final : public CutListener {
 public:
  CutChurn(std::size_t tree_size, int window_steps, int first_step);
  /// Before the boundary's operations.
  void begin_boundary(int step) { step_ = step; }
  /// After them: the body's committed nodes now.
  void end_boundary(int committed_nodes);
  void cut_changed(OpKind kind, TreeId block) override;
  const ChurnCounts& counts() const { return counts_; }

 private:
  struct BlockOp {
    bool any = false;  // an operation was begun on the block
    OpKind kind = OpKind::kRefine;
    int step = 0;
  };
  bool counting() const { return step_ >= first_step_; }
  bool recent(int step) const { return step_ - step <= window_steps_; }

  int window_steps_;
  int first_step_;
  int step_ = 0;
  std::vector<BlockOp> last_op_;  // by tree id
  int committed_ = -1;            // before the first boundary: unknown
  int last_move_ = 0;             // sign of the committed nodes' last change
  int last_move_step_ = 0;
  ChurnCounts counts_;
};

}  // namespace tcsb
