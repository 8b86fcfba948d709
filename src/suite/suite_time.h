// Suite wall-time estimate: about how long the timed cases of a suite take, so `tcsb validate` can say whether a
// sweep is minutes or hours (and how to shard it) before anything runs. A rough figure from one per-node-step cost,
// not a measurement: the machine, the cache regime and the feedback work move it by a factor of a few.
#pragma once

#include "suite/suite.h"

namespace tcsb {

/// Seconds per simulated node and step at 2 solver iterations: the dearest of plain Bullet's measured 0.20-0.35 us
/// per node-step on the paper suite's nets (docs/methodology.md, "Step linearity and the L2").
inline constexpr double kNodeStepSeconds = 0.35e-6;

/// Estimated wall seconds of every repetition of every case this process runs (Suite::run_units), warm-up steps
/// included, building bodies and the fidelity pass not: per step, the nodes a case simulates (a TC-SB or
/// plain_equal case its budget's share of the net) x kNodeStepSeconds x the case's solver iterations
/// (piterations + viterations + diterations) / 2, since Bullet's constraint solving, most of a step, is one sweep
/// over the links per iteration.
double estimate_wall_seconds(const Suite& suite);

}  // namespace tcsb
