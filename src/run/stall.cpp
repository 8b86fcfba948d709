#include "run/stall.h"

namespace tcsb {

std::vector<Stall> stalled_repetitions(const RunResult& result) {
  std::vector<Stall> stalls;
  for (const CaseResult& c : result.cases) {
    for (const RepetitionResult& r : c.repetitions) {
      if (r.status != "ok" || !(r.median_step_ms > 0) || r.mean_step_ms <= kStallFactor * r.median_step_ms) continue;
      stalls.push_back({c.label, r.repetition, r.mean_step_ms / r.median_step_ms,
                        (r.mean_step_ms - r.median_step_ms) * result.suite.steps / 1000.0});
    }
  }
  return stalls;
}

}  // namespace tcsb
