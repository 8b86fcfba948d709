#include "cli/run_support.h"

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <unistd.h>

#include "cli/cli_common.h"
#include "harness/context.h"
#include "harness/runner.h"
#include "harness/stall.h"
#include "report/console_report.h"
#include "report/report_writer.h"
#include "report/terminal_text.h"
#include "report/text_table.h"

namespace tcsb::cli {

void check_out_path(const std::string& out, const std::string& option) {
  if (out.empty()) return;
  const std::filesystem::path path(out);
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw UsageError(option + " " + out + ": directory " + dir.string() + " does not exist");
  }
  if (std::filesystem::is_directory(path, ec)) throw UsageError(option + " " + out + ": is a directory");
  // A device or pipe (/dev/null, /dev/stdout, a FIFO) is written into, not replaced: no file is created beside it.
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) return;
  // Create a file for real rather than ask access(): root passes access() on read-only file systems and /proc.
  const std::filesystem::path probe = dir / (".tcsb-write-probe-" + std::to_string(::getpid()));
  const bool writable = std::ofstream(probe).good();
  std::filesystem::remove(probe, ec);
  if (!writable) throw UsageError(option + " " + out + ": cannot create files in directory " + dir.string());
}

double checked_budget(double compression) {
  if (!(compression > 0 && compression <= 1))
    throw UsageError("--compression: each budget must be in (0, 1], got " + std::to_string(compression));
  return compression;
}

void add_repetitions_option(CLI::App& command, std::optional<int>& repetitions) {
  command.add_option("--repetitions", repetitions,
                     "Repetitions of every case, 1 to " + std::to_string(kMaxRepetitions) +
                         " (overrides the suite; more make the medians and claim intervals steadier on a noisy machine)");
}

void apply_repetitions(const std::optional<int>& repetitions, Suite& suite) {
  if (!repetitions) return;
  if (*repetitions < 1 || *repetitions > kMaxRepetitions) {
    throw UsageError("--repetitions: must be a whole number from 1 to " + std::to_string(kMaxRepetitions) + ", got " +
                     std::to_string(*repetitions));
  }
  suite.repetitions = *repetitions;
}

std::string known_formats() {
  std::string known;
  for (const std::string& n : format_names()) known += (known.empty() ? "" : ", ") + n;
  return known;
}

std::unique_ptr<ReportFormat> checked_format(const std::string& name) {
  if (auto format = make_format(name)) return format;
  throw UsageError("--format: unknown format \"" + name + "\" (known: " + known_formats() + ")");
}

namespace {

/// A single updating progress line, only on a terminal (a log file would collect hundreds of lines).
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  ~ProgressLine() { clear(); }
  void update(int done, int total, const std::string& label) {
    if (!enabled_) return;
    std::string text = "[";  // appended piecewise: see report_writer.cpp on GCC 12's -Wrestrict
    text += std::to_string(done);
    text += "/";
    text += std::to_string(total);
    text += "] ";
    text += terminal_safe(label, kMaxMessageBytes);  // case labels carry net names from the suite file
    const std::size_t shown = text.size();
    if (text.size() < width_) text.append(width_ - text.size(), ' ');
    width_ = shown;
    std::cerr << '\r' << text << std::flush;
  }
  void clear() {
    if (!enabled_ || width_ == 0) return;
    std::cerr << '\r' << std::string(width_, ' ') << '\r' << std::flush;
    width_ = 0;
  }

 private:
  bool enabled_;
  std::size_t width_ = 0;
};

/// One warning line per diverged repetition: case, step, reason.
void warn_diverged(const RunResult& result) {
  for (const CaseResult& c : result.cases) {
    for (const RepetitionResult& r : c.repetitions) {
      if (r.status == "ok") continue;
      std::string message = "case " + c.label + " " + r.status + " in repetition " + std::to_string(r.repetition);
      if (r.diverged_step) message += " at step " + std::to_string(*r.diverged_step);
      if (!r.diverged_reason.empty()) message += " (" + r.diverged_reason + ")";
      print_warning(message + "; left out of the tables");
    }
  }
}

/// A warning per repetition during which the machine stalled.
void warn_stalls(const RunResult& result) {
  for (const Stall& s : stalled_repetitions(result)) {
    print_warning("case " + s.label + " repetition " + std::to_string(s.repetition) + ": mean step " +
                  fixed(s.mean_over_median, 1) + "x its median, the machine stalled for about " + fixed(s.lost_s, 1) +
                  " s; the case's median over repetitions keeps one such repetition out");
  }
}

}  // namespace

RunResult run_on_console(const Suite& suite, bool quiet) {
  const Context context = gather_context();
  print_warnings(context, std::cerr);
  RunResult result;
  {
    ProgressLine line(!quiet && ::isatty(STDERR_FILENO) == 1);  // cleared before anything else is printed
    RunOptions options;
    options.progress = [&line](int done, int total, const std::string& label) { line.update(done, total, label); };
    result = run_suite(suite, context, options);
  }
  if (!quiet) print_console_report(result, std::cerr);
  warn_diverged(result);
  warn_stalls(result);
  return result;
}

int write_report(const std::string& text, const std::string& out) {
  if (out.empty()) {
    std::cout << text << std::flush;
    return kExitOk;
  }
  try {
    write_file_atomically(out, text);
  } catch (const std::exception& e) {
    // The run is done and may have taken hours: do not lose it because a disk filled up meanwhile.
    print_error(std::string(e.what()) + "; writing the report to stdout instead");
    std::cout << text << std::flush;
    return kExitInternal;
  }
  return kExitOk;
}

std::filesystem::path resolve_data_file(const std::string& argument) {
  const std::filesystem::path given(argument);
  std::error_code ec;
  if (std::filesystem::exists(given, ec) || given.is_absolute()) return given;
  const std::filesystem::path in_tree = std::filesystem::path(TCSB_SOURCE_DIR) / given;
  return std::filesystem::exists(in_tree, ec) ? in_tree : given;
}

}  // namespace tcsb::cli
