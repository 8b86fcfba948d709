// The world pass's section of the native JSON report: `world`, one row per method of a scene of many bodies.
#pragma once

#include <nlohmann/json.hpp>

#include "paper/run_tables.h"
#include "run/run_result.h"

namespace tcsb {

/// Adds `world` to `doc` when the run has a world pass, with its speed-up at equal error from `tables`
/// (run_tables(result)); leaves `doc` alone otherwise.
void add_world_json(const RunResult& result, const RunTables& tables, nlohmann::ordered_json& doc);

}  // namespace tcsb
