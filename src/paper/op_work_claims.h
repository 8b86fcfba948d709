// The deterministic witness of the paper's Figure 4 ("the TreeCut operations are constant in time"): per operation,
// (a) no count's maximum, the swap-with-last's relocations included, exceeds the bound derived from the cut's
// invariants (softbody/op_work_bounds.h) on any net: a hidden loop over anything sized by the net would eventually
// exceed a constant; and (b) each block-local count has the same maximum over all calls and the same mean over the
// interior calls (OpWork::interior) on every net. The mean over all calls is not compared: border blocks have fewer
// neighbours and children, and their share falls as 1 / width, so it rises with the net for reasons of geometry.
// Wall time on this machine is decided by its memory hierarchy; these counts are decided by the code alone.
#pragma once

#include <string>
#include <vector>

#include "analysis/claim.h"
#include "paper/op_work.h"
#include "run/run_result.h"

namespace tcsb {

/// How far the per-net maxima and interior means of a count may spread across nets: (largest - smallest) / largest.
inline constexpr double kOpWorkSpreadTolerance = 0.05;

/// The counts whose maximum must be within its bound: every OpWork count the cut's invariants bound. The DBVT
/// ancestors walk is left out: its length depends on where a new node lies relative to its neighbours' boxes, not
/// on the cut (OpWork); it is reported, not judged.
inline constexpr OpWorkCount kOpWorkBoundedCounts[] = {OpWorkCount::kNodes,           OpWorkCount::kLinks,
                                                       OpWorkCount::kTreeRecords,     OpWorkCount::kDbvtLeaves,
                                                       OpWorkCount::kRelocationNodes, OpWorkCount::kRelocationLinks};

/// The block-local counts: those that measure the operation's block and its neighbourhood only, whose maximum and
/// interior mean must agree across nets. The relocation counts depend on which node or link is last in Bullet's
/// arrays, a draw unrelated to the block: bounded, not compared.
inline constexpr OpWorkCount kOpWorkBlockLocalCounts[] = {OpWorkCount::kNodes, OpWorkCount::kLinks,
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

/// One claim per operation, id "op_work_<operation>" (op_kind_name). measured is the worst of: each bounded count's
/// per-net maximum divided by its bound (on every net), and each block-local count's spread across nets of the
/// per-net maximum and of the per-net interior mean, divided by kOpWorkSpreadTolerance; the claim passes iff
/// measured <= 1. It is unmeasured (fails) when fewer than two nets have TC-SB cases, or when a net has no call, or
/// no interior call, of the operation.
std::vector<Claim> op_work_claims(const RunResult& result);

}  // namespace tcsb
