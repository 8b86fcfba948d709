#include "cli/run_support.h"

#include <CLI/CLI.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include <iostream>
#include <utility>

#include "base/atomic_file.h"
#include "base/terminal_text.h"
#include "cli/cli_common.h"
#include "report/console_report.h"
#include "report/format_registry.h"
#include "report/text_table.h"
#include "run/context.h"
#include "run/runner.h"
#include "run/stall.h"
#include "suite/calibration_path.h"
#include "sweep/shard_plan.h"

namespace tcsb::cli {

void check_out_path(const std::string& out, const std::string& option) {
  if (out.empty()) return;
  if (const std::string problem = output_problem(out); !problem.empty()) {
    throw UsageError(option + " " + out + ": " + problem);
  }
}

void check_out_is_not_input(const std::string& out, const std::filesystem::path& input, const std::string& option) {
  if (out.empty() || input.empty()) return;
  struct stat out_st {
  }, in_st{};
  bool same = false;
  if (::stat(out.c_str(), &out_st) == 0 && ::stat(input.c_str(), &in_st) == 0) {
    // Both exist: the same file however it is spelled (a symlink, "./", a hard link).
    same = out_st.st_dev == in_st.st_dev && out_st.st_ino == in_st.st_ino;
  } else {
    std::error_code ec1, ec2;
    const std::filesystem::path a = std::filesystem::weakly_canonical(out, ec1);
    const std::filesystem::path b = std::filesystem::weakly_canonical(input, ec2);
    same = !ec1 && !ec2 && a == b;
  }
  if (same) {
    throw UsageError(option + " " + out + ": is the input file " + input.string() +
                     " (writing it would replace what is being read); choose another file");
  }
}

void check_out_is_not_suite_input(const std::string& out, const Suite& suite, const std::string& option) {
  check_out_is_not_input(out, suite.path, option);
  if (!suite.fidelity.calibration_path.empty())
    check_out_is_not_input(out, calibration_file_path(suite.path, suite.fidelity.calibration_path), option);
}

double checked_budget(double compression) {
  if (!(compression > 0 && compression <= 1))
    throw UsageError("--compression: each budget must be in (0, 1], got " + std::to_string(compression));
  return compression;
}

void add_repetitions_option(CLI::App& command, std::optional<int>& repetitions) {
  command.add_option(
      "--repetitions", repetitions,
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
    std::string text = "[";  // appended piecewise: GCC 12 misreports "literal" + string chains (-Wrestrict)
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

/// One warning line per diverged repetition numbered `from` or later: case, step, reason.
void warn_diverged(const RunResult& result, int from) {
  for (const CaseResult& c : result.cases) {
    for (const RepetitionResult& r : c.repetitions) {
      if (r.status == "ok" || r.repetition < from) continue;
      std::string message = "case " + c.label + " " + r.status + " in repetition " + std::to_string(r.repetition);
      if (r.diverged_step) message += " at step " + std::to_string(*r.diverged_step);
      if (!r.diverged_reason.empty()) message += " (" + r.diverged_reason + ")";
      print_warning(message + "; left out of the tables");
    }
  }
}

/// A warning per repetition numbered `from` or later during which the machine stalled.
void warn_stalls(const RunResult& result, int from) {
  for (const Stall& s : stalled_repetitions(result)) {
    if (s.repetition < from) continue;
    print_warning("case " + s.label + " repetition " + std::to_string(s.repetition) + ": mean step " +
                  fixed(s.mean_over_median, 1) + "x its median, the machine stalled for about " + fixed(s.lost_s, 1) +
                  " s" +
                  (result.suite.repetitions >= 3 ? "; the case's median over repetitions keeps one such repetition out"
                                                 : "; with fewer than 3 repetitions it is in the case's figures"));
  }
}

}  // namespace

FinishedRun run_on_console(const Suite& suite, bool quiet, const std::optional<ShardIndex>& shard, Measure measure) {
  const Context context = gather_context();
  print_warnings(context, std::cerr);
  RunResult result;
  {
    ProgressLine line(!quiet && ::isatty(STDERR_FILENO) == 1);  // cleared before anything else is printed
    RunOptions options;
    options.measure = measure;
    options.progress = [&line](int done, int total, const std::string& label) { line.update(done, total, label); };
    result = run_suite(suite, context, options);
    result.shard = shard;
  }
  RunTables tables = run_tables(result);
  if (!quiet) print_console_report(result, tables, std::cerr);
  warn_repetitions(result, 0);
  return {std::move(result), std::move(tables)};
}

void warn_repetitions(const RunResult& result, int from) {
  warn_diverged(result, from);
  warn_stalls(result, from);
}

int write_report(const std::string& text, const std::string& out) {
  if (out.empty()) {
    std::cout << text << std::flush;  // a failure is main's to report (cli/standard_streams.h): exit 3
    return kExitOk;
  }
  try {
    write_file_atomically(out, text);
  } catch (const std::exception& e) {
    // The run is done and may have taken hours: do not lose it because a disk filled up meanwhile.
    print_error(std::string(e.what()) + "; writing the report to stdout instead");
    std::cout << text << std::flush;  // main checks that stdout took it
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
