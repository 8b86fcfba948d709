// The subcommands: each file registers its options on the CLI11 app (add_*) and implements the command (*_command),
// so main.cpp only dispatches.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gate/adaptivity_tax.h"
#include "suite/suite.h"

namespace CLI {
class App;
}  // namespace CLI

namespace tcsb::cli {

/// Options of `tcsb run` (also used by the default reproduction).
struct RunArgs {
  std::string suite;                  ///< a path or a bundled suite name
  std::string out;                    ///< output file; empty: stdout
  std::string format = "json";        ///< a make_format() name
  bool quiet = false;                 ///< no console report on stderr
  std::vector<double> compression;    ///< overrides the suite's TC-SB node budgets (fractions), when given
  std::optional<double> max_step_ms;  ///< overrides the suite's time budget per step (ms; 0 disables), when given
  std::optional<int> repetitions;     ///< overrides the suite's repetitions per case, when given
  std::string shard;                  ///< "K/N": run only shard K of N (sweep/shard_plan.h); empty: everything
  std::string split = "repetitions";  ///< what --shard splits: "repetitions" or "nets" (sweep/shard_plan.h)
  std::string measure = "time";       ///< "time", or "instructions": counted under callgrind (cli/callgrind_launch.h)
};

/// Options of `tcsb merge`.
struct MergeArgs {
  std::vector<std::string> shards;  ///< shard result files
  std::string out;                  ///< output file; empty: stdout
  bool quiet = false;               ///< no console report on stderr
};

/// Options of `tcsb reproduce`.
struct ReproduceArgs {
  std::string suite = "paper";               ///< a path or a bundled suite name
  std::string paper = "results/paper.json";  ///< the paper's own numbers
  std::string out;                           ///< output file; empty: stdout
  bool quiet = false;                        ///< only the reproduction tables on stderr
  bool targets = false;                      ///< also print this project's targets on stderr (always in the JSON)
  std::optional<int> repetitions;            ///< overrides the suite's repetitions per case, when given
  /// Wall time (s) for judging the claims after the run — intervals, and extra repetitions of undecided claims
  /// while they fit; absent: what is left of kReproductionWallTargetS (paper/paper_claims.h); 0: no extra repetitions.
  std::optional<double> budget;
  /// Processes the run's repetitions are measured in, one after another (cli/shard_processes.h): 1 runs them in this
  /// one, as always; more gives intervals that include the spread between processes.
  int processes = 1;
};

/// `--targets` of `tcsb reproduce` and of the bare `tcsb`: the project's own targets are not the paper's claims, so
/// the console shows them only when asked.
inline constexpr const char* kTargetsFlagHelp =
    "Also print this project's own targets (reported, not gating) on stderr; the JSON always holds them "
    "(reproduction.targets)";

/// The largest --budget accepted (a day): a bound against typing errors.
inline constexpr double kMaxReproduceBudget = 86400.0;

/// Options of `tcsb frames`.
struct FramesArgs {
  std::string suite = "paper";               ///< a path or a bundled suite name
  std::string net;                           ///< a net of the suite by name; empty: its last
  std::optional<double> compression;         ///< TC-SB node budget; absent: the suite's smallest target
  std::vector<int> steps{30, 60, 120, 240};  ///< record after these steps (the cloth falls, then swings)
  std::optional<int> every;                  ///< instead of steps: after every this many, from 0 to the run's end
  bool calibrated = false;                   ///< TC-SB with the suite's calibration (fidelity.calibration)
  std::string out;                           ///< output file; empty: stdout
};

/// The latest step `tcsb frames` records (a bound against typing errors; 100 000 steps take minutes at 81 x 81).
inline constexpr int kMaxFrameStep = 100000;

/// Options of `tcsb validate`.
struct ValidateArgs {
  std::string suite;
};

/// Options of `tcsb calibrate`.
struct CalibrateArgs {
  std::string suite;
  std::string out;    ///< calibration file; empty: the suite's fidelity.calibration path, else SUITE.calibration.json
  std::string check;  ///< a calibration file to measure on the suite's nets and regime instead of fitting one
  bool quiet = false;
};

/// The default --threshold of `tcsb compare` for times (a dedicated machine) and for instruction counts: half the
/// 1 % increase of TC-SB's step the instruction gate must catch every time (a build counts the same in every run, so
/// an unchanged build differs by exactly 0).
inline constexpr double kTimeThreshold = 0.05;
inline constexpr double kInstructionThreshold = 0.005;

/// Options of `tcsb compare`.
struct CompareArgs {
  std::string base;     ///< baseline result file
  std::string next;     ///< new result file
  double alpha = 0.05;  ///< family-wise significance level (Holm over the gated metrics)
  /// Smallest relative change that fails the gate (a timing median's, or an instruction count's); absent: 5 % for
  /// times, kInstructionThreshold for counts.
  std::optional<double> threshold;
  bool absolute = false;     ///< gate absolute step times too (dedicated machines)
  std::string summary;       ///< Markdown summary file; empty: stderr
  std::string summary_json;  ///< JSON summary file (report/gate_summary_json.h); empty: none
};

/// Options of `tcsb tax` (defaults: the scaling target, gate/adaptivity_tax.h's TaxTarget).
struct TaxArgs {
  std::vector<std::string> runs;                       ///< result files to pool
  double bound = TaxTarget{}.bound;                    ///< the largest ratio to plain_equal that passes
  double compression = TaxTarget{}.compression;        ///< the TC-SB node budget judged
  std::int64_t min_nodes = TaxTarget{}.min_net_nodes;  ///< judge only nets of at least this many grid nodes
  bool over_nets = false;  ///< one claim on Table 2's ratio over the nets instead of one per net
  std::string out;         ///< output file; empty: stdout
};

/// Options of `tcsb export`.
struct ExportArgs {
  std::string result;  ///< a native result file
  std::string format;  ///< a make_format() name
  std::string out;     ///< output file; empty: stdout
};

/// Registers `run SUITE [--out FILE] [--format NAME] [--quiet] [--shard K/N]`.
CLI::App* add_run_command(CLI::App& app, RunArgs& args);
/// Checks the format and --out, parses the suite, then runs and reports it (run_and_report).
int run_command(const RunArgs& args);
/// Runs an already parsed suite and reports it as `args` says; --format and --out must have been checked (they
/// are checked again, cheaply, so no caller can start a long run that cannot be written).
int run_and_report(const Suite& suite, const RunArgs& args);

/// Registers `merge SHARD.json... [--out FILE] [--quiet]`.
CLI::App* add_merge_command(CLI::App& app, MergeArgs& args);
/// Checks that the shard results make up one suite exactly once, merges them (report/shard_merge.h) and writes the
/// merged result: 0, or 2 for a bad set of shards (naming the file).
int merge_command(const MergeArgs& args);

/// Registers `list`.
CLI::App* add_list_command(CLI::App& app);
/// Prints the bundled suites: name, nets, methods, the description's first line.
int list_command();

/// Registers `calibrate SUITE [--out FILE]`.
CLI::App* add_calibrate_command(CLI::App& app, CalibrateArgs& args);
/// Fits the suite's per-level link stiffness and uniform-grid stiffness and writes the calibration file.
int calibrate_command(const CalibrateArgs& args);

/// Registers `validate SUITE`.
CLI::App* add_validate_command(CLI::App& app, ValidateArgs& args);
/// Parses the suite and prints "SUITE: ok (...)".
int validate_command(const ValidateArgs& args);

/// Registers `compare BASE NEW [--alpha A] [--threshold T] [--absolute] [--summary FILE]`.
CLI::App* add_compare_command(CLI::App& app, CompareArgs& args);
/// The CI regression gate: 0 pass, 1 a regression or changed behaviour, 2 unusable input or different suites.
int compare_command(const CompareArgs& args);
CLI::App* add_tax_command(CLI::App& app, TaxArgs& args);
int tax_command(const TaxArgs& args);

/// Registers `frames [--suite S] [--net N] [--compression C] [--steps A,B,... | --every K] [--calibrated]
/// [--out FILE]`.
CLI::App* add_frames_command(CLI::App& app, FramesArgs& args);
/// Records the frames (fidelity/figure_frames.h; of a scene of many bodies, world/world_frames.h) and writes their
/// JSON (report/frames_json.h, report/world_frames_json.h).
int frames_command(const FramesArgs& args);

/// Registers `export RESULT --format NAME [--out FILE]`.
CLI::App* add_export_command(CLI::App& app, ExportArgs& args);
/// Renders an existing result file in another format (gbench, github-action-smaller, ...).
int export_command(const ExportArgs& args);

/// Registers `reproduce [--suite S] [--paper FILE] [--out FILE] [--quiet] [--targets] [--repetitions N]
/// [--budget SECONDS]`.
CLI::App* add_reproduce_command(CLI::App& app, ReproduceArgs& args);
/// Runs the suite, prints both tables beside the paper's, judges the claims (adding repetitions for undecided ones
/// within the budget): 0 all passed, 1 a claim failed, 4 none failed but some are undecided.
int reproduce_command(const ReproduceArgs& args);

}  // namespace tcsb::cli
