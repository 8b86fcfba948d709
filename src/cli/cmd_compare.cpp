// `tcsb compare BASE NEW`: the CI regression gate. Unlike Google Benchmark's compare.py (which always exits 0) it
// exits 1 when behaviour changed — a deterministic quantity (N, L, I, operations, status, final-state hash)
// differs — or a gated metric regressed. Timings (analysis/regression_gate.h) get three verdicts from a bootstrap
// interval of each metric's change with the threshold as the margin: regression (exit 1), no regression, or
// undecided (exit 4, with about how many more repetitions would decide). By default only same-run ratios gate,
// because they survive a noisy shared machine; absolute step times gate only with --absolute. Instruction counts
// (results of `tcsb run --measure instructions`) are the same in every run of a build, so a count that grows beyond
// the threshold is a decided regression (gate/instruction_gate.h). It fails closed: every case (by label) and
// repetition (by number) must be matched one to one, impossible values (a time <= 0, an ok repetition without one)
// are refused while reading, and with nothing reliable to gate it cannot pass. Runs of different suites, settings or
// measures are refused (exit 2), and so are runs the gate cannot decide on.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>

#include "base/atomic_file.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/run_support.h"
#include "gate/gate_outcome.h"
#include "report/comparison_summary.h"
#include "report/gate_summary_json.h"
#include "report/json_report.h"
#include "result/result_file.h"

namespace tcsb::cli {
namespace {

void warn_about_contexts(const LoadedResult& base, const LoadedResult& next, const ResultComparison& comparison) {
  if (!comparison.machine_differences.empty()) {
    std::string list;
    for (const std::string& d : comparison.machine_differences) list += (list.empty() ? "" : "; ") + d;
    print_warning(base.view.file + " and " + next.view.file + " come from different machines or builds (" + list +
                  "): absolute step times are not comparable; the same-run ratios still are");
  }
  // The runs' own context warnings (a loaded machine, a debug build) explain noisy numbers: repeat them here.
  for (const LoadedResult* r : {&base, &next}) {
    const auto warnings = r->view.context.find("warnings");
    if (warnings == r->view.context.end() || !warnings->is_array()) continue;
    for (const auto& w : *warnings) {
      if (w.is_string()) print_warning(r->view.file + " was measured with a warning: " + w.get<std::string>());
    }
  }
}

}  // namespace

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "compare", "Regression gate: compare two results of the same suite and measure (exit 0 pass, 1 regression "
                 "or changed behaviour, 2 bad input, different suites or measures or nothing to decide on, 4 "
                 "timings undecided)");
  cmd->add_option("base", args.base, "Baseline result (a `tcsb run` JSON file)")->required();
  cmd->add_option("new", args.next, "New result of the same suite")->required();
  cmd->add_option("--alpha", args.alpha, "Family-wise significance level of the U tests (Holm), in (0, 1)")
      ->capture_default_str();
  cmd->add_option("--threshold", args.threshold,
                  "Smallest relative change that fails (0.05 = 5 %): of a timing median (default 0.05), or of an "
                  "instruction count (results of --measure instructions; default 0.005)");
  cmd->add_flag("--absolute", args.absolute, "Gate absolute step times too (only on a dedicated machine)");
  cmd->add_option("--summary", args.summary, "Write the Markdown summary to FILE (atomically) instead of stderr");
  cmd->add_option("--summary-json", args.summary_json,
                  "Also write the verdict and its counts as JSON to FILE (atomically): verdict, exit_code, "
                  "behaviour_changes, regressions, undecided, more_repetitions");
  return cmd;
}

int compare_command(const CompareArgs& args) {
  if (!(args.alpha > 0.0 && args.alpha < 1.0)) {
    throw UsageError("--alpha: must be in (0, 1), got " + std::to_string(args.alpha));
  }
  if (args.threshold && (!(*args.threshold >= 0.0) || !std::isfinite(*args.threshold))) {
    throw UsageError("--threshold: must be a finite number >= 0, got " + std::to_string(*args.threshold));
  }
  check_out_path(args.summary, "--summary");
  check_out_is_not_input(args.summary, args.base, "--summary");
  check_out_is_not_input(args.summary, args.next, "--summary");
  check_out_path(args.summary_json, "--summary-json");
  check_out_is_not_input(args.summary_json, args.base, "--summary-json");
  check_out_is_not_input(args.summary_json, args.next, "--summary-json");
  if (!args.summary_json.empty() && args.summary_json == args.summary)
    throw UsageError("--summary-json: the same file as --summary");
  const LoadedResult base = load_result_file(args.base);
  const LoadedResult next = load_result_file(args.next);
  ResultComparison comparison;
  try {
    comparison = compare_results(base.view, next.view);
  } catch (const SuiteMismatch& e) {
    throw UsageError(e.what());
  }
  GateSettings settings;
  settings.alpha = args.alpha;
  settings.threshold =
      args.threshold.value_or(comparison.measure == "instructions" ? kInstructionThreshold : kTimeThreshold);
  const GateOutcome outcome = decide_gate(std::move(comparison), settings, args.absolute);
  // No reliable gated metric: the gate measured nothing, so it must not pass (kExitOk). Nor has it failed
  // (kExitFailed means a gate decided that something failed): that would report a regression nobody measured. The
  // files cannot answer the question (too few repetitions, no TC-SB case with a plain partner): bad input,
  // kExitUsage, one line and no summary, as for any unusable input. Changed behaviour is decided without timings,
  // so it still fails (kExitFailed) below, with its summary.
  if (!outcome.timings_decided() && !outcome.behaviour_changed()) {
    throw UsageError(base.view.file + " and " + next.view.file +
                     ": the gate cannot decide: " + undecided_reason(outcome));
  }
  warn_about_contexts(base, next, outcome.comparison);
  const std::string summary = comparison_summary_markdown(outcome, base.view, next.view);
  if (args.summary.empty()) {
    std::cerr << summary << '\n';
  } else {
    write_file_atomically(args.summary, summary);
  }
  int exit_code = kExitFailed;
  if (outcome.verdict() == Verdict::kPass) exit_code = kExitOk;
  if (outcome.verdict() == Verdict::kUndecided) exit_code = kExitUndecided;
  if (!args.summary_json.empty())
    write_file_atomically(args.summary_json,
                          json_text(gate_summary_json(outcome, exit_code, base.view.file, next.view.file)));
  std::cerr << "tcsb compare: " << comparison_verdict_line(outcome) << std::endl;
  return exit_code;
}

}  // namespace tcsb::cli
