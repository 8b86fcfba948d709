// `tcsb reproduce` (and `tcsb` with no arguments): runs the paper suite, prints Tables 1 and 2 beside the paper's
// own numbers (results/paper.json), judges the paper's claims — adding repetitions for those the run cannot decide,
// within a wall-time budget — and exits 0 (all passed), 1 (one failed) or 4 (none failed, some undecided).
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>

#include "base/atomic_file.h"
#include "case/step_clock.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/run_support.h"
#include "cli/shard_processes.h"
#include "paper/paper_claims.h"
#include "report/console_report.h"
#include "report/json_report.h"
#include "report/reproduction_report.h"
#include "report/text_table.h"

namespace tcsb::cli {

namespace {

/// --budget: a finite number of seconds in [0, kMaxReproduceBudget], else UsageError.
void check_budget(const std::optional<double>& budget) {
  if (budget && !(std::isfinite(*budget) && *budget >= 0.0 && *budget <= kMaxReproduceBudget))
    throw UsageError("--budget: expected seconds between 0 and " + general(kMaxReproduceBudget, 6) + ", got " +
                     general(*budget, 6));
}

/// One line per look on stderr, so a long adaptive phase is not silent.
void print_look(const Look& look) {
  std::cerr << "tcsb: look " << look.look;
  if (look.extra > 0) std::cerr << ": +" << look.extra << " repetitions of " << look.cases << " cases";
  std::cerr << ", " << look.undecided << " claim(s) undecided (" << fixed(look.seconds, 1) << " s)\n";
}

}  // namespace

CLI::App* add_reproduce_command(CLI::App& app, ReproduceArgs& args) {
  CLI::App* cmd = app.add_subcommand("reproduce", "Run the paper suite and check the paper's claims (the default)");
  cmd->add_option("--suite", args.suite, "Suite to reproduce with (a path or bundled name)")->capture_default_str();
  cmd->add_option("--paper", args.paper, "The paper's numbers (JSON)")->capture_default_str();
  cmd->add_option("--out", args.out, "Write the JSON report to FILE (atomically) instead of stdout");
  cmd->add_flag("--quiet", args.quiet, "Only the side-by-side tables and claims on stderr");
  cmd->add_flag("--targets", args.targets, kTargetsFlagHelp);
  add_repetitions_option(*cmd, args.repetitions);
  cmd->add_option("--budget", args.budget,
                  "Seconds for judging the claims after the run: intervals, and extra repetitions of undecided "
                  "claims while they fit (default: what is left of 150 s for the whole command; 0: no extra "
                  "repetitions)");
  cmd->add_option("--processes", args.processes,
                  "Measure the run's repetitions in P processes, one after another, and merge them: the claims' "
                  "intervals then resample processes first, so they include the spread between processes")
      ->capture_default_str();
  return cmd;
}

int reproduce_command(const ReproduceArgs& args) {
  const StepClock::time_point start = StepClock::now();
  check_budget(args.budget);
  check_out_path(args.out);
  const std::filesystem::path paper_file = resolve_data_file(args.paper);
  const std::filesystem::path suite_file = resolve_suite(args.suite);
  check_out_is_not_input(args.out, paper_file);
  check_out_is_not_input(args.out, suite_file);
  const PaperReference paper = load_paper_reference(paper_file);
  // --repetitions is applied before parse_suite's memory check (see run_command).
  const Suite suite = parse_suite(suite_file, [&args](Suite& s) { apply_repetitions(args.repetitions, s); });
  check_out_is_not_suite_input(args.out, suite);
  refuse_axes(suite, "reproduce");  // its claims and extra repetitions are of one configuration
  RunResult result;
  std::optional<nlohmann::ordered_json> merged_context;  // with --processes: the merged shards' context block
  if (args.processes == 1) {
    result = run_on_console(suite, args.quiet).result;  // the looks may add repetitions: tables are taken after
  } else {
    MergedShards merged = run_in_processes(suite_file, args.repetitions, args.processes, suite.repetitions);
    for (const std::string& warning : merged.warnings) print_warning(warning);
    result = std::move(merged.result);
    merged_context = std::move(merged.context);
    if (!args.quiet) print_console_report(result, run_tables(result), std::cerr);
  }

  ReproductionOptions options;
  const double elapsed_s = ms_between(start, StepClock::now()) / 1000.0;
  options.budget_s = args.budget ? *args.budget : std::max(0.0, kReproductionWallTargetS - elapsed_s);
  if (!args.quiet) options.on_look = print_look;
  const Reproduction reproduction = check_reproduction(result, paper, options);
  warn_repetitions(result, suite.repetitions);  // those the looks added; the run's own were warned of above
  print_reproduction(reproduction, args.targets, std::cerr);

  nlohmann::ordered_json report = native_json(result, reproduction.tables.run);
  if (merged_context) report["context"] = *merged_context;
  report["reproduction"] = reproduction_json(reproduction);
  const int written = write_report(json_text(report), args.out);
  if (written != kExitOk) return written;
  switch (reproduction.verdict()) {
    case Verdict::kPass: return kExitOk;
    case Verdict::kFail: return kExitFailed;
    case Verdict::kUndecided: return kExitUndecided;
  }
  return kExitInternal;
}

}  // namespace tcsb::cli
