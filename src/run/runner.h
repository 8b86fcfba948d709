// Runner: executes a suite — every case's repetitions, interleaved — and records what happened.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "suite/suite.h"

namespace tcsb {

/// How a run reports progress and what it measures besides time; how it measures is the suite's.
struct RunOptions {
  /// kInstructions: each timed step's parts are also counted by an InstructionMeter (the process must run under
  /// callgrind; attach_instruction_counts reads the counts afterwards).
  Measure measure = Measure::kTime;
  /// Called after each repetition with (done, total, label); used for the progress line on a TTY.
  std::function<void(int done, int total, const std::string& label)> progress;
};

/// Runs every case of the suite in interleaved_plan() order (every repetition runs every case once, a net's cases
/// side by side); each repetition builds a fresh body, steps warm-up steps untimed, then times every step with a
/// monotonic clock. With Suite::interleave_steps = k, a net's cases of one repetition step side by side instead: all
/// bodies alive, each in turn taking one untimed step and k timed ones. A repetition that diverges stops at once and is
/// reported with its step, never averaged in. With suite.run_units (a shard's units), only those units' cases (and
/// their nets' fidelity pass) run and result.cases holds only them; nets of no unit are never built. With axes, every
/// case runs with its configuration's settings (configuration_suite, suite/suite_axes.h). The cases run keep their
/// suite-wide indices, so seeds, labels and the interleaved order among them are those of the whole suite.
RunResult run_suite(const Suite& suite, const Context& context, const RunOptions& options = {});

/// Runs `extra` more repetitions of the cases `case_indices` of a finished run (indices into result.cases), in the
/// run's own interleaved order restricted to those cases (every extra repetition runs each of them once, a net's
/// cases side by side), numbered after the case's last repetition, each with the case's own seed — so a repetition
/// added later does the same work as the first ones. Recomputes the touched cases' summaries and adds the time
/// taken to result.wall_s. Indices out of range are ignored. The fidelity pass is not repeated. `result` must hold
/// every case of its suite (not a shard's, Suite::run_units): a case's index is its seed.
void run_more_repetitions(RunResult& result, const std::vector<std::size_t>& case_indices, int extra,
                          const RunOptions& options = {});

}  // namespace tcsb
