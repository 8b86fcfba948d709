// What no run of `tcsb run` writes, looked for in a result that is pooled (`tcsb tax`) or merged (`tcsb merge`):
// those commands build a verdict or a new result from the cases as they stand, so a case on a net the suite does not
// have, a node count that is not its net's, or repetitions numbered twice would be counted as if measured. The
// schema and read_result() check each field alone; this checks the fields against each other and the suite block.
#pragma once

#include "result/result_view.h"

namespace tcsb {

/// Throws InputError naming the file and the field when `result` holds what no run writes: a case on a net
/// suite.nets does not list, net_nodes other than that net's width x height, or repetitions that are not numbered
/// 0, 1, ... once each and at least suite.repetitions of them (a run writes every repetition of every case,
/// diverged or not; `reproduce` may add more).
/// In a result of `--measure instructions`, its instruction counts too (check_instruction_counts).
void check_run_is_possible(const ResultView& result);

/// Throws InputError naming the file and the field when a result of `--measure instructions` holds counts no run
/// writes: a case without `instructions` (a run counts every case), a case with ok repetitions that counts fewer
/// instructions than one per simulated node and timed step, or any while none is ok. A result of `--measure time`
/// passes. The instruction gate fails closed on what this refuses. (The listed functions are not bounded by the
/// total: callgrind's function costs over the dumps add up to a little more than the dumps' totals, 0.4 % in the
/// CI baseline.)
void check_instruction_counts(const ResultView& result);

}  // namespace tcsb
