// The fidelity pass as console tables: error, popping and energy drift per method and compression, the Pareto
// sweep, the maximal compression factor and the fidelity targets.
#pragma once

#include <iosfwd>

#include "paper/run_tables.h"
#include "run/run_result.h"

namespace tcsb {

/// Prints the fidelity tables (computed in `tables`) when the run has a fidelity pass; prints nothing otherwise.
void print_fidelity_report(const RunResult& result, const RunTables& tables, std::ostream& out);

}  // namespace tcsb
