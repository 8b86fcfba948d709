// Runner: executes a suite — every case's repetitions, interleaved — and records what happened.
#pragma once

#include <functional>
#include <string>

#include "harness/run_result.h"
#include "harness/suite.h"

namespace tcsb {

/// How a run reports progress; measurement itself is not configurable here (the suite says everything).
struct RunOptions {
  /// Called after each repetition with (done, total, label); used for the progress line on a TTY.
  std::function<void(int done, int total, const std::string& label)> progress;
};

/// Runs every case of the suite in interleaved_plan() order (every repetition runs every case once, a net's cases
/// side by side); each repetition builds a fresh body, steps warm-up steps untimed, then times every step with a
/// monotonic clock. A repetition that diverges stops at once and is reported with its step, never averaged in.
RunResult run_suite(const Suite& suite, const Context& context, const RunOptions& options = {});

}  // namespace tcsb
