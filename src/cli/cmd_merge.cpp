// `tcsb merge SHARD.json... --out ALL.json`: joins the results of `tcsb run SUITE --shard K/N` for K = 1..N (run on
// Slurm array tasks, CI matrix jobs or GNU parallel slots) into the result one `tcsb run SUITE` would have written:
// the same cases in the same order, with Table 1, Table 2, the fits and the fidelity tables computed from the merged
// cases (sweep/shard_merge.h). Bad sets of shards are refused before anything is written.
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/run_support.h"
#include "gate/run_consistency.h"
#include "report/console_report.h"
#include "report/json_report.h"
#include "result/result_file.h"
#include "sweep/shard_merge.h"

namespace tcsb::cli {

CLI::App* add_merge_command(CLI::App& app, MergeArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join the JSON results of `tcsb run SUITE --shard K/N`, K = 1..N, into one result of the whole suite");
  cmd->add_option("shards", args.shards, "Shard result files, each shard exactly once, in any order")->required();
  cmd->add_option("--out", args.out, "Write the merged result to FILE (atomically) instead of stdout");
  cmd->add_flag("--quiet", args.quiet, "No console report on stderr (warnings still appear)");
  return cmd;
}

int merge_command(const MergeArgs& args) {
  check_out_path(args.out);
  for (const std::string& shard : args.shards) check_out_is_not_input(args.out, shard);
  std::vector<ShardDocument> shards;
  for (const std::string& file : args.shards) {
    LoadedResult shard = load_result_file(file);
    check_run_is_possible(shard.view);  // as strictly as a result is checked before it is judged
    shards.push_back({file, std::move(shard.document)});
  }
  const MergedShards merged = merge_shards(shards);
  // The suite and its calibration were read too (from where the shards' suite lived).
  check_out_is_not_suite_input(args.out, merged.result.suite);
  for (const std::string& warning : merged.warnings) print_warning(warning);
  const RunTables tables = run_tables(merged.result);
  if (!args.quiet) print_console_report(merged.result, tables, std::cerr);
  return write_report(json_text(merged_json(merged, tables)), args.out);
}

}  // namespace tcsb::cli
