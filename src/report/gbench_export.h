// Google Benchmark's JSON output format, so Google Benchmark's own tools — tools/compare.py, shipped by Debian's
// libbenchmark-tools as /usr/share/benchmark/compare.py — can compare two tcsb runs:
//   compare.py benchmarks BASE.gbench.json NEW.gbench.json
// One "iteration" entry per ok repetition, named after its case ("n33/tcsb@0.3"), with real_time = cpu_time = the
// repetition's mean step time in microseconds (time_unit "us": compare.py prints times without decimals, and steps
// are often below a millisecond; tcsb measures wall time only), iterations = timed steps, and counters N, L, I;
// then the _mean, _median, _stddev and _cv aggregates Google Benchmark writes for --benchmark_repetitions, read off
// the run's own summary of the case (step_ms), with the counters, the case's means, on _mean alone.
// Diverged repetitions are left out: Google Benchmark has no null time, and a NaN would break the tools.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "report/report_format.h"
#include "result/result_view.h"

namespace tcsb {

/// The run as a Google Benchmark JSON document (context, benchmarks).
nlohmann::ordered_json gbench_json(const ResultView& result);

/// The "gbench" format.
class GbenchFormat final : public ReportFormat {
 public:
  /// "gbench".
  std::string name() const override { return "gbench"; }
  /// gbench_json() of a result file, indented by 2.
  std::string render_native(const nlohmann::ordered_json& native) const override;
};

}  // namespace tcsb
