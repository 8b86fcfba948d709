// `tcsb validate`: everything parse_suite checks (keys, types, ranges, memory), without running anything.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "report/terminal_text.h"
#include "suite/case_plan.h"
#include "suite/suite_memory.h"

namespace tcsb::cli {

CLI::App* add_validate_command(CLI::App& app, ValidateArgs& args) {
  CLI::App* validate = app.add_subcommand("validate", "Check a suite without running it");
  validate->add_option("suite", args.suite, "Suite file, or a bundled suite name")->required();
  return validate;
}

int validate_command(const ValidateArgs& args) {
  const Suite suite = parse_suite(resolve_suite(args.suite));
  char mib[32];
  std::snprintf(mib, sizeof mib, "%.1f", static_cast<double>(estimate_peak_bytes(suite)) / (1024.0 * 1024.0));
  std::cout << terminal_safe(args.suite) << ": ok (" << suite.nets.size() << " nets, " << expand_cases(suite).size()
            << " cases, " << suite.repetitions << " repetitions, estimated peak memory " << mib << " MiB)" << std::endl;
  return kExitOk;
}

}  // namespace tcsb::cli
