// The harness's clock for timing steps and operations: monotonic (steady_clock), read in milliseconds.
#pragma once

#include <chrono>
#include <cstddef>
#include <vector>

namespace tcsb {

using StepClock = std::chrono::steady_clock;

/// Milliseconds from `a` to `b`.
inline double ms_between(StepClock::time_point a, StepClock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

/// Appends the mean of series[from, end) to `blocks` when the block timed any step: a block's mean step, the unit
/// the fidelity and world passes interleave their bodies by, and the speed-up's interval resamples
/// (paper/equal_error_table.h).
inline void add_block_mean(const std::vector<double>& series, std::size_t from, std::vector<double>& blocks) {
  if (series.size() <= from) return;
  double sum = 0;
  for (std::size_t i = from; i < series.size(); ++i) sum += series[i];
  blocks.push_back(sum / static_cast<double>(series.size() - from));
}

}  // namespace tcsb
