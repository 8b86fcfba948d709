// What the commands that run suites share: checking --out before a long run, the progress line, warnings about
// diverged cases, and writing the report atomically.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "paper/run_tables.h"
#include "report/report_format.h"
#include "run/run_result.h"
#include "suite/suite.h"

namespace CLI {
class App;
}  // namespace CLI

namespace tcsb::cli {

/// Fails now (UsageError), not after the run, if --out could not be written (base/atomic_file.h's
/// output_problem: a missing directory, a directory, a name too long, no file can be created there). Empty `out`
/// means stdout: nothing to check. `option` names the flag in the message.
void check_out_path(const std::string& out, const std::string& option = "--out");

/// Fails now (UsageError) if `out` is the file `input` the command reads: compared by device and inode when both
/// exist (so a symlink, "./x" or a hard link is caught), else by canonical path. Empty `out` or `input`: nothing.
void check_out_is_not_input(const std::string& out, const std::filesystem::path& input,
                            const std::string& option = "--out");

/// check_out_is_not_input for every file a parsed suite was read from: the suite file and its calibration.
void check_out_is_not_suite_input(const std::string& out, const Suite& suite, const std::string& option = "--out");

/// The names of the output formats, comma-separated ("json, gbench, ..."), for --format's help and errors.
std::string known_formats();

/// The output format called `name` (--format); throws UsageError listing the known ones when there is none.
std::unique_ptr<ReportFormat> checked_format(const std::string& name);

/// A TC-SB node budget given with --compression: returned when in (0, 1], else UsageError.
double checked_budget(double compression);

/// Options both `run` and `reproduce` take: --repetitions.
void add_repetitions_option(CLI::App& command, std::optional<int>& repetitions);
/// Applies --repetitions to the suite, within the bounds the suite file itself has (UsageError otherwise).
void apply_repetitions(const std::optional<int>& repetitions, Suite& suite);

/// A finished run and its tables (paper/run_tables.h), which every rendering of it shows.
struct FinishedRun {
  RunResult result;
  RunTables tables;
};

/// Runs the suite as `run` and `reproduce` do, talking on stderr: the machine's warnings (run/context.h), a
/// single updating progress line when stderr is a terminal and not `quiet`, the console report unless `quiet`, then
/// a warning per diverged repetition (case, step, reason) and per repetition during which the machine stalled
/// (run/stall.h).
/// With `shard`, the result says which shard it is; the suite must be restricted to it (restrict_to_shard()).
/// With Measure::kInstructions the process must run under callgrind (cli/callgrind_launch.h).
/// Returns the run with its tables, computed once for the console and the output file.
FinishedRun run_on_console(const Suite& suite, bool quiet, const std::optional<ShardIndex>& shard = std::nullopt,
                           Measure measure = Measure::kTime);

/// The warnings run_on_console gives after a run (diverged and stalled repetitions), for the repetitions numbered
/// `from` or later: `reproduce` gives them for the repetitions its looks added.
void warn_repetitions(const RunResult& result, int from);

/// Writes the report to stdout, or atomically to `out`. If the file cannot be written after a long run, the report
/// goes to stdout instead and the result is kExitInternal; otherwise kExitOk. Whether stdout took the report is
/// checked once for every command at exit (cli/standard_streams.h's finish_stdout).
int write_report(const std::string& text, const std::string& out);

/// A data file argument (such as results/paper.json): as given if it exists, else relative to the source tree.
std::filesystem::path resolve_data_file(const std::string& argument);

}  // namespace tcsb::cli
