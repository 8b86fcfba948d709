// Comparing two finished runs for the CI gate: checks that they measured the same suite with the same settings,
// lists every difference in the deterministic quantities (changed behaviour), and collects the per-repetition
// timing samples the gate decides on (analysis/regression_gate.h). Pure: two ResultViews in, one struct out.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/regression_gate.h"
#include "result/result_view.h"

namespace tcsb {

/// The two runs measured different suites or settings: comparing them would be meaningless. what() is one line
/// naming the first difference.
class SuiteMismatch : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The metric of a BehaviourChange for a case (repetition nullopt) or a repetition that is not matched one to one:
/// absent from a run or present more than once; its values are "absent", "present" or "K entries".
inline constexpr const char* kPresenceMetric = "presence";

/// One deterministic quantity that differs between the runs.
struct BehaviourChange {
  std::string case_label;  ///< the case's label
  /// "N", "L", "I", "final_state_hash", "operations", "status" or kPresenceMetric
  std::string metric;
  std::optional<int> repetition;  ///< the repetition, or nullopt for the case-level value
  std::string base, next;         ///< the two values as text
};

/// One timing metric of one case, in both runs.
struct TimingSeries {
  std::string case_label;
  std::string metric;  ///< kRatioMetric or kStepMsMetric
  TimingSamples samples;
};

/// The gated-by-default metric: TC-SB step time over plain step time of the same net, per repetition, same run.
inline constexpr const char* kRatioMetric = "ratio vs plain";
/// Absolute mean step time per repetition (ms): machine-dependent, gated only on request.
inline constexpr const char* kStepMsMetric = "step ms";

/// One case's instruction counts in both runs (runs measured with `--measure instructions`).
struct InstructionPair {
  std::string case_label;
  InstructionsView base, next;
};

/// Everything the gate needs to decide, and what it tells the reader.
struct ResultComparison {
  std::string measure = "time";  ///< what both runs measured ("time" or "instructions")
  std::string suite_name;
  std::string suite_sha256;
  std::size_t cases = 0;        ///< cases matched one to one (by label)
  std::size_t repetitions = 0;  ///< repetitions of those matched one to one (by number)
  /// False when a per-step time budget (feedback.max_step_ms > 0) lets timing steer the node budget: N, L, I and
  /// the final state then depend on the machine, so their differences are listed but cannot mean changed code.
  bool deterministic = true;
  /// Deterministic differences (changed behaviour), including every case or repetition not matched one to one.
  std::vector<BehaviourChange> changes;
  std::vector<TimingSeries> ratios;              ///< one per TC-SB case that has a plain case on its net
  std::vector<TimingSeries> step_ms;             ///< one per case
  std::vector<InstructionPair> instructions;     ///< one per case that has counts in both runs (measure instructions)
  std::vector<std::string> machine_differences;  ///< context fields that differ, e.g. "cpu_model: \"A\" vs \"B\""
};

/// The first place where two JSON values differ, as "PATH.key: A vs B" (values shortened to one line), or "" when
/// they are equal. Objects are compared key by key whatever their order; arrays element by element.
std::string first_json_difference(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b,
                                  const std::string& path);

/// The first difference between two runs' suites and seeds that makes them runs of different suites or settings, as
/// "suite.FIELD: A vs B" or "context.seed: A vs B"; "" when there is none. The suites' paths never count (where the
/// file lived), nor, with `ignore_repetitions`, their repetitions (runs of one suite pooled across processes).
std::string suite_difference(const ResultView& a, const ResultView& b, bool ignore_repetitions);

/// The first context field that makes two runs different builds (commit, version, compiler, flags, build type,
/// sanitizers, Bullet's version and precision), as "context.FIELD: A vs B"; "" when there is none. Their
/// measurements are of different programs: they may be compared (that is what the gate is for), never pooled.
std::string build_difference(const ResultView& a, const ResultView& b);

/// The context fields that make two runs' absolute times incomparable (machine, compiler, build, Bullet, huge
/// pages) and differ, each as "field: A vs B". Same-run ratios stay comparable whatever these say.
std::vector<std::string> machine_differences(const ResultView& base, const ResultView& next);

/// Compares `base` with `next`. Cases are matched by label and their repetitions by number, one to one and in any
/// order (gate/one_to_one_match.h); whatever does not match is a kPresenceMetric change, even when the run is
/// not deterministic, and only matched cases contribute timings. Throws SuiteMismatch when two cases of one label
/// differ in net, method, compression or configuration (naming `next`'s field), or when the suite blocks differ
/// in anything but their path (the name, the SHA-256 of the file, and every effective setting: steps, repetitions,
/// solver, feedback, nets, methods, compression — a run may be narrowed from its file) or when the seeds differ, and
/// when the runs measured different things (a time result against an instruction count result).
ResultComparison compare_results(const ResultView& base, const ResultView& next);

}  // namespace tcsb
