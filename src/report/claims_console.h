// Claims and targets as a console table (id, check, expected, measured, verdict), for the reproduction and the
// fidelity report alike.
#pragma once

#include <ostream>
#include <vector>

#include "analysis/claim.h"

namespace tcsb {

/// Prints `title` on its own line, then one row per claim. When any claim has an interval, two more columns: the
/// 95 % interval and whether the verdict is beyond noise ("yes", "no", "-" without an interval).
void print_claims(const char* title, const std::vector<Claim>& claims, std::ostream& out);

}  // namespace tcsb
