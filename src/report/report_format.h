// ReportFormat: the one interface every output format implements (as Google Benchmark's reporters do), so the CLI
// picks a format by name (report/format_registry.h) and each format lives in its own file.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace tcsb {

struct RunResult;
struct RunTables;

/// Renders a finished run as the text of one output format.
class ReportFormat {
 public:
  virtual ~ReportFormat() = default;
  /// The name users pass to --format, e.g. "json".
  virtual std::string name() const = 0;
  /// The complete output (what goes to stdout or the --out file), newline-terminated, of a run and its tables
  /// (run_tables): render_native() of the run's
  /// native document, so each format is written once and `tcsb run --format` and `tcsb export` agree by
  /// construction.
  std::string render(const RunResult& result, const RunTables& tables) const;
  /// The same output from a finished run's native JSON document (a result file, as `tcsb export` reads it); the
  /// document has been checked against the result schema.
  virtual std::string render_native(const nlohmann::ordered_json& native) const = 0;
};

}  // namespace tcsb
