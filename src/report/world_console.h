// The world pass as a console table: one row per method of a scene of many bodies.
#pragma once

#include <iosfwd>

#include "paper/run_tables.h"
#include "run/run_result.h"

namespace tcsb {

/// Prints the world pass's table when the run has one, and its speed-up at equal error from `tables`
/// (run_tables(result)); prints nothing otherwise.
void print_world_report(const RunResult& result, const RunTables& tables, std::ostream& out);

}  // namespace tcsb
