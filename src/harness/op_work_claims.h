// The deterministic witness of the paper's Figure 4 ("the TreeCut operations are constant in time"): per operation,
// the work it counts (OpWork) has the same maximum and the same mean on every net of the run, and no maximum exceeds
// the bound derived from the cut's invariants (softbody/op_work_bounds.h). Wall time on this machine is decided by
// its memory hierarchy; these counts are decided by the code alone.
#pragma once

#include <string>
#include <vector>

#include "analysis/claim.h"
#include "harness/op_work.h"
#include "harness/run_result.h"

namespace tcsb {

/// How far the per-net maxima and means of a count may spread across nets: (largest - smallest) / largest.
inline constexpr double kOpWorkSpreadTolerance = 0.05;

/// The counts the witness checks: every OpWork count the cut's invariants bound. The DBVT ancestors walk is left
/// out: its length depends on where a new node lies relative to its neighbours' boxes, not on the cut (OpWork).
inline constexpr OpWorkCount kOpWorkWitnessCounts[] = {OpWorkCount::kNodes, OpWorkCount::kLinks,
                                                       OpWorkCount::kTreeRecords, OpWorkCount::kDbvtLeaves};

/// One net's operation work: every TC-SB case of the net pooled (all budgets, all repetitions).
struct NetOpWork {
  std::string net;
  std::int64_t net_nodes = 0;
  OpWorkTally tally;
};

/// The TC-SB cases' operation work per net, in the order the nets first appear among the cases; nets without a
/// TC-SB case are absent.
std::vector<NetOpWork> op_work_by_net(const RunResult& result);

/// (largest - smallest) / largest of `values`; 0 when all are 0 or there are none.
double relative_spread(const std::vector<double>& values);

/// One claim per operation, id "op_work_<operation>" (op_kind_name). measured is the worst of, over the checked
/// counts: each count's spread across nets of the per-net maximum and of the per-net mean divided by
/// kOpWorkSpreadTolerance, and each net's maximum divided by its bound; the claim passes iff measured <= 1. It is
/// unmeasured (fails) when fewer than two nets have TC-SB cases, or when a net has no call of the operation.
std::vector<Claim> op_work_claims(const RunResult& result);

}  // namespace tcsb
