// `tcsb reproduce` (and `tcsb` with no arguments): runs the paper suite, prints Tables 1 and 2 beside the paper's
// own numbers (results/paper.json), checks the paper's claims and exits 1 if any fails.
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/run_support.h"
#include "report/json_report.h"
#include "report/reproduction_report.h"
#include "report/report_writer.h"

namespace tcsb::cli {

CLI::App* add_reproduce_command(CLI::App& app, ReproduceArgs& args) {
  CLI::App* cmd = app.add_subcommand("reproduce", "Run the paper suite and check the paper's claims (the default)");
  cmd->add_option("--suite", args.suite, "Suite to reproduce with (a path or bundled name)")->capture_default_str();
  cmd->add_option("--paper", args.paper, "The paper's numbers (JSON)")->capture_default_str();
  cmd->add_option("--out", args.out, "Write the JSON report to FILE (atomically) instead of stdout");
  cmd->add_flag("--quiet", args.quiet, "Only the side-by-side tables and claims on stderr");
  add_repetitions_option(*cmd, args.repetitions);
  return cmd;
}

int reproduce_command(const ReproduceArgs& args) {
  check_out_path(args.out);
  const std::filesystem::path paper_file = resolve_data_file(args.paper);
  const std::filesystem::path suite_file = resolve_suite(args.suite);
  check_out_is_not_input(args.out, paper_file);
  check_out_is_not_input(args.out, suite_file);
  const PaperReference paper = load_paper_reference(paper_file);
  // --repetitions is applied before parse_suite's memory check (see run_command).
  const Suite suite = parse_suite(suite_file, [&args](Suite& s) { apply_repetitions(args.repetitions, s); });
  const RunResult result = run_on_console(suite, args.quiet);
  const Reproduction reproduction = check_reproduction(result, paper);
  print_reproduction(result, reproduction, std::cerr);

  nlohmann::ordered_json report = native_json(result);
  report["reproduction"] = reproduction_json(result, reproduction);
  const int written = write_report(json_text(report), args.out);
  if (written != kExitOk) return written;
  return reproduction.pass() ? kExitOk : kExitFailed;
}

}  // namespace tcsb::cli
