// `tcsb tax RUN.json...`: judges the tax of adaptivity on finished runs — per net, TC-SB's step time over that of
// plain_equal (a static plain body of its node budget) in the same repetition — pooled over one or more runs of one
// suite and build (gate/adaptivity_tax.h). Prints the table on stderr and the JSON verdict on stdout or --out, and
// exits 0 (every net passes), 1 (one fails), 4 (none fails, some undecided) or 2 (bad input, nothing to judge).
#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/run_support.h"
#include "gate/result_comparison.h"
#include "gate/run_consistency.h"
#include "gate/same_process.h"
#include "report/json_report.h"
#include "report/tax_report.h"
#include "report/text_table.h"
#include "result/result_file.h"

namespace tcsb::cli {
namespace {

void check_target(const TaxArgs& args) {
  if (!(std::isfinite(args.bound) && args.bound > 0.0))
    throw UsageError("--bound: expected a ratio > 0, got " + general(args.bound, 6));
  if (!(args.compression > 0.0 && args.compression < 1.0))
    throw UsageError("--compression: expected a node budget in (0, 1), got " + general(args.compression, 6));
  if (args.min_nodes < 1)
    throw UsageError("--min-nodes: expected a node count >= 1, got " + std::to_string(args.min_nodes));
}

/// Each process counts once: the same file twice (by path), or two files holding one process's measurements (a
/// copy with its date edited, a merged result beside one of its shards) would count its repetitions twice and
/// narrow the interval.
void check_distinct(const std::vector<std::string>& files, const std::vector<LoadedResult>& runs) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      std::error_code ec;
      std::string why = std::filesystem::equivalent(files[i], files[j], ec) ? "the same file" : "";
      if (why.empty()) why = shared_measurement(runs[j].view, runs[i].view);
      if (!why.empty())
        throw UsageError(files[i] + ": the same run as " + files[j] + " (" + why +
                         "; each process may be pooled once)");
    }
  }
}

/// A run no `tcsb run` could have written is not judged (gate/run_consistency.h).
void check_possible(const std::vector<LoadedResult>& runs) {
  for (const LoadedResult& r : runs) check_run_is_possible(r.view);
}

}  // namespace

CLI::App* add_tax_command(CLI::App& app, TaxArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "tax",
      "Judge the tax of adaptivity on finished runs: per net, TC-SB against plain_equal (a static body of its node "
      "budget), pooled over runs of one suite and build (exit 0 pass, 1 fail, 4 undecided, 2 bad input)");
  cmd->add_option("runs", args.runs,
                  "Result files of `tcsb run` (one suite, settings and build; repetitions may differ)")
      ->required();
  cmd->add_option("--bound", args.bound, "The largest ratio to plain_equal that passes")->capture_default_str();
  cmd->add_option("--compression", args.compression, "The TC-SB node budget judged (a fraction in (0, 1))")
      ->capture_default_str();
  cmd->add_option("--min-nodes", args.min_nodes, "Judge only nets of at least this many grid nodes")
      ->capture_default_str();
  cmd->add_flag("--over-nets", args.over_nets,
                "Judge the nets together, as Table 2 does (the mean of TC-SB's median steps over plain_equal's), "
                "instead of each net");
  cmd->add_option("--out", args.out, "Write the JSON verdict to FILE (atomically) instead of stdout");
  return cmd;
}

int tax_command(const TaxArgs& args) {
  check_target(args);
  check_out_path(args.out);
  for (const std::string& run : args.runs) check_out_is_not_input(args.out, run);
  std::vector<LoadedResult> loaded;
  for (const std::string& run : args.runs) loaded.push_back(load_result_file(run));
  check_possible(loaded);
  check_distinct(args.runs, loaded);
  std::vector<ResultView> views;
  for (const LoadedResult& r : loaded) views.push_back(r.view);

  TaxTarget target;
  target.bound = args.bound;
  target.compression = args.compression;
  target.min_net_nodes = args.min_nodes;
  target.over_nets = args.over_nets;
  std::vector<NetTax> nets;
  try {
    nets = judge_tax(views, target);
  } catch (const SuiteMismatch& e) {
    throw UsageError(e.what());
  }
  if (nets.empty())
    throw UsageError(args.runs.front() + ": nothing to judge: no TC-SB case at " + general(args.compression, 6) +
                     " with a plain_equal case on a net of at least " + std::to_string(args.min_nodes) +
                     " nodes (the scaling suite has them)");
  for (std::size_t i = 1; i < views.size(); ++i) {
    const std::vector<std::string> differences = machine_differences(views.front(), views[i]);
    if (!differences.empty())
      print_warning(views.front().file + " and " + views[i].file + " ran on different machines or builds (" +
                    differences.front() + "): their ratios are pooled as runs of one population");
  }
  for (const ResultView& v : views) {
    const auto it = v.context.find("git_commit");
    const std::string commit = it != v.context.end() && it->is_string() ? it->get<std::string>() : "";
    if (views.size() > 1 && commit.ends_with("-dirty"))
      print_warning(v.file + " was built from a modified tree (" + commit +
                    "): runs of different modifications of one commit cannot be told apart, and pool");
  }
  if (views.size() == 1)
    print_warning("one run: its intervals cover the noise between its repetitions, not the variation between runs in "
                  "separate processes (docs/methodology.md, \"The tax across runs\"); pool several runs to judge that");
  print_tax(nets, target, std::cerr);

  const int written = write_report(json_text(tax_json(nets, target, args.runs)), args.out);
  if (written != kExitOk) return written;
  switch (tax_verdict(nets)) {
    case Verdict::kPass: return kExitOk;
    case Verdict::kFail: return kExitFailed;
    case Verdict::kUndecided: return kExitUndecided;
  }
  return kExitInternal;
}

}  // namespace tcsb::cli
