// The world pass as a console table: one row per method of a scene of many bodies.
#pragma once

#include <iosfwd>

#include "run/run_result.h"

namespace tcsb {

/// Prints the world pass's table when the run has one; prints nothing otherwise.
void print_world_report(const RunResult& result, std::ostream& out);

}  // namespace tcsb
