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
void check_run_is_possible(const ResultView& result);

}  // namespace tcsb
