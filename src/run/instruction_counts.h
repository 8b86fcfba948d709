// The instruction counts of a run measured with `--measure instructions`: the meter's dumps (run/callgrind_dumps.h)
// read into each repetition's parts and each case's totals and functions, once the run has finished.
#pragma once

#include "run/callgrind_dumps.h"
#include "run/run_result.h"

namespace tcsb {

/// Fills every repetition's `instructions` from its `metered` parts (cleared afterwards), and every case's
/// `instructions` and `functions` from its ok repetitions. Throws CallgrindFileError naming `file` when a part's dump
/// is not in `dumps`.
void attach_instruction_counts(RunResult& result, const MeterDumps& dumps, const std::string& file);

}  // namespace tcsb
