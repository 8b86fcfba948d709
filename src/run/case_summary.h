// A case's summary over its repetitions: what the tables and fits read. The runner computes it once per case; the
// bootstrap recomputes it for every resample of the repetitions, so both use this one definition.
#pragma once

#include <vector>

#include "run/run_result.h"

namespace tcsb {

/// Arithmetic mean accumulated in double; 0 for an empty vector. (Not statistics' mean(): the recorded results and
/// their gate baselines were computed this way, and exact numbers such as mean N must not change in the last bit.)
template <class T>
double mean_of(const std::vector<T>& values) {
  if (values.empty()) return 0;
  double sum = 0;
  for (const T& v : values) sum += static_cast<double>(v);
  return sum / static_cast<double>(values.size());
}

/// Fills c.step_ms (over the ok repetitions' mean step times), the mean N, L, I and feedback costs, the median
/// step breakdown, and marks the
/// case "diverged" when any repetition is not ok (its numbers are left out, never averaged in).
void summarize_case(CaseResult& c);

}  // namespace tcsb
