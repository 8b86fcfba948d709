#include "analysis/claim.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace tcsb {

namespace {

bool passes(Comparison c, double expected, double tolerance, double m) {
  switch (c) {
    case Comparison::kAtMost: return m <= expected + tolerance;
    case Comparison::kAtLeast: return m >= expected - tolerance;
    case Comparison::kWithin: return std::fabs(m - expected) <= tolerance;
  }
  return false;
}

}  // namespace

Claim check_claim(std::string id, std::string description, Comparison c, double expected, double tolerance,
                  std::optional<double> measured) {
  // Claims are written by us, not measured: a bad one is a programming error, so say so loudly.
  if (!std::isfinite(expected) || !std::isfinite(tolerance) || tolerance < 0.0)
    throw std::invalid_argument("check_claim '" + id + "': expected and tolerance must be finite, tolerance >= 0");

  Claim claim;
  claim.id = std::move(id);
  claim.description = std::move(description);
  claim.comparison = c;
  claim.expected = expected;
  claim.tolerance = tolerance;
  if (measured && std::isfinite(*measured)) claim.measured = measured;
  if (!claim.measured) return claim;  // not measured: fails

  claim.pass = passes(c, expected, tolerance, *claim.measured);
  return claim;
}

std::optional<bool> decided(const Claim& claim) {
  if (!claim.interval || !claim.measured) return std::nullopt;
  const auto verdict = [&](double m) { return passes(claim.comparison, claim.expected, claim.tolerance, m); };
  const Interval& ci = *claim.interval;
  if (verdict(ci.low) != claim.pass || verdict(ci.high) != claim.pass) return false;
  // A failing "within" claim: both ends outside the band, but they must be on the same side of it.
  if (claim.comparison == Comparison::kWithin && !claim.pass)
    return (ci.low > claim.expected) == (ci.high > claim.expected);
  return true;
}

bool all_pass(std::span<const Claim> claims) {
  return std::all_of(claims.begin(), claims.end(), [](const Claim& c) { return c.pass; });
}

const char* comparison_name(Comparison c) {
  switch (c) {
    case Comparison::kAtMost: return "at_most";
    case Comparison::kAtLeast: return "at_least";
    case Comparison::kWithin: return "within";
  }
  return "unknown";  // unreachable for valid enumerators; keeps -Wreturn-type quiet
}

}  // namespace tcsb
