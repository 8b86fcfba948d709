// The fidelity sections of the native JSON report: `fidelity` (settings, rows per method and compression, per-net
// cases, targets), `pareto` (the TC-SB time-versus-error sweep) and `max_compression`.
#pragma once

#include <nlohmann/json.hpp>

#include "paper/run_tables.h"
#include "run/run_result.h"

namespace tcsb {

/// Adds the three top-level keys to `doc` when the run has a fidelity pass (its tables computed in `tables`); leaves
/// `doc` alone otherwise.
void add_fidelity_json(const RunResult& result, const RunTables& tables, nlohmann::ordered_json& doc);

}  // namespace tcsb
