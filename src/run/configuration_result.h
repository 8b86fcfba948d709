// One configuration's share of a run: the run of a suite with axes (suite/suite_axes.h) holds the cases of every
// configuration; its tables, fits and ratios are computed per configuration, never across them (a mean over
// configurations would mix settings). This view is the run the configuration would have been alone.
#pragma once

#include <cstddef>
#include <vector>

#include "run/run_result.h"

namespace tcsb {

/// The run of one configuration: its settings as the suite (configuration_suite), its cases in run order (labels
/// and keys as in the whole run), the whole run's context, wall time and shard. Without axes (configuration 0), a
/// copy of the run.
RunResult configuration_result(const RunResult& result, std::size_t configuration);

/// The indices of the run's cases that configuration_result(result, configuration) holds, in run order (every case
/// without axes).
std::vector<std::size_t> configuration_cases(const RunResult& result, std::size_t configuration);

}  // namespace tcsb
