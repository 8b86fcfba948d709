// Claims and targets as a console table (id, check, expected, measured, verdict), for the reproduction and the
// fidelity report alike.
#pragma once

#include <ostream>
#include <vector>

#include "analysis/claim.h"
#include "paper/sequential_claims.h"

namespace tcsb {

/// Prints `title` on its own line, then one row per claim with its verdict ("pass", "FAIL", "undecided"). When
/// any claim has an interval, an interval column too.
void print_claims(const char* title, const std::vector<Claim>& claims, std::ostream& out);

/// The same for claims judged in looks, with two more columns when any was judged on an interval: the look that
/// gave its verdict and the repetitions per case behind it; the interval column names no fixed confidence, since
/// later looks use stricter ones (shown in the look summary).
void print_claims(const char* title, const std::vector<TrackedClaim>& claims, std::ostream& out);

/// A verdict as the console shows it: "pass", "FAIL" (capitals: the one to look at) or "undecided".
const char* verdict_text(Verdict v);

}  // namespace tcsb
