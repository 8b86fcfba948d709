#include "report/github_action_export.h"

#include <cmath>
#include <cstdio>

#include "analysis/statistics.h"
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
    const std::vector<double> times = ok_step_times(c);
    if (times.empty()) continue;
    const Summary s = summarize(times);
    out.push_back({{"name", c.label + " step time"},
                   {"unit", "ms"},
                   {"value", json_number(s.median)},
                   {"range", "± " + formatted("%.3g", s.stddev)},
                   {"extra", "median of " + std::to_string(s.count) + " repetitions' mean step times (CV " +
                                 formatted("%.1f", 100.0 * s.cv) + " %); " + counts(c)}});
  }
  return out;
}

ojson github_action_speedups(const ResultView& result) {
  ojson out = ojson::array();
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseView& c = result.cases[i];
    const auto plain = plain_case_of(result, i);
    if (c.method != "tcsb" || !plain) continue;
    // plain / TC-SB per repetition: the reciprocal of the paired ratio, so that bigger is better.
    std::vector<double> speedups;
    for (const double ratio : paired_step_ratios(result, i, *plain)) {
      // A ratio can be finite and its reciprocal not (1e308 ms against 0.5 ms): such a pair has no speed-up to
      // show, and summarising an infinity would be an internal error instead of a page.
      const double speedup = 1.0 / ratio;
      if (ratio > 0.0 && std::isfinite(speedup)) speedups.push_back(speedup);
    }
    if (speedups.empty()) continue;
    const Summary s = summarize(speedups);
    const CaseView& p = result.cases[*plain];
    std::string extra = "plain / TC-SB step time, paired by repetition in the same run, median of " +
                        std::to_string(s.count) + "; " + counts(c);
    if (c.mean_nodes && p.mean_nodes && *p.mean_nodes > 0) {
      extra += "; N/plain " + formatted("%.3f", *c.mean_nodes / *p.mean_nodes);
    }
    out.push_back({{"name", c.label + " speed-up vs plain"},
                   {"unit", "x"},
                   {"value", json_number(s.median)},
                   {"range", "± " + formatted("%.3g", s.stddev)},
                   {"extra", std::move(extra)}});
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
