// `tcsb run`: parse a suite, run it, and write the report. Everything that could make the end of a long run fail
// (an unknown format, an unwritable --out) is checked before the first step.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>

#include "case/instruction_meter.h"
#include "cli/callgrind_launch.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/flag_values.h"
#include "cli/run_support.h"
#include "report/json_report.h"
#include "report/report_format.h"
#include "report/shard_section.h"
#include "run/instruction_counts.h"
#include "sweep/shard_plan.h"

namespace tcsb::cli {
namespace {

/// Budgets given on the command line replace the suite's, checked like the suite's own (exit 2 when wrong).
void apply_budget_overrides(const RunArgs& args, Suite& suite) {
  if (!args.compression.empty()) {
    const auto runs = [&suite](Method m) {
      return std::find(suite.methods.begin(), suite.methods.end(), m) != suite.methods.end();
    };
    if (!runs(Method::kTcsb) && !runs(Method::kPlainEqual))
      throw UsageError("--compression: the suite runs neither tcsb nor plain_equal");
    // plain_equal runs one case per budget below 1: without one it would silently run nothing.
    if (runs(Method::kPlainEqual) &&
        std::none_of(args.compression.begin(), args.compression.end(), [](double c) { return c < 1.0; }))
      throw UsageError("--compression: the suite runs plain_equal, which needs a budget below 1");
    for (std::size_t i = 0; i < args.compression.size(); ++i) {
      const double c = checked_budget(args.compression[i]);
      if (std::find(args.compression.begin(), args.compression.begin() + static_cast<std::ptrdiff_t>(i), c) !=
          args.compression.begin() + static_cast<std::ptrdiff_t>(i))
        throw UsageError("--compression: budget " + std::to_string(c) + " given twice");
    }
    suite.compression = args.compression;
  }
  if (args.max_step_ms) {
    if (!std::isfinite(*args.max_step_ms) || *args.max_step_ms < 0)
      throw UsageError("--max-step-ms: must be a finite number of milliseconds >= 0");
    suite.feedback.max_step_ms = *args.max_step_ms;
  }
}

/// --shard as a ShardIndex (nullopt without it). Only the native JSON carries what `tcsb merge` needs, so a shard
/// in another format could never be merged: refused too.
std::optional<ShardIndex> checked_shard(const RunArgs& args) {
  const std::optional<ShardSplit> split = parse_split(args.split);
  if (!split) throw UsageError("--split: expected repetitions or nets, got \"" + args.split + "\"");
  if (args.shard.empty()) return std::nullopt;
  const std::optional<ShardIndex> shard = parse_shard_index(args.shard, *split);
  if (!shard) {
    throw UsageError("--shard: expected K/N with 1 <= K <= N <= " + std::to_string(kMaxShards) + ", got \"" +
                     args.shard + "\"");
  }
  if (args.format != "json") throw UsageError("--shard: needs --format json (the format `tcsb merge` reads)");
  return shard;
}

/// What a run with --measure instructions needs of its options and suite: counts that are the same in every run (the
/// feedback on the simulation thread, no time budget steering the work) in the native JSON, one process.
void check_instruction_measure(const RunArgs& args, const Suite& suite) {
  const std::string flag = "--measure instructions: ";
  if (args.format != "json") throw UsageError(flag + "needs --format json (the format that records the counts)");
  if (!args.shard.empty()) throw UsageError(flag + "cannot be sharded (--shard)");
  if (suite.feedback.parallel)
    throw UsageError(suite.path.string() + ": feedback.parallel: " + flag +
                     "needs false (a worker thread's instructions would depend on scheduling)");
  if (suite.feedback.max_step_ms > 0)
    throw UsageError(suite.path.string() + ": feedback.max_step_ms: " + flag +
                     "needs 0 (a time budget makes the work depend on the clock)");
}

Measure checked_measure(const std::string& measure) {
  if (measure == "time") return Measure::kTime;
  if (measure == "instructions") return Measure::kInstructions;
  throw UsageError("--measure: expected time or instructions, got \"" + measure + "\"");
}

}  // namespace

CLI::App* add_run_command(CLI::App& app, RunArgs& args) {
  CLI::App* run = app.add_subcommand("run", "Run a suite and print its JSON report");
  run->add_option("suite", args.suite, "Suite file, or a bundled suite name (see `tcsb list`)")->required();
  run->add_option("--out", args.out, "Write the report to FILE (atomically) instead of stdout");
  run->add_option("--format", args.format, "Output format: " + known_formats())->capture_default_str();
  run->add_flag("--quiet", args.quiet, "No console report on stderr (warnings still appear)");
  add_list_option(*run, "--compression", args.compression,
                  "TC-SB node budgets as fractions of the initial node count, e.g. 0.75,0.3 (overrides the suite)");
  run->add_option("--max-step-ms", args.max_step_ms,
                  "TC-SB time budget per step in ms, 0 to disable (overrides the suite)");
  add_repetitions_option(*run, args.repetitions);
  run->add_option("--shard", args.shard,
                  "Run only shard K of N (e.g. 2/4): a deterministic share of the suite's repetitions or nets "
                  "(--split), each net's cases together; join the shards' JSON results with `tcsb merge`");
  run->add_option("--split", args.split,
                  "What --shard splits: repetitions (a net's repetitions spread over the shards, each with all the "
                  "net's cases) or nets (each net with all its repetitions in one shard)")
      ->capture_default_str();
  run->add_option("--measure", args.measure,
                  "What each timed step is measured in: time, or instructions (TC-SB's own and Bullet's, counted by "
                  "Valgrind's callgrind, which tcsb starts itself; deterministic, for `tcsb compare`)")
      ->capture_default_str();
  return run;
}

int run_command(const RunArgs& args) {
  // Under callgrind (started by the outer tcsb): tell it valgrind did start this process, whatever happens next.
  if (running_on_valgrind()) note_started_under_callgrind();
  checked_format(args.format);
  const std::optional<ShardIndex> shard = checked_shard(args);
  check_out_path(args.out);
  const std::filesystem::path suite_file = resolve_suite(args.suite);
  check_out_is_not_input(args.out, suite_file);
  // The flags are applied inside parse_suite, before its memory check: a suite too large for this machine is
  // refused whether its size comes from the file or from --repetitions / --compression.
  const Suite suite = parse_suite(suite_file, [&args, &shard](Suite& s) {
    apply_budget_overrides(args, s);
    apply_repetitions(args.repetitions, s);
    // A shard runs only its units, and the memory check counts only them: it may fit where the whole suite would not.
    if (shard) restrict_to_shard(s, *shard);
  });
  if (checked_measure(args.measure) == Measure::kInstructions) {
    check_instruction_measure(args, suite);
    if (!running_on_valgrind()) return rerun_under_callgrind();
  }
  return run_and_report(suite, args);
}

int run_and_report(const Suite& suite, const RunArgs& args) {
  const std::unique_ptr<ReportFormat> format = checked_format(args.format);
  const std::optional<ShardIndex> shard = checked_shard(args);
  check_out_path(args.out);
  check_out_is_not_suite_input(args.out, suite);
  const Measure measure = checked_measure(args.measure);
  std::filesystem::path counts;
  if (measure == Measure::kInstructions) {
    check_instruction_measure(args, suite);
    counts = callgrind_out_file();
  }
  FinishedRun run = run_on_console(suite, args.quiet, shard, measure);
  // The counts change no table (they read step times), so the tables computed for the console stay the run's.
  if (measure == Measure::kInstructions)
    attach_instruction_counts(run.result, read_meter_dumps(counts), counts.string());
  // A shard's result carries what `tcsb merge` needs (--shard takes the native JSON only).
  return write_report(shard ? json_text(shard_json(run.result, run.tables)) : format->render(run.result, run.tables),
                      args.out);
}

}  // namespace tcsb::cli
