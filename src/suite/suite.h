// Suite: a validated benchmark description — which nets, which methods, which compression targets, how long and
// how often. Parsed from JSON by parse_suite(); everything here has already been checked.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "feedback/feedback_settings.h"
#include "net/net_spec.h"
#include "scene/scene_settings.h"
#include "softbody/solver_settings.h"
#include "softbody/tc_settings.h"
#include "suite/calibration_file.h"

namespace tcsb {

/// The ways a case can simulate a net.
enum class Method {
  kPlain,        ///< stock btSoftBody built from the net's finest level (the baseline)
  kBulletPatch,  ///< stock btSoftBodyHelpers::CreatePatch of the same grid (checks the baseline is not handicapped)
  kTcsb,         ///< the TreeCut soft body at each compression target
  /// Stock btSoftBody of a uniform coarse grid holding about each compression target's node budget (the fidelity
  /// pass's uniform grid: same size, total mass and pins), one case per target below 1: what a static body of the
  /// node count TC-SB simulates costs, measured in the same interleaved repetitions.
  kPlainEqual,
  /// Under the compliant material (SolverSettings::model), stock Bullet built from the net's finest level with the
  /// suite's solver settings (kLST and piterations): the baseline a Bullet user has today, beside the compliant
  /// bodies. Under Bullet's model it would be "plain", and is refused.
  kStock,
};
/// Every method, in declaration order.
inline constexpr Method kAllMethods[] = {Method::kPlain, Method::kBulletPatch, Method::kTcsb, Method::kPlainEqual,
                                         Method::kStock};

/// The curves of error against step time the speed-up at equal error is read from (paper/equal_error_table.h):
/// TC-SB and the uniform grid at every budget, and full resolution with the suite's iterations (or, under the
/// compliant material, its small steps) divided by each divisor.
struct FidelityCurves {
  std::vector<double> budgets;       ///< fractions of the net's nodes, each in (0, 1), ascending, no two equal
  std::vector<int> solver_divisors;  ///< each > 1, ascending, no two equal
};

/// Fidelity measurement settings (reference run in lockstep, error metrics).
struct FidelitySettings {
  bool enabled = false;                  ///< run the full-resolution reference beside each TC-SB case
  double rms_threshold_pct = 1.0;        ///< maximal compression: smallest budget whose RMS error stays under this
  std::vector<double> pareto_targets;    ///< extra compression targets for the Pareto sweep (empty: none)
  bool ablations = false;                ///< run the equal-budget ablations
  std::optional<FidelityCurves> curves;  ///< the error-against-time curves (nullopt: none)
  /// Over how many step boundaries TC-SB's shown surface spreads each jump (fidelity/surface_morph.h), in the
  /// fidelity and world passes; nullopt: the blend's own, tcsb.blend_steps + 1. How a game would show the cut, not
  /// how it simulates: a longer morph makes smaller jumps and lags the simulated surface longer.
  std::optional<int> geomorph_boundaries;
  /// The suite's calibration file as written ("converged.calibration.json", relative to the suite file); empty:
  /// none. With one, the pass adds calibrated TC-SB and the calibrated uniform grid at each target below 1.
  std::string calibration_path;
};

/// A validated suite.
/// The most repetitions a suite (or --repetitions) may ask for.
inline constexpr int kMaxRepetitions = 1000;

/// One axis of a suite: a setting (its path in the suite file, "solver.piterations") and the values it takes, each
/// checked by that setting's own parser (suite/suite_axes.h).
struct Axis {
  std::string path;
  std::vector<nlohmann::json> values;  ///< in file order, no two equal
};

/// One point of the cross product of a suite's axes: which value each axis takes.
struct Configuration {
  std::vector<std::size_t> value_index;  ///< per axis (Suite::axes order), an index into its values
  std::string label;                     ///< "piterations=8,blend_steps=4": short settings names, axis order
};

struct Suite {
  std::string name;
  std::string description;
  std::filesystem::path path;  ///< where it was read from
  std::string sha256;          ///< SHA-256 of the file's bytes
  std::string source;          ///< the file's bytes (a shard carries them, so `tcsb merge` can rebuild the suite)
  std::vector<NetSpec> nets;
  std::vector<Method> methods;  ///< in the order repetitions interleave them
  /// TC-SB (and plain_equal) node budgets as fractions of the initial count; 1.0 = none.
  std::vector<double> compression;
  WorldSettings world;
  /// What surrounds the cloth (the suite's "scene" block): no colliders without one, the paper's scene.
  SceneSettings scene;
  int steps = 300;        ///< timed steps per repetition
  int warmup_steps = 30;  ///< untimed steps before them
  int repetitions = 5;
  /// 0: each repetition of a case runs alone, start to end. k > 0: a net's cases of one repetition run side by
  /// side, each stepping in turn one untimed step (its data back into the caches) and then k timed steps, so every
  /// case of the net meets the same moments of the machine (docs/methodology.md, "Side by side").
  int interleave_steps = 0;
  /// With interleave_steps set: every net's cases of one repetition take turns together, not one net's at a time, so
  /// the nets too meet the same moments of the machine and a repetition is one sample of every net. Fits across the
  /// nets (Figure 5's line) then keep little of the drift, and the bootstrap draws a repetition for all nets at once
  /// (paper/claim_intervals.h). Every net's bodies are alive at once.
  bool interleave_across_nets = false;
  std::uint64_t seed = 1;
  SolverSettings solver;
  TcSettings tcsb;
  FeedbackSettings feedback;
  FidelitySettings fidelity;
  /// The suite's axes (empty: none); the settings above are then the base every configuration starts from.
  std::vector<Axis> axes;
  /// The cross product of the axes, first axis slowest (empty without axes: the suite is its one configuration).
  std::vector<Configuration> configurations;
  /// The units this process runs, indexed configuration x nets.size() + net (a shard's, suite/shard_plan.h); empty:
  /// all. Not a setting of the suite (results never record it): the runner runs and the memory check counts only
  /// these units' cases. Without axes a unit is a net.
  std::vector<bool> run_units;
  /// With a split by repetition (a shard's): which repetitions of each unit this process runs, indexed unit x
  /// repetitions + repetition; empty: every repetition of the units in run_units. Not a setting either.
  std::vector<bool> run_repetitions;
  /// The calibration fidelity.calibration_path names, read and checked against this suite (calibration_mismatch)
  /// when the suite was parsed; nullopt without one.
  std::optional<Calibration> calibration;
};

/// Whom the BSWDF's view terms see through in `suite`: its scene's camera when feedback.view is on, else none.
inline std::optional<Spectator> suite_spectator(const Suite& suite) {
  if (!suite.feedback.view || !suite.scene.camera) return std::nullopt;
  return Spectator{*suite.scene.camera, suite.world.dt};
}

/// Every step a repetition of a case takes, warm-up and the untimed step opening each interleaved block included.
/// In 64 bits: each field may be up to INT_MAX, and only the memory check bounds their sum.
inline long long steps_per_repetition(const Suite& suite) {
  const long long steps = suite.steps, k = suite.interleave_steps;
  const long long blocks = k > 0 && steps > 0 ? (steps - 1) / k + 1 : 0;
  return suite.warmup_steps + steps + blocks;
}

/// How many configurations the suite runs: one without axes.
inline std::size_t configuration_count(const Suite& suite) {
  return suite.configurations.empty() ? 1 : suite.configurations.size();
}

/// Whether `suite` runs net `net` of configuration `configuration` in this process (Suite::run_units).
inline bool runs_unit(const Suite& suite, std::size_t configuration, std::size_t net) {
  const std::size_t unit = configuration * suite.nets.size() + net;
  return suite.run_units.empty() || (unit < suite.run_units.size() && suite.run_units[unit]);
}

/// Whether `suite` runs repetition `repetition` of net `net` of configuration `configuration` in this process
/// (Suite::run_units, Suite::run_repetitions).
inline bool runs_repetition(const Suite& suite, std::size_t configuration, std::size_t net, int repetition) {
  if (!runs_unit(suite, configuration, net)) return false;
  if (suite.run_repetitions.empty()) return true;
  const std::size_t index = (configuration * suite.nets.size() + net) * static_cast<std::size_t>(suite.repetitions) +
                            static_cast<std::size_t>(repetition);
  return index < suite.run_repetitions.size() && suite.run_repetitions[index];
}

/// Whether this process runs the fidelity pass of net `net` (one per net, never with axes): the process that runs
/// the net's first repetition.
inline bool runs_fidelity_of(const Suite& suite, std::size_t net) { return runs_repetition(suite, 0, net, 0); }

/// Whether `suite` runs net `net` in any configuration in this process (then the net is built).
inline bool runs_net(const Suite& suite, std::size_t net) {
  for (std::size_t c = 0; c < configuration_count(suite); ++c)
    if (runs_unit(suite, c, net)) return true;
  return false;
}

/// Changes the command line makes to a parsed suite (--repetitions, --compression, ...); throws to reject them.
using SuiteAdjustment = std::function<void(Suite&)>;

/// Reads and validates a suite file. Throws InputError (unknown keys, wrong types, out-of-range values, a suite too
/// large for this process's memory limits (suite/suite_memory.h), unreadable file) before anything runs.
/// `adjust`, when given, runs on the parsed suite before the memory check, so the check sees the suite that runs.
Suite parse_suite(const std::filesystem::path& path, const SuiteAdjustment& adjust = {});

/// Validates a suite given as JSON text; `file` names it in errors. The same checks as parse_suite.
Suite parse_suite_text(const std::string& text, const std::string& file, const SuiteAdjustment& adjust = {});

/// Name used in JSON for a method ("plain", "bullet_patch", "tcsb", "plain_equal", "stock").
const char* method_name(Method method);

}  // namespace tcsb
