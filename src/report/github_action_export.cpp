#include "report/github_action_export.h"

#include <cmath>
#include <cstdio>

#include "report/json_report.h"
#include "report/text_table.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

std::string counts(const CaseView& c) {
  std::string out;
  if (c.mean_nodes) out += "N " + formatted("%.0f", *c.mean_nodes);
  if (c.mean_links) out += ", L " + formatted("%.0f", *c.mean_links);
  if (c.mean_interpolations) out += ", I " + formatted("%.2f", *c.mean_interpolations);
  return out;
}

}  // namespace

ojson github_action_step_times(const ResultView& result) {
  ojson out = ojson::array();
  for (const CaseView& c : result.cases) {
    if (c.step_ms_count == 0 || !c.median_step_ms) continue;  // no ok repetition
    // The run's own summary of the case (step_ms), not one of the export's: every format shows the same numbers.
    out.push_back({{"name", c.label + " step time"},
                   {"unit", "ms"},
                   {"value", json_number(*c.median_step_ms)},
                   {"range", "± " + formatted("%.3g", c.stddev_step_ms.value_or(0.0))},
                   {"extra", "median of " + std::to_string(c.step_ms_count) + " repetitions' mean step times (CV " +
                                 formatted("%.1f", 100.0 * c.cv_step_ms.value_or(0.0)) + " %); " + counts(c)}});
  }
  return out;
}

ojson github_action_speedups(const ResultView& result) {
  ojson out = ojson::array();
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseView& c = result.cases[i];
    const auto plain = plain_case_of(result, i);
    if (c.method != "tcsb" || !plain || !c.ratio_vs_plain || !(*c.ratio_vs_plain > 0.0)) continue;
    // plain / TC-SB: the reciprocal of the run's paired ratio (ratio_vs_plain), so that bigger is better. A ratio can
    // be finite and its reciprocal not (1e308 ms against 0.5 ms): such a case has no speed-up to show.
    const double speedup = 1.0 / *c.ratio_vs_plain;
    if (!std::isfinite(speedup)) continue;
    const CaseView& p = result.cases[*plain];
    std::string extra = "plain / TC-SB step time, the reciprocal of the median ratio over repetitions paired in the "
                        "same run; " +
                        counts(c);
    if (c.mean_nodes && p.mean_nodes && *p.mean_nodes > 0) {
      extra += "; N/plain " + formatted("%.3f", *c.mean_nodes / *p.mean_nodes);
    }
    out.push_back(
        {{"name", c.label + " speed-up vs plain"}, {"unit", "x"}, {"value", json_number(speedup)}, {"extra", extra}});
  }
  return out;
}

std::string GithubActionSmallerFormat::render_native(const nlohmann::ordered_json& native) const {
  return json_text(github_action_step_times(read_result(native, "result")));
}

std::string GithubActionBiggerFormat::render_native(const nlohmann::ordered_json& native) const {
  return json_text(github_action_speedups(read_result(native, "result")));
}

}  // namespace tcsb
