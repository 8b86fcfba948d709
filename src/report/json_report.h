// The native JSON report: everything a run measured, its context, and the paper's tables and fits, in a stable key
// order. Per-step series are left out (a long run would produce hundreds of megabytes); the per-repetition
// summaries and the deterministic final-state hashes are in.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "paper/run_tables.h"
#include "report/json_number.h"
#include "result/result_schema.h"
#include "run/run_result.h"

namespace tcsb {

/// A JSON document as output text: indented by `indent` (-1: all on one line), newline-terminated; invalid UTF-8 in
/// recorded strings (a host name, say) is replaced, not thrown on.
std::string json_text(const nlohmann::ordered_json& doc, int indent = 2);

/// The `context` block of every document tcsb writes: the machine and build (run/context.h), and the suite's
/// path, SHA-256 and seed.
nlohmann::ordered_json context_json(const Context& context, const Suite& suite);

/// The suite as run (after any command-line overrides): the `suite` block of every document tcsb writes.
nlohmann::ordered_json suite_json(const Suite& suite);

/// The whole run as the native JSON document (schema_version, tool, context, suite, cases, table1, table2,
/// scaling, [configurations when the suite has axes: per configuration its tables and fits, the run-wide tables
/// then empty], [fidelity, pareto, max_compression when the run has a fidelity pass; pareto_calibrated,
/// max_compression_calibrated when it has calibrated TC-SB], status, wall_s — in that
/// order); with axes every case has its `configuration` {label, axes} and the suite block its `axes`;
/// a shard's run is written by shard_json (report/shard_section.h), which adds what `tcsb merge` needs.
/// `tables` are run_tables(result): the document renders them and computes nothing.
nlohmann::ordered_json native_json(const RunResult& result, const RunTables& tables);

}  // namespace tcsb
