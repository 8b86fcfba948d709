// What every subcommand shares: exit codes, where the bundled suites live, how a SUITE argument becomes a file, and
// how failures become exactly one "tcsb: error: ..." line on stderr.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "suite/suite.h"

namespace CLI {
class App;
class ParseError;
}  // namespace CLI

namespace tcsb::cli {

/// Process exit codes (DESIGN §6).
enum ExitCode : int {
  kExitOk = 0,         ///< success (a run with diverged cases included: they are reported, not hidden)
  kExitFailed = 1,     ///< a gate or claim failed (decided)
  kExitUsage = 2,      ///< bad usage or bad input; nothing ran and no output file was touched
  kExitInternal = 3,   ///< anything else: a bug, or the machine failed us (e.g. the output could not be written)
  kExitUndecided = 4,  ///< reproduce, tax: no claim failed, but some remain undecided (within the run's noise)
};

/// Bad usage found after parsing (an unusable --out, an unknown --format): exits with kExitUsage.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where bundled suites live: $TCSB_SUITES_DIR if set and non-empty, else TCSB_SOURCE_DIR/suites.
std::filesystem::path suites_dir();

/// Names of the bundled suites (stems of *.json in suites_dir()), sorted; empty if the directory is missing.
std::vector<std::string> bundled_suite_names();

/// A SUITE argument as a file: an existing path as is; a bare name ("paper") as suites_dir()/NAME.json. Throws
/// InputError naming the argument when a bare name is neither a file nor a bundled suite.
std::filesystem::path resolve_suite(const std::string& argument);

/// Throws InputError naming the suite file and its `axes` when the suite has axes: `command` ("reproduce",
/// "frames", "calibrate") runs the suite's one set of settings, and only `tcsb run` runs configurations.
void refuse_axes(const Suite& suite, const std::string& command);

/// `text` with line breaks turned into spaces, so every error is exactly one line, made terminal_safe (control
/// characters escaped) and cut to kMaxMessageBytes (base/terminal_text.h).
std::string one_line(std::string_view text);

/// Writes "tcsb: error: <message>" as one line to stderr.
void print_error(std::string_view message);

/// Writes "tcsb: warning: <message>" as one line to stderr.
void print_warning(std::string_view message);

/// Runs a command, turning exceptions into one stderr line and an exit code: InputError, UsageError and running out
/// of memory (OutOfMemoryError, std::bad_alloc: a suite too large for this machine) -> kExitUsage; WriteError
/// (base/atomic_file.h: an output the machine refused) -> kExitInternal; any other
/// std::exception -> "tcsb: internal error: ..." and kExitInternal.
int guarded(const std::function<int()>& command);

/// Exit code for a command-line parse failure: --help prints help (0); anything else prints one error line (2).
int parse_error_exit(CLI::App& app, const CLI::ParseError& error);

/// "tcsb <version> (commit <git>, Bullet <version> <precision>)".
std::string version_line();

}  // namespace tcsb::cli
