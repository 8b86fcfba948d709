// The speed-up at equal error (the result's fidelity.equal_error, paper/equal_error_table.h, and world.equal_error) as
// Markdown: a run's own sections for its full render, and the headline page's row and verdict
// (scripts/render-results.sh), each read from the generic JSON document as the markdown format reads it
// (report/markdown_export.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "report/report_format.h"

namespace tcsb {

/// The speed-up at equal error of every net of a run, its curves and rows; empty when the run drew no curves.
std::string equal_error_section(const nlohmann::ordered_json& doc);

/// The world pass's speed-up at equal error and its world-against-per-body table (the result's world.equal_error,
/// paper/world_equal_error.h); empty when the pass drew no curves.
std::string world_equal_error_section(const nlohmann::ordered_json& doc);

/// The speed-up the headline page asks of a scene against the best uniform grid (Koh et al.'s figure for view
/// dependence, 2x and more).
inline constexpr double kHeadlineSpeedup = 2.0;

/// The "markdown-headline" format: one row of the headline table "where TC-SB pays" (its largest net, TC-SB at
/// 30 % and its best budget), without the last cell (the page adds the link to the kept run).
class HeadlineRowFormat final : public ReportFormat {
 public:
  std::string name() const override { return "markdown-headline"; }
  std::string render_native(const nlohmann::ordered_json& native) const override;
};

/// The "markdown-verdict" format: one line saying whether the scene reaches kHeadlineSpeedup against the best
/// uniform grid at any budget, and by how much it falls short where it does not.
class HeadlineVerdictFormat final : public ReportFormat {
 public:
  std::string name() const override { return "markdown-verdict"; }
  std::string render_native(const nlohmann::ordered_json& native) const override;
};

}  // namespace tcsb
