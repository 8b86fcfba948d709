// Time at equal error: where a rival's curve of error against step time reaches a given error. The field reports
// adaptivity as a speed-up at equal quality (Koh, Narain and O'Brien 2014/2015; Lee et al. 2010): for the error an
// adaptive body reaches, how long the non-adaptive rival's step must be to reach it too. And its twin at equal cost
// in nodes: the error a curve of error against node count has at a given count. Pure functions.
#pragma once

#include <optional>
#include <vector>

namespace tcsb {

/// One body of a curve: its step time and its error (both positive; the error in whatever unit the curve uses).
struct CurvePoint {
  double time_ms = 0;
  double error = 0;
};

/// Whether the rival's curve reaches an error, and where.
enum class EqualErrorStatus {
  kInterpolated,  ///< between two of its points: time_ms interpolated in log-log
  kNotReached,    ///< no point of the curve is that accurate: it is never extrapolated
  kAtCheapest,    ///< the cheapest point is already at least that accurate: time_ms (the cheapest point's) is an
                  ///< upper bound of what the rival needs, since below its cheapest point it is not measured
};

/// "interpolated", "not_reached", "at_cheapest".
const char* equal_error_status_name(EqualErrorStatus status);

struct TimeAtError {
  EqualErrorStatus status = EqualErrorStatus::kNotReached;
  double time_ms = 0;  ///< kInterpolated: the time; kAtCheapest: the bound; kNotReached: 0
};

/// The least step time at which the curve reaches `error`: its points in ascending time, the first that is at least
/// as accurate, interpolated in log-log (log time linear in log error) with the point before it. On a curve that is
/// not monotone this is the first crossing, the cheapest way the curve gets there. Points need positive time and
/// error; throws std::invalid_argument otherwise or for an empty curve.
TimeAtError time_at_error(std::vector<CurvePoint> curve, double error);

/// Whether the error never grows as the step time grows (points in ascending time; equal times in any order).
bool is_monotone(std::vector<CurvePoint> curve);

/// One body of a curve of error against simulated nodes (both positive).
struct NodesPoint {
  double nodes = 0;
  double error = 0;
};

/// The curve's error at `nodes`: its points in ascending nodes, interpolated in log-log (log error linear in log
/// nodes, as an error falling as a power of the resolution is) between the two around `nodes`; nullopt outside the
/// curve's range, which is never extrapolated. Points need positive nodes and error and no two the same nodes;
/// throws std::invalid_argument otherwise, for an empty curve or for `nodes` not positive.
std::optional<double> error_at_nodes(std::vector<NodesPoint> curve, double nodes);

}  // namespace tcsb
