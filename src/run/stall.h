// Stalls: repetitions during which the machine paused the process. On this shared VM a repetition's mean step has
// been seen at 21x its median (about 1.7 s lost within 400 steps of 0.2 ms), in plain and TC-SB cases alike. Its
// mean step time is then not the method's cost; a case's median over repetitions keeps one such repetition out, a
// bootstrap interval does not. Reported so a reader can tell a stall from a slow method. A body's own rhythm is not a
// stall: a falling cloth re-inserts its whole DBVT every 4th step (docs/methodology.md, "Whole re-insert cycles in
// the timed window"), and on the largest nets those steps take 6-20x a quiet one, which lifts the mean above 3x the
// median with the machine idle.
#pragma once

#include <string>
#include <vector>

#include "run/run_result.h"

namespace tcsb {

/// A repetition's mean step above this multiple of its median step counts as a stall (step times within a
/// repetition otherwise stay within about 1.5x: the same physics, the same operations).
inline constexpr double kStallFactor = 3.0;

struct Stall {
  std::string label;  ///< the case
  int repetition = 0;
  double mean_over_median = 0;  ///< the repetition's mean step / median step
  double lost_s = 0;            ///< (mean - median) x timed steps: about how long the pause lasted
};

/// A repetition at least this share of whose timed steps are slow (above kStallFactor x the median), none two in a
/// row, is slow by its own rhythm: a pause of the machine is rare, and one that lasts makes slow steps in a row.
inline constexpr double kRhythmShare = 1.0 / 8.0;

/// Whether the slow steps of `step_ms` (those above kStallFactor x `median_ms`) are a rhythm: at least kRhythmShare
/// of the steps, and never two in a row. False for an empty series.
bool slow_by_rhythm(const std::vector<double>& step_ms, double median_ms);

/// Every ok repetition whose mean step exceeds kStallFactor x its median step, in case order, except those whose
/// recorded per-step times are slow_by_rhythm.
std::vector<Stall> stalled_repetitions(const RunResult& result);

}  // namespace tcsb
