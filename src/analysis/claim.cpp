#include "analysis/claim.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace tcsb {

namespace {

/// The values that satisfy the claim, as a closed interval (unbounded sides as +-infinity). Every comparison's
/// accepted set is one interval, so "the whole interval satisfies" and "no point satisfies" are containment and
/// disjointness.
Interval accepted(const Claim& claim) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  switch (claim.comparison) {
    case Comparison::kAtMost: return {-kInf, claim.expected + claim.tolerance};
    case Comparison::kAtLeast: return {claim.expected - claim.tolerance, kInf};
    case Comparison::kWithin: return {claim.expected - claim.tolerance, claim.expected + claim.tolerance};
  }
  return {kInf, -kInf};  // unreachable for valid enumerators: accepts nothing
}

}  // namespace

Claim check_claim(std::string id, std::string description, Comparison c, double expected, double tolerance,
                  std::optional<double> measured, Evidence evidence) {
  // Claims are written by us, not measured: a bad one is a programming error, so say so loudly.
  if (!std::isfinite(expected) || !std::isfinite(tolerance) || tolerance < 0.0)
    throw std::invalid_argument("check_claim '" + id + "': expected and tolerance must be finite, tolerance >= 0");

  Claim claim;
  claim.id = std::move(id);
  claim.description = std::move(description);
  claim.comparison = c;
  claim.expected = expected;
  claim.tolerance = tolerance;
  claim.evidence = evidence;
  if (measured && std::isfinite(*measured)) claim.measured = measured;
  return claim;
}

bool satisfies(const Claim& claim, double x) { return accepted(claim).contains(x); }

Verdict verdict(const Claim& claim) {
  if (!claim.measured) return Verdict::kFail;  // silence is never a pass
  if (claim.evidence == Evidence::kDeterministic)
    return satisfies(claim, *claim.measured) ? Verdict::kPass : Verdict::kFail;
  if (!claim.interval) return Verdict::kUndecided;  // too few repetitions to know the noise
  const Interval ok = accepted(claim);
  const Interval& ci = *claim.interval;
  if (ok.low <= ci.low && ci.high <= ok.high) return Verdict::kPass;
  if (ci.high < ok.low || ci.low > ok.high) return Verdict::kFail;
  return Verdict::kUndecided;
}

Verdict overall_verdict(std::span<const Claim> claims) {
  Verdict overall = Verdict::kPass;
  for (const Claim& c : claims) {
    const Verdict v = verdict(c);
    if (v == Verdict::kFail) return Verdict::kFail;
    if (v == Verdict::kUndecided) overall = Verdict::kUndecided;
  }
  return overall;
}

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::kPass: return "pass";
    case Verdict::kFail: return "fail";
    case Verdict::kUndecided: return "undecided";
  }
  return "unknown";  // unreachable for valid enumerators; keeps -Wreturn-type quiet
}

const char* comparison_name(Comparison c) {
  switch (c) {
    case Comparison::kAtMost: return "at_most";
    case Comparison::kAtLeast: return "at_least";
    case Comparison::kWithin: return "within";
  }
  return "unknown";
}

const char* evidence_name(Evidence e) {
  switch (e) {
    case Evidence::kDeterministic: return "deterministic";
    case Evidence::kRepeated: return "repeated";
  }
  return "unknown";
}

}  // namespace tcsb
