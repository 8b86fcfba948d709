// The console report: the run as aligned human-readable tables (cases, Table 1, Table 2, the scaling fits), meant
// for stderr so stdout stays machine-readable JSON.
#pragma once

#include <iosfwd>

#include "paper/run_tables.h"
#include "run/run_result.h"

namespace tcsb {

/// Prints the cases (label, status, N, L, I, median ms, CV, paired ratio vs plain), Table 1, Table 2 and the
/// linear fits (slope, intercept, R²) as aligned plain text; "-" marks a value that was not measured. With axes,
/// all of these once per configuration, under a heading naming it. `tables` are run_tables(result).
void print_console_report(const RunResult& result, const RunTables& tables, std::ostream& out);

}  // namespace tcsb
