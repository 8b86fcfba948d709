// What a shard's result carries for `tcsb merge` (sweep/shard_merge.h), written here and read there: the
// `merge_data` section, what the merge needs beyond the summaries a result keeps —
//
// {"suite_file": the suite file's text,
//  "op_samples": {TC-SB case label: {"kind": [...], "node_ns": [...], "link_ns": [...], "nodes": [...],
//                 "links": [...], "interior": [0/1...], "work": {count name: [...] for each OpWork count}}},
//  "breakdown_ms": {case label: [[bullet, feedback, operations, blending] per repetition, in recording order]}}
//
// Columns in recording order: a case's operation samples are its repetitions' in turn (each repetition records
// `operations` of them). `breakdown_ms` is absent from shards written before the split by repetition.
#pragma once

#include <nlohmann/json.hpp>

#include "paper/run_tables.h"
#include "run/run_result.h"

namespace tcsb {

/// The operation sample columns of merge_data.op_samples, in order, besides the work counts.
inline constexpr const char* kMergeSampleColumns[] = {"kind", "node_ns", "link_ns", "nodes", "links", "interior"};

/// The per-repetition step breakdown's parts in merge_data.breakdown_ms, in order (StepBreakdown's).
inline constexpr const char* kMergeBreakdownParts[] = {"bullet", "feedback", "operations", "blending"};

/// The `merge_data` section of a shard's result.
nlohmann::ordered_json merge_data_json(const RunResult& result);

/// A shard's result (result.shard set): native_json(result, tables) with context.shard {k, n, split} and, last,
/// merge_data_json(result).
nlohmann::ordered_json shard_json(const RunResult& result, const RunTables& tables);

}  // namespace tcsb
