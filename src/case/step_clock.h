// The harness's clock for timing steps and operations: monotonic (steady_clock), read in milliseconds.
#pragma once

#include <chrono>

namespace tcsb {

using StepClock = std::chrono::steady_clock;

/// Milliseconds from `a` to `b`.
inline double ms_between(StepClock::time_point a, StepClock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace tcsb
