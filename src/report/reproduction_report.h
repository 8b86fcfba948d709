// The reproduction's report (paper/reproduction.h judges it and computes its tables): our Tables 1 and 2 beside the
// paper's, Figure 5's fits, the claims with their verdicts — as a JSON section appended to the native report, and
// as text for the console. Renders only: everything it shows is in the Reproduction it is given.
#pragma once

#include <iosfwd>

#include <nlohmann/json.hpp>

#include "paper/reproduction.h"

namespace tcsb {

/// The `reproduction` section: side-by-side tables (paper, ours), Figure 5's fits, claims and targets (each with its
/// verdict, interval, look and repetitions), the looks, the overall verdict, wall time.
nlohmann::ordered_json reproduction_json(const Reproduction& reproduction);

/// Both tables side by side with the paper's, then every claim of the paper with its verdict; the project's own
/// targets too with `with_targets`, else one line saying where they are.
void print_reproduction(const Reproduction& reproduction, bool with_targets, std::ostream& out);

}  // namespace tcsb
