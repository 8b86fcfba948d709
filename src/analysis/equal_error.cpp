#include "analysis/equal_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tcsb {

namespace {

void sort_by_time(std::vector<CurvePoint>& curve) {
  std::stable_sort(curve.begin(), curve.end(),
                   [](const CurvePoint& a, const CurvePoint& b) { return a.time_ms < b.time_ms; });
}

}  // namespace

const char* equal_error_status_name(EqualErrorStatus status) {
  switch (status) {
    case EqualErrorStatus::kInterpolated: return "interpolated";
    case EqualErrorStatus::kNotReached: return "not_reached";
    case EqualErrorStatus::kAtCheapest: return "at_cheapest";
  }
  return "unknown";
}

TimeAtError time_at_error(std::vector<CurvePoint> curve, double error) {
  if (curve.empty()) throw std::invalid_argument("time_at_error: an empty curve");
  if (!(error > 0)) throw std::invalid_argument("time_at_error: the error must be positive");
  for (const CurvePoint& p : curve)
    if (!(p.time_ms > 0) || !(p.error > 0) || !std::isfinite(p.time_ms) || !std::isfinite(p.error))
      throw std::invalid_argument("time_at_error: a point's time and error must be positive and finite");
  sort_by_time(curve);
  if (curve.front().error <= error) return {EqualErrorStatus::kAtCheapest, curve.front().time_ms};
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const CurvePoint& above = curve[i - 1];  // less accurate than `error` (else the walk would have stopped)
    const CurvePoint& at = curve[i];
    if (at.error > error) continue;
    // above.error > error >= at.error, so the slope's denominator is not 0.
    const double t = (std::log(error) - std::log(above.error)) / (std::log(at.error) - std::log(above.error));
    return {EqualErrorStatus::kInterpolated,
            std::exp(std::log(above.time_ms) + t * (std::log(at.time_ms) - std::log(above.time_ms)))};
  }
  return {EqualErrorStatus::kNotReached, 0.0};
}

bool is_monotone(std::vector<CurvePoint> curve) {
  sort_by_time(curve);
  for (std::size_t i = 1; i < curve.size(); ++i)
    if (curve[i].error > curve[i - 1].error) return false;
  return true;
}

}  // namespace tcsb
