// `tcsb validate`: everything parse_suite checks (keys, types, ranges, axes, memory), without running anything. For
// a suite with axes it also says how many configurations the axes make and about how long the run takes.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>

#include "base/terminal_text.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "suite/case_plan.h"
#include "suite/suite_memory.h"
#include "suite/suite_time.h"

namespace tcsb::cli {

CLI::App* add_validate_command(CLI::App& app, ValidateArgs& args) {
  CLI::App* validate = app.add_subcommand("validate", "Check a suite without running it");
  validate->add_option("suite", args.suite, "Suite file, or a bundled suite name")->required();
  return validate;
}

namespace {

/// "about 40 s", "about 12 min" or "about 3.5 h" (or "under 1 s"): a rough figure in a unit a person plans with.
std::string wall_time_text(double seconds) {
  char buf[48];
  if (seconds < 1)
    std::snprintf(buf, sizeof buf, "under 1 s");
  else if (seconds < 120)
    std::snprintf(buf, sizeof buf, "about %.0f s", seconds);
  else if (seconds < 2 * 3600)
    std::snprintf(buf, sizeof buf, "about %.0f min", seconds / 60);
  else
    std::snprintf(buf, sizeof buf, "about %.1f h", seconds / 3600);
  return buf;
}

}  // namespace

int validate_command(const ValidateArgs& args) {
  const Suite suite = parse_suite(resolve_suite(args.suite));
  char mib[32];
  std::snprintf(mib, sizeof mib, "%.1f", static_cast<double>(estimate_peak_bytes(suite)) / (1024.0 * 1024.0));
  if (suite.axes.empty()) {  // as it always was
    std::cout << terminal_safe(args.suite) << ": ok (" << suite.nets.size() << " nets, " << expand_cases(suite).size()
              << " cases, " << suite.repetitions << " repetitions, estimated peak memory " << mib << " MiB)"
              << std::endl;
    return kExitOk;
  }
  std::cout << terminal_safe(args.suite) << ": ok (" << suite.nets.size() << " nets, " << suite.configurations.size()
            << " configurations, " << expand_cases(suite).size() << " cases, " << suite.repetitions
            << " repetitions, estimated peak memory " << mib << " MiB, estimated wall time "
            << wall_time_text(estimate_wall_seconds(suite)) << ")" << std::endl;
  return kExitOk;
}

}  // namespace tcsb::cli
