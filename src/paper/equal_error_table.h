// The speed-up at equal error of a fidelity pass with curves (fidelity.curves): per net, three curves of error
// against step time — TC-SB across budgets, the uniform grids across sizes, full resolution at fewer link passes
// (small steps) — and, for the error TC-SB reaches at each budget, the step time each rival needs to reach it
// (analysis/equal_error.h), as a ratio to TC-SB's. Computed once from a FidelityResult; every report renders it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/bootstrap.h"
#include "analysis/equal_error.h"
#include "fidelity/fidelity_result.h"

namespace tcsb {

/// One body of a curve as measured.
struct EqualErrorPoint {
  std::string
      method;  ///< FidelitySubjectSpec::method, or "reference" (full resolution as the pass's reference steps it)
  double compression = 1.0;
  int solver_divisor = 1;
  double nodes = 0;    ///< simulated nodes, mean over the measured steps
  double time_ms = 0;  ///< median over the pass's blocks of the block's mean step
  double error = 0;    ///< the net's error metric (EqualErrorNet::metric); the reference's is the noise floor
};

/// One rival at the error of one TC-SB budget.
struct EqualErrorRival {
  EqualErrorStatus status = EqualErrorStatus::kNotReached;
  std::optional<double> time_ms;     ///< the rival's step time at that error (kAtCheapest: an upper bound)
  std::optional<double> speedup;     ///< time_ms / TC-SB's step time (kAtCheapest: an upper bound)
  std::optional<Interval> interval;  ///< 95 % percentile bootstrap of the speed-up over the pass's blocks
};

/// TC-SB at one budget against both rivals.
struct EqualErrorRow {
  double compression = 1.0;
  double nodes = 0;
  double time_ms = 0;
  double error = 0;
  EqualErrorRival grid;  ///< the uniform grids' curve (the world pass: discrete LOD's), the reference its finest point
  EqualErrorRival full;  ///< full resolution at fewer passes (the reference as its finest point)
};

/// One net.
struct EqualErrorNet {
  std::string net;
  /// "p95_px" (the mean over the measured steps of the per-step p95 pixel error) in a scene with a camera, else
  /// "rms_pct" (the mean RMS, % of the net's extent).
  std::string metric;
  double floor = 0;  ///< the noise floor in that metric: the reference's point, and what no error can go below
  std::vector<EqualErrorPoint> tcsb, grid, full;  ///< the curves, ascending time
  bool grid_monotone = true, full_monotone = true, tcsb_monotone = true;
  std::vector<EqualErrorRow> rows;  ///< per TC-SB budget below 1, ascending
  /// Why the net has no rows (a curve without points, a diverged reference, no noise floor); empty when it has.
  std::string missing;
};

/// Per net (the result's order) when the pass ran curves; empty otherwise. `seed` drives the bootstrap.
std::vector<EqualErrorNet> equal_error_table(const FidelityResult& result, std::uint64_t seed = 1);

/// A body of one of the curves and its per-block step times, which the interval resamples.
struct TimedCurvePoint {
  EqualErrorPoint point;
  const std::vector<double>* blocks = nullptr;  ///< one time per block of the pass, the same blocks for every point
};

/// Fills `out`'s curves, their monotonicity and its rows from three curves of one pass: TC-SB's, the grid-like
/// rival's and full resolution's at fewer passes, each rival with the reference as its finest point, every point's
/// blocks as many as `blocks`. What the fidelity pass's nets and the world pass's scene (paper/world_equal_error.h)
/// share.
void fill_equal_error(std::vector<TimedCurvePoint> tcsb, std::vector<TimedCurvePoint> grid,
                      std::vector<TimedCurvePoint> full, std::size_t blocks, std::uint64_t seed, EqualErrorNet& out);

}  // namespace tcsb
