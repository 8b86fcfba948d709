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

/// y at x on the line through (x0, y0) and (x1, y1) in log-log; x0 != x1, every value positive.
double log_log_between(double x0, double y0, double x1, double y1, double x) {
  const double t = (std::log(x) - std::log(x0)) / (std::log(x1) - std::log(x0));
  return std::exp(std::log(y0) + t * (std::log(y1) - std::log(y0)));
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
    return {EqualErrorStatus::kInterpolated, log_log_between(above.error, above.time_ms, at.error, at.time_ms, error)};
  }
  return {EqualErrorStatus::kNotReached, 0.0};
}

bool is_monotone(std::vector<CurvePoint> curve) {
  sort_by_time(curve);
  for (std::size_t i = 1; i < curve.size(); ++i)
    if (curve[i].error > curve[i - 1].error) return false;
  return true;
}

std::optional<double> error_at_nodes(std::vector<NodesPoint> curve, double nodes) {
  if (curve.empty()) throw std::invalid_argument("error_at_nodes: an empty curve");
  if (!(nodes > 0)) throw std::invalid_argument("error_at_nodes: the node count must be positive");
  for (const NodesPoint& p : curve)
    if (!(p.nodes > 0) || !(p.error > 0) || !std::isfinite(p.nodes) || !std::isfinite(p.error))
      throw std::invalid_argument("error_at_nodes: a point's nodes and error must be positive and finite");
  std::sort(curve.begin(), curve.end(), [](const NodesPoint& a, const NodesPoint& b) { return a.nodes < b.nodes; });
  for (std::size_t i = 1; i < curve.size(); ++i)
    if (curve[i].nodes == curve[i - 1].nodes)
      throw std::invalid_argument("error_at_nodes: two points of the same node count");
  for (std::size_t i = 0; i < curve.size(); ++i) {
    if (curve[i].nodes == nodes) return curve[i].error;
    if (i > 0 && curve[i - 1].nodes < nodes && nodes < curve[i].nodes)
      return log_log_between(curve[i - 1].nodes, curve[i - 1].error, curve[i].nodes, curve[i].error, nodes);
  }
  return std::nullopt;
}

}  // namespace tcsb
