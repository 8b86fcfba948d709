#include "cli/cli_common.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "base/atomic_file.h"
#include "base/terminal_text.h"
#include "run/context.h"
#include "run/out_of_memory.h"
#include "suite/suite.h"

namespace tcsb::cli {

std::filesystem::path suites_dir() {
  if (const char* env = std::getenv("TCSB_SUITES_DIR"); env != nullptr && *env != '\0') return env;
  return std::filesystem::path(TCSB_SOURCE_DIR) / "suites";
}

std::vector<std::string> bundled_suite_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(suites_dir(), ec)) {
    if (entry.path().extension() == ".json" && entry.is_regular_file(ec)) names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::filesystem::path resolve_suite(const std::string& argument) {
  if (argument.empty()) throw UsageError("SUITE must not be empty");
  const std::filesystem::path path(argument);
  std::error_code ec;
  // Exists, or cannot be looked at for a reason other than absence (a symlink loop): parse_suite says which.
  if (std::filesystem::status(path, ec).type() != std::filesystem::file_type::not_found) return path;
  // Only a bare word is looked up among the bundled suites: "out/paper" or "paper.json" mean files.
  const bool bare_name = !path.has_parent_path() && path.extension().empty();
  if (!bare_name) return path;  // parse_suite reports the missing file by name
  const std::filesystem::path bundled = suites_dir() / (argument + ".json");
  if (std::filesystem::is_regular_file(bundled, ec)) return bundled;
  std::string known;
  for (const std::string& name : bundled_suite_names()) known += (known.empty() ? "" : ", ") + name;
  throw InputError(argument, "",
                   "no such file, and not a bundled suite (bundled: " +
                       (known.empty() ? "none in " + suites_dir().string() : known) + ")");
}

void refuse_axes(const Suite& suite, const std::string& command) {
  if (suite.axes.empty()) return;
  throw InputError(suite.path.string(), "axes",
                   "`tcsb " + command + "` runs one set of settings; run a suite with axes with `tcsb run`");
}

std::string one_line(std::string_view text) {
  std::string line(text);
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::replace(line.begin(), line.end(), '\r', ' ');
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return terminal_safe(line, kMaxMessageBytes);
}

void print_error(std::string_view message) { std::cerr << "tcsb: error: " << one_line(message) << std::endl; }

void print_warning(std::string_view message) { std::cerr << "tcsb: warning: " << one_line(message) << std::endl; }

int guarded(const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& e) {
    print_error(e.what());
    return kExitUsage;
  } catch (const UsageError& e) {
    print_error(e.what());
    return kExitUsage;
  } catch (const WriteError& e) {
    // Not a bug: the machine refused the output (a full disk, a closed pipe). Said plainly, without "internal".
    print_error(e.what());
    return kExitInternal;
  } catch (const OutOfMemoryError& e) {
    print_error(e.what());
    return kExitUsage;
  } catch (const std::bad_alloc&) {  // outside a run (the runner names the case: run/out_of_memory.h)
    print_error(out_of_memory_message("tcsb"));
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "tcsb: internal error: " << one_line(e.what()) << std::endl;
    return kExitInternal;
  }
}

int parse_error_exit(CLI::App& app, const CLI::ParseError& error) {
  // --help (and --help-all) arrive as "errors" with exit code 0: let CLI11 print the help to stdout.
  if (error.get_exit_code() == 0) return app.exit(error);
  print_error(error.what());
  return kExitUsage;
}

std::string version_line() {
  const Context c = gather_context();
  return "tcsb " + c.tcsb_version + " (commit " + c.git_commit + ", Bullet " + c.bullet_version + " " +
         c.bullet_precision + ")";
}

}  // namespace tcsb::cli
