// What CutChurn counts: operations begun from the first counted step, those undoing a recent one on the same block,
// the body's nodes turning back, and how far they moved.
#include "world/cut_churn.h"

#include <gtest/gtest.h>

namespace tcsb {
namespace {

TEST(CutChurn, CountsOperationsThatUndoARecentOneOnTheSameBlock) {
  CutChurn churn(/*tree_size=*/8, /*window_steps=*/4, /*first_step=*/0);
  churn.begin_boundary(0);
  churn.cut_changed(OpKind::kRefine, 1);
  churn.cut_changed(OpKind::kRefine, 2);
  churn.cut_changed(OpKind::kEndRefine, 1);  // ends undo nothing and are not counted
  churn.begin_boundary(4);
  churn.cut_changed(OpKind::kCoarse, 1);  // 4 boundaries after its refine: undone
  churn.cut_changed(OpKind::kCoarse, 3);  // a block not operated on before
  churn.begin_boundary(9);
  churn.cut_changed(OpKind::kCoarse, 2);  // 9 after: detail that stayed
  churn.cut_changed(OpKind::kRefine, 3);  // 5 after its coarsen: outside the window
  churn.begin_boundary(10);
  churn.cut_changed(OpKind::kCoarse, 3);  // 1 after its refine
  const ChurnCounts& c = churn.counts();
  EXPECT_EQ(c.refines, 3);
  EXPECT_EQ(c.coarsens, 4);
  EXPECT_EQ(c.undone, 2);
}

TEST(CutChurn, RemembersTheWarmUpButCountsOnlyFromTheFirstStep) {
  CutChurn churn(8, 4, /*first_step=*/5);
  churn.begin_boundary(3);
  churn.cut_changed(OpKind::kRefine, 0);
  churn.end_boundary(100);
  churn.begin_boundary(5);
  churn.cut_changed(OpKind::kCoarse, 0);
  churn.end_boundary(97);
  EXPECT_EQ(churn.counts().refines, 0);
  EXPECT_EQ(churn.counts().coarsens, 1);
  EXPECT_EQ(churn.counts().undone, 1);
  EXPECT_EQ(churn.counts().nodes_moved, 3);  // the warm-up's move is not counted
}

TEST(CutChurn, CountsTheNodesTurningBackWithinTheWindow) {
  CutChurn churn(8, 4, 0);
  const auto boundary = [&churn](int step, int committed) {
    churn.begin_boundary(step);
    churn.end_boundary(committed);
  };
  boundary(0, 100);   // the first boundary sets where the body stands
  boundary(1, 103);   // up
  boundary(2, 103);   // no move
  boundary(5, 100);   // down 4 after the last move: a reversal
  boundary(6, 97);    // down again
  boundary(11, 100);  // up 5 after: outside the window
  boundary(12, 97);   // down 1 after: a reversal
  EXPECT_EQ(churn.counts().reversals, 2);
  EXPECT_EQ(churn.counts().nodes_moved, 3 + 3 + 3 + 3 + 3);
}

}  // namespace
}  // namespace tcsb
