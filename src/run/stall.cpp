#include "run/stall.h"

namespace tcsb {

bool slow_by_rhythm(const std::vector<double>& step_ms, double median_ms) {
  std::size_t slow = 0;
  bool previous_slow = false;
  for (const double t : step_ms) {
    const bool is_slow = t > kStallFactor * median_ms;
    if (is_slow && previous_slow) return false;  // slow steps in a row: a pause, or at least not a rhythm
    slow += is_slow;
    previous_slow = is_slow;
  }
  return !step_ms.empty() && static_cast<double>(slow) >= kRhythmShare * static_cast<double>(step_ms.size());
}

std::vector<Stall> stalled_repetitions(const RunResult& result) {
  std::vector<Stall> stalls;
  for (const CaseResult& c : result.cases) {
    for (const RepetitionResult& r : c.repetitions) {
      if (r.status != "ok" || !(r.median_step_ms > 0) || r.mean_step_ms <= kStallFactor * r.median_step_ms) continue;
      if (slow_by_rhythm(r.series.step_ms, r.median_step_ms)) continue;
      stalls.push_back({c.label, r.repetition, r.mean_step_ms / r.median_step_ms,
                        (r.mean_step_ms - r.median_step_ms) * result.suite.steps / 1000.0});
    }
  }
  return stalls;
}

}  // namespace tcsb
