// `tcsb export RESULT --format NAME`: an existing result file (a baseline, a run from another machine) in another
// format, without running anything again. The same formats `tcsb run --format` offers, rendered from the file.
#include <CLI/CLI.hpp>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/run_support.h"
#include "result/result_file.h"

namespace tcsb::cli {

CLI::App* add_export_command(CLI::App& app, ExportArgs& args) {
  CLI::App* cmd =
      app.add_subcommand("export", "Convert a result file to another format (gbench, github-action-*, markdown)");
  cmd->add_option("result", args.result, "A result file written by `tcsb run`")->required();
  cmd->add_option("--format", args.format, "Output format: " + known_formats())->required();
  cmd->add_option("--out", args.out, "Write to FILE (atomically) instead of stdout");
  return cmd;
}

int export_command(const ExportArgs& args) {
  const std::unique_ptr<ReportFormat> format = checked_format(args.format);
  check_out_path(args.out);
  check_out_is_not_input(args.out, args.result);
  const LoadedResult result = load_result_file(args.result);
  return write_report(format->render_native(result.document), args.out);
}

}  // namespace tcsb::cli
