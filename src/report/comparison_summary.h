// The Markdown summary of `tcsb compare`: verdict, what was compared and how, one table row per timing metric
// (case, metric, base median, new median, change %, p-value, verdict) and one per changed deterministic value.
// Markdown because CI systems render it (GitHub's job summary, merge-request comments) and it reads fine as text.
#pragma once

#include <string>

#include "gate/gate_outcome.h"
#include "result/result_view.h"

namespace tcsb {

/// Behaviour-change rows shown at most; the rest are counted in one line (a changed seed changes every hash).
inline constexpr std::size_t kMaxChangeRows = 40;

/// The summary as Markdown, newline-terminated.
std::string comparison_summary_markdown(const GateOutcome& outcome, const ResultView& base, const ResultView& next);

/// One line for stderr: "PASS: ..." or "FAIL: N regressions, M behaviour changes ...".
std::string comparison_verdict_line(const GateOutcome& outcome);

/// Why the timings were not decided (outcome.timings_decided() is false), as one line without a period: no metric
/// in the gated family, or none with enough samples.
std::string undecided_reason(const GateOutcome& outcome);

}  // namespace tcsb
