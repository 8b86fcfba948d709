// Budget policy: how ranked candidates become operations under a node budget, with the paper's threshold (§5).
#pragma once

#include "../feedback/evaluator.h"
#include "../feedback/feedback_settings.h"
#include "../softbody/tc_softbody.h"

namespace tcsb {

/// What the policy remembers between steps.
struct BudgetState {
  bool converged = false;  ///< the body has fitted the budget once; from then on it must always fit
};

/// Begins operations from an evaluation (at most settings.max_ops_per_step):
///  1. while the committed cut is above the budget less a small reserve, coarsen the cheapest blocks;
///  2. refine the most salient nodes — free while under the budget, otherwise paid for by a coarse whose priority
///     is lower by more than settings.threshold, so a node is only inserted when its gain beats the penalty of the
///     removal plus the threshold and nothing flips back and forth;
///  3. once converged, never let the simulated (Bullet) node count exceed `budget`, blends included.
/// Candidates are re-checked (can_refine/can_coarsen), so a stale evaluation is safe. Returns operations begun.
int apply_evaluation(TcSoftBody& body, const Evaluation& evaluation, int budget, const FeedbackSettings& settings,
                     BudgetState& state);

/// Nodes kept free below the budget so operations can begin: a refine adds its children before the parent goes,
/// a coarse adds the parent before the children go.
int budget_reserve(int budget, int max_ops);

}  // namespace tcsb
