// The JSON summary of `tcsb compare` (--summary-json FILE): the gate's verdict and its counts, for scripts (CI reads
// whether behaviour changed or only timings failed from here, not from the Markdown).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "gate/gate_outcome.h"

namespace tcsb {

/// {"measure", "verdict": "pass" | "fail" | "undecided", "exit_code", "behaviour_changes", "regressions",
/// "undecided", "gated", "more_repetitions" (null unless undecided), "threshold", "alpha", "base", "new"}.
/// `exit_code` is what `tcsb compare` exits with for this outcome.
nlohmann::ordered_json gate_summary_json(const GateOutcome& outcome, int exit_code, const std::string& base_file,
                                         const std::string& next_file);

}  // namespace tcsb
