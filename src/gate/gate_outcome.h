// The CI gate's verdict on two runs: the deterministic differences of a ResultComparison plus the timing decisions
// (analysis/regression_gate.h) over the metrics that gate — the same-run ratios always, absolute step times only
// when asked (they measure the machine as much as the code). Pure.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "analysis/claim.h"
#include "analysis/regression_gate.h"
#include "gate/instruction_gate.h"
#include "gate/result_comparison.h"

namespace tcsb {

/// Everything `tcsb compare` reports and exits on.
struct GateOutcome {
  ResultComparison comparison;
  GateSettings settings;
  bool absolute_gated = false;                  ///< --absolute: step times gate too (one Holm family with the ratios)
  std::vector<TimingDecision> ratio_decisions;  ///< parallel to comparison.ratios
  std::vector<TimingDecision> step_decisions;   ///< parallel to comparison.step_ms
  /// Runs measured with `--measure instructions`: the counts gate (one decision per case with counts), the timings
  /// (callgrind's) are neither gated nor shown.
  bool counts = false;
  std::vector<InstructionDecision> instruction_decisions;  ///< parallel to comparison.instructions
  std::size_t gated_metrics = 0;  ///< reliable metrics in the gated family (the Holm family size), or counted cases
  std::size_t regressions = 0;    ///< gated metrics (or counted cases) that regressed
  std::size_t undecided = 0;      ///< gated metrics whose interval straddles the threshold
  std::size_t warnings = 0;       ///< step times that would have regressed had they been gated

  /// Behaviour changed: a deterministic quantity differs, or a case or repetition is not matched one to one.
  bool behaviour_changed() const { return !comparison.changes.empty(); }
  /// The timings were decided: at least one gated metric is reliable. With none (too few repetitions, no TC-SB
  /// case with a plain case on its net) the gate has not measured anything, and a gate that fails closed cannot
  /// call that a pass.
  bool timings_decided() const { return gated_metrics > 0; }
  /// Gated metrics that are unreliable (too few samples on a side): reported, never decided.
  std::size_t unreliable_metrics() const;
  /// The gate passes: the timings were decided, with no regression and none undecided, and no behaviour changed.
  bool pass() const { return timings_decided() && regressions == 0 && undecided == 0 && !behaviour_changed(); }
  /// Three verdicts, as `reproduce` gives them: kFail on changed behaviour or a regression, kUndecided when neither
  /// but some gated metric is undecided, kPass when the gate passes. (Undecided timings are not a pass: the gate
  /// fails closed, and tcsb compare exits 4 for them.)
  Verdict verdict() const;
  /// The most extra repetitions per run any undecided metric would likely need (0 when none is undecided;
  /// kMaxMoreRepetitions when one cannot say).
  int more_repetitions() const;
  /// The most processes any gated interval pooled in the base and in the new run: more than 1 only for a merged
  /// result, whose intervals resample its shards first.
  std::pair<std::size_t, std::size_t> processes() const;
};

/// Decides the timings of `comparison`. Throws std::invalid_argument on bad settings (see decide_timings).
GateOutcome decide_gate(ResultComparison comparison, const GateSettings& settings, bool absolute_gated);

}  // namespace tcsb
