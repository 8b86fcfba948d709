// RunResult: everything one `tcsb run` measured, before any formatting. The runner fills it; the tables, fits and
// claims are computed from it by pure functions; each report format renders it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/statistics.h"
#include "case/instruction_meter.h"
#include "fidelity/fidelity_result.h"
#include "run/context.h"
#include "softbody/op_sample.h"
#include "suite/case_plan.h"
#include "suite/shard_index.h"
#include "suite/suite.h"
#include "world/world_result.h"

namespace tcsb {

/// What a run measured of each timed step: its wall time (always), or also its instructions (`tcsb run --measure
/// instructions`, under callgrind: deterministic, but the step times are callgrind's, many times slower).
enum class Measure { kTime, kInstructions };

/// "time" or "instructions", as the result file records it.
const char* measure_name(Measure measure);

/// Instructions of timed steps, summed over them, by part (StepPart).
struct InstructionCount {
  std::uint64_t own = 0;     ///< TC-SB's own work (0 for a stock body)
  std::uint64_t bullet = 0;  ///< Bullet's step
  std::uint64_t total() const { return own + bullet; }
};

/// One function's own instructions over a case's timed steps (callgrind's self cost): where a count changed.
struct FunctionCount {
  std::string name;
  std::uint64_t instructions = 0;
};

/// Per-step samples of one repetition (timed steps only).
struct StepSeries {
  std::vector<double> step_ms;               ///< wall time of the whole step (blends, feedback, operations, Bullet)
  std::vector<std::int32_t> nodes;           ///< Bullet nodes after the step (N)
  std::vector<std::int32_t> links;           ///< Bullet links after the step (L)
  std::vector<std::int32_t> interpolations;  ///< operations blending during the step (I)
  std::vector<double> feedback_ms;           ///< feedback work on the step's critical path (TC-SB only)
  std::vector<double> feedback_total_ms;     ///< feedback work including what ran on worker threads (TC-SB only)
};

/// Where a step's time goes, milliseconds per step. The parts are disjoint; what they leave of the whole step is
/// the clock reads and calls between them. A stock body's step is all Bullet's.
struct StepBreakdown {
  double bullet_ms = 0;      ///< Bullet's step (predictMotion, solveConstraints, integrateMotion)
  double feedback_ms = 0;    ///< the feedback stage on the simulation thread (waiting for a worker included),
                             ///< the operations it begins excluded
  double operations_ms = 0;  ///< the TreeCut operations begun and ended in the step (their own timers, OpSample)
  double blending_ms = 0;    ///< advancing the blends (link weights, mass hand-over), the end operations excluded
};

/// Contact correctness of one repetition in a scene with colliders: nodes found inside a collider, deeper than the
/// contact margin, after a step (warm-up and timed steps alike). Bullet holds a node in contact at the margin; a node
/// deeper than that is one no contact held, and a body that falls through a collider is a defect.
struct Penetrations {
  std::int64_t node_steps = 0;  ///< over every step: nodes deeper than the margin, summed
  double deepest_pct = 0;       ///< the deepest any node got, % of the net's extent (0 when none penetrated)
  /// Over every step: Bullet's rigid contacts (btSoftBody::m_rcontacts, one per node within the margin of a
  /// collider), summed. What contact costs a body: Bullet solves each in every position iteration, so a body that puts
  /// its nodes where the cloth touches pays for it in its step.
  std::int64_t contact_node_steps = 0;
  std::int64_t steps = 0;  ///< steps counted (warm-up and timed)
  /// Bullet's contacts per step, on average.
  double mean_contacts() const { return steps > 0 ? static_cast<double>(contact_node_steps) / steps : 0.0; }
};

/// One repetition of one case: a fresh body, warm-up, then timed steps.
struct RepetitionResult {
  int repetition = 0;
  std::string status = "ok";         ///< "ok" or "diverged"
  std::optional<int> diverged_step;  ///< first step (counting warm-up) after which the body failed a check
  std::string diverged_reason;
  StepSeries series;
  double mean_step_ms = 0, median_step_ms = 0;
  double mean_nodes = 0, mean_links = 0, mean_interpolations = 0;
  double mean_feedback_ms = 0, mean_feedback_total_ms = 0;
  StepBreakdown breakdown;                   ///< means over the timed steps
  std::int64_t operations = 0;               ///< operations begun or ended during timed steps
  std::string final_state_hash;              ///< FNV-1a of node count and final positions: deterministic, gateable
  double build_ms = 0;                       ///< building the body (not part of step times)
  std::optional<Penetrations> penetrations;  ///< in scenes with colliders only
  /// The parts the instruction meter dumped (measure kInstructions), until the dumps are read into `instructions`.
  std::vector<MeteredPart> metered;
  std::optional<InstructionCount> instructions;  ///< over the timed steps (measure kInstructions)
  /// The process that measured it: 0 in a run of one process; in a merged result, the shard (k, 1-based). Its
  /// intervals resample processes first, then repetitions within them (analysis/bootstrap.h).
  int process = 0;
};

/// Operation costs of one case (TC-SB only), from timed steps.
struct OpRecord {
  std::vector<OpSample> samples;
};

/// One case: a net x method x target, all its repetitions, and their summary.
struct CaseResult {
  CaseKey key;
  std::string label;
  std::string net_name;
  std::int64_t net_nodes = 0;  ///< grid nodes of the net (the finest level)
  std::int64_t net_links = 0;
  int target_nodes = 0;       ///< node budget of a TC-SB or plain_equal case (0 for other methods)
  std::string status = "ok";  ///< "ok" when every repetition is ok, else "diverged"
  std::vector<RepetitionResult> repetitions;
  Summary step_ms;  ///< over the ok repetitions' mean step times
  double mean_nodes = 0, mean_links = 0, mean_interpolations = 0;
  double mean_feedback_ms = 0, mean_feedback_total_ms = 0;
  StepBreakdown breakdown;  ///< each part's median over the ok repetitions' means (medians: the parts need not add up)
  OpRecord ops;
  std::optional<InstructionCount> instructions;  ///< summed over the ok repetitions (measure kInstructions)
  /// The functions with the most own instructions over the ok repetitions' timed steps, most first
  /// (kFunctionsKept; measure kInstructions).
  std::vector<FunctionCount> functions;
};

/// Functions a case keeps in `functions`: enough to name where a changed count went.
inline constexpr std::size_t kFunctionsKept = 25;

/// A whole run.
struct RunResult {
  Measure measure = Measure::kTime;
  Suite suite;
  Context context;
  std::vector<CaseResult> cases;
  std::optional<FidelityResult> fidelity;  ///< the fidelity pass, when the suite enables it and runs TC-SB
  std::optional<WorldResult> world;        ///< the world pass, for a scene of many bodies (is_world_suite)
  double wall_s = 0;                       ///< wall time of the run (the fidelity pass included)
  /// Set when this run is one shard of its suite (`tcsb run --shard K/N`): `cases` then holds only the shard's
  /// cases (with a repetition split, only its repetitions of them), and the JSON carries what `tcsb merge` needs
  /// (sweep/shard_merge.h).
  std::optional<ShardIndex> shard;
};

}  // namespace tcsb
