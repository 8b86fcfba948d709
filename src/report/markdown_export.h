// The "markdown" format: one run as a section of docs/results.md — a heading naming the suite, a Source: line (command,
// date, commit, CPU, load, wall time, all from the document), then Table 2 (beside the paper's when the run was a
// reproduction), Table 1, the scaling fits, the fidelity summary and the claims, each only when the document has
// it. scripts/render-results.sh concatenates one such section per file in results/runs/.
//
// The renderer reads the generic JSON document rather than a typed view so that a block it does not know yet, or a
// claim with fields added or missing, is rendered as far as it goes instead of refused: a missing value is an
// empty cell. Numbers are printed with a fixed number of significant digits, so the same file always gives the same
// bytes (docs/results.md is checked against a fresh rendering).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "report/markdown_table.h"
#include "report/report_format.h"

namespace tcsb {

/// One run as Markdown (see the file comment), newline-terminated, with no blank line at the end.
std::string markdown_report(const nlohmann::ordered_json& native);

/// The "markdown" format.
class MarkdownFormat final : public ReportFormat {
 public:
  /// "markdown".
  std::string name() const override { return "markdown"; }
  /// markdown_report() of a result file.
  std::string render_native(const nlohmann::ordered_json& native) const override;
};

}  // namespace tcsb
