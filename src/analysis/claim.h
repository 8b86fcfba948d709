// A claim of the paper (e.g. "TC-SB at 30 % costs at most 0.43 x plain Bullet") checked against what the benchmark
// measured, with one of three verdicts: pass, fail, or undecided when the run's noise leaves both open. A claim
// that could not be measured fails: silence is never a pass.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "analysis/bootstrap.h"

namespace tcsb {

/// How a measurement is compared with a claim's expected value.
enum class Comparison {
  kAtMost,   ///< satisfied iff measured <= expected + tolerance
  kAtLeast,  ///< satisfied iff measured >= expected - tolerance
  /// satisfied iff |measured - expected| <= tolerance: an equivalence claim ("costs the same, within 3 %"). Judged
  /// on an interval it is two one-sided tests (TOST): it passes only when the whole interval lies in the band.
  kWithin,
};

/// Where a claim's measured value comes from, which decides how it is judged.
enum class Evidence {
  kDeterministic,  ///< an exact count, hash or metric the same on every run: judged on its value
  kRepeated,       ///< measured over noisy repetitions (wall time): judged on its interval, never on its value
};

/// What a claim's check concluded.
enum class Verdict {
  kPass,       ///< satisfied: by its value (deterministic) or over its whole interval (repeated)
  kFail,       ///< violated: by its value, over its whole interval, or not measured at all
  kUndecided,  ///< a repeated claim whose interval is partly satisfied, or that has no interval
};

/// A claim checked against a measurement: `measured` compared to `expected` by `comparison` within `tolerance`.
struct Claim {
  std::string id;                                ///< stable identifier, e.g. "tcsb_30_vs_plain"
  std::string description;                       ///< the claim in words, as the paper states it
  Comparison comparison = Comparison::kAtMost;   ///< how measured is compared with expected
  double expected = 0.0;                         ///< the claimed value
  double tolerance = 0.0;                        ///< allowed slack, >= 0
  Evidence evidence = Evidence::kDeterministic;  ///< how the verdict is reached
  std::optional<double> measured;                ///< nullopt when not measured (or diverged, or non-finite); then fails
  /// Where `measured` could lie had the run been repeated (a bootstrap interval over repetitions), when computed.
  std::optional<Interval> interval;
};

/// Builds a claim. A non-finite `measured` is stored as nullopt (and fails), so no NaN reaches a report. Throws
/// std::invalid_argument if `expected` or `tolerance` is non-finite or `tolerance` is negative.
Claim check_claim(std::string id, std::string description, Comparison c, double expected, double tolerance,
                  std::optional<double> measured, Evidence evidence = Evidence::kDeterministic);

/// Whether the value `x` satisfies the claim's comparison.
bool satisfies(const Claim& claim, double x);

/// The claim's verdict. Not measured: kFail. Deterministic: kPass or kFail on the measured value. Repeated: kPass
/// when every point of the interval satisfies the claim, kFail when none does, kUndecided otherwise and when there
/// is no interval. The point estimate never decides a repeated claim.
Verdict verdict(const Claim& claim);

/// True iff the verdict is kPass.
inline bool passed(const Claim& claim) { return verdict(claim) == Verdict::kPass; }

/// The verdict over a list: kFail if any claim fails, else kUndecided if any is undecided, else kPass (also for an
/// empty list: nothing was claimed, so nothing failed).
Verdict overall_verdict(std::span<const Claim> claims);

/// Stable name of a verdict for reports: "pass", "fail" or "undecided".
const char* verdict_name(Verdict v);

/// Stable name of a comparison for reports: "at_most", "at_least" or "within".
const char* comparison_name(Comparison c);

/// Stable name of an evidence kind for reports: "deterministic" or "repeated".
const char* evidence_name(Evidence e);

}  // namespace tcsb
