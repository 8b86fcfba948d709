// The merge of shards: a shard (`tcsb run SUITE --shard K/N`, sweep/shard_plan.h) writes a normal result of its own
// cases (with a split by repetition: its repetitions of them) plus `merge_data` (report/shard_section.h) — the suite
// file's bytes, every TC-SB case's operation samples and every repetition's step breakdown, which the normal result
// summarises away. `tcsb merge` checks that a set of shard results is one suite, build, settings and split, covered
// exactly once, and rebuilds the run they make up (RunResult), each repetition marked with the shard (process) that
// measured it, so Table 1, Table 2, the fits and the fidelity tables and targets are computed from the merged cases by
// the very code a single `tcsb run` uses, on the cases and repetitions in the order the unsharded run has them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "paper/run_tables.h"
#include "result/result_view.h"
#include "run/run_result.h"

namespace tcsb {

/// One shard result as read from its file (result/result_file.h has checked it against the schema).
struct ShardDocument {
  std::string file;                 ///< the name used in errors
  nlohmann::ordered_json document;  ///< the parsed result
};

/// A merged run: the result, the context block to write, and the warnings the merge adds.
struct MergedShards {
  RunResult result;                   ///< every case of the suite in unsharded order, summarised again
  nlohmann::ordered_json context;     ///< shard 1's context without `shard`, all shards' warnings, `merged_shards`
  std::vector<std::string> warnings;  ///< new warnings of the merge (different machines), also in context.warnings
};

/// Merges shard results. Throws InputError (one line naming the file and the field) when a file is not a
/// shard, the shards are of different suites, settings, seeds or builds, of different shard counts or splits, the
/// same shard is given twice or one is missing (so a repetition would be missing or counted twice), or a shard's
/// cases or repetitions are not the ones its index assigns. Each merged repetition's `process` is its shard's k. Warns
/// when the shards ran on different machines (host or CPU model): their absolute times then mix machines, though every
/// same-shard ratio stays valid.
MergedShards merge_shards(const std::vector<ShardDocument>& shards);

/// The merged native JSON document: native_json(merged.result, tables) with merged.context as its context block.
nlohmann::ordered_json merged_json(const MergedShards& merged, const RunTables& tables);

}  // namespace tcsb
