// The two custom formats of github-action-benchmark (benchmark-action/github-action-benchmark), which draws charts
// of a metric across commits and can alert on a change. Each is a JSON array of {name, unit, value, extra}, read off
// what the run computed once for each case (step_ms, ratio_vs_plain), so they show the numbers every format shows:
//   github-action-smaller  tool "customSmallerIsBetter": each case's step time (median over repetitions, ms), with
//                          its standard deviation as the range
//   github-action-bigger   tool "customBiggerIsBetter": each TC-SB case's speed-up over plain of the same net
//                          (plain / TC-SB step time: the reciprocal of the median ratio over repetitions paired in
//                          the same run; "x")
// The speed-ups are the machine-independent numbers to chart on shared runners; the step times are for dedicated
// ones. Cases without a number (every repetition diverged) are left out: the action needs a number.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "report/report_format.h"
#include "result/result_view.h"

namespace tcsb {

/// customSmallerIsBetter entries: "<case> step time" in ms.
nlohmann::ordered_json github_action_step_times(const ResultView& result);

/// customBiggerIsBetter entries: "<tcsb case> speed-up vs plain" in x.
nlohmann::ordered_json github_action_speedups(const ResultView& result);

/// The "github-action-smaller" format.
class GithubActionSmallerFormat final : public ReportFormat {
 public:
  /// "github-action-smaller".
  std::string name() const override { return "github-action-smaller"; }
  /// github_action_step_times() of a result file.
  std::string render_native(const nlohmann::ordered_json& native) const override;
};

/// The "github-action-bigger" format.
class GithubActionBiggerFormat final : public ReportFormat {
 public:
  /// "github-action-bigger".
  std::string name() const override { return "github-action-bigger"; }
  /// github_action_speedups() of a result file.
  std::string render_native(const nlohmann::ordered_json& native) const override;
};

}  // namespace tcsb
