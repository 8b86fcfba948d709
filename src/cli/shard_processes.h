// A suite's repetitions run in several processes, one after another, and merged: what `tcsb reproduce --processes P`
// judges, so its intervals include the spread between processes that one process's repetitions cannot show
// (docs/sweeps.md, "Intervals of a merged result").
#pragma once

#include <filesystem>
#include <optional>

#include "sweep/shard_merge.h"

namespace tcsb::cli {

/// Runs `suite_file` (with --repetitions `repetitions` when given) as `processes` shards split by repetition, each
/// in a process of this executable of its own (`tcsb run --shard k/P --split repetitions`), one after another so they
/// do not measure each other, and merges them (sweep/shard_merge.h). Throws UsageError for a count below 1 or above
/// the suite's repetitions; std::runtime_error when a process fails (its own error line is on stderr).
MergedShards run_in_processes(const std::filesystem::path& suite_file, const std::optional<int>& repetitions,
                              int processes, int suite_repetitions);

}  // namespace tcsb::cli
