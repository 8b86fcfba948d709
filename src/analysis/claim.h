// A claim of the paper (e.g. "TC-SB is at least 3x faster than plain Bullet on the 128x128 net") checked against
// what the benchmark measured. A claim that could not be measured fails: silence is never a pass.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "analysis/bootstrap.h"

namespace tcsb {

/// How a measurement is compared with a claim's expected value.
enum class Comparison {
  kAtMost,   ///< pass iff measured <= expected + tolerance
  kAtLeast,  ///< pass iff measured >= expected - tolerance
  kWithin,   ///< pass iff |measured - expected| <= tolerance
};

/// A claim checked against a measurement: passes when `measured` compares to `expected` by `comparison` within
/// `tolerance`.
struct Claim {
  std::string id;                          ///< stable identifier, e.g. "speedup_128"
  std::string description;                 ///< the claim in words, as the paper states it
  Comparison comparison = Comparison::kAtMost;  ///< how measured is compared with expected
  double expected = 0.0;                   ///< the claimed value
  double tolerance = 0.0;                  ///< allowed slack, >= 0
  std::optional<double> measured;          ///< nullopt when not measured (or diverged, or non-finite); then fails
  bool pass = false;                       ///< the verdict
  /// Where `measured` could lie had the run been repeated (a bootstrap interval over repetitions), when computed.
  std::optional<Interval> interval;
};

/// Builds and judges a claim. A non-finite `measured` is stored as nullopt (and fails), so no NaN reaches a report.
/// Throws std::invalid_argument if `expected` or `tolerance` is non-finite or `tolerance` is negative.
Claim check_claim(std::string id, std::string description, Comparison c, double expected, double tolerance,
                  std::optional<double> measured);

/// Whether the claim's interval gives the same verdict throughout, i.e. the verdict is not within the run's noise;
/// nullopt when the claim has no interval (or no measurement).
std::optional<bool> decided(const Claim& claim);

/// True iff every claim passes; true for an empty list (nothing was claimed, so nothing failed).
bool all_pass(std::span<const Claim> claims);

/// Stable name of a comparison for reports: "at_most", "at_least" or "within".
const char* comparison_name(Comparison c);

}  // namespace tcsb
