// Stalls: repetitions during which the machine paused the process. On this shared VM a repetition's mean step has
// been seen at 21x its median (about 1.7 s lost within 400 steps of 0.2 ms), in plain and TC-SB cases alike. Its
// mean step time is then not the method's cost; a case's median over repetitions keeps one such repetition out, a
// bootstrap interval does not. Reported so a reader can tell a stall from a slow method.
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

/// Every ok repetition whose mean step exceeds kStallFactor x its median step, in case order.
std::vector<Stall> stalled_repetitions(const RunResult& result);

}  // namespace tcsb
