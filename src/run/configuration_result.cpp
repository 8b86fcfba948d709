#include "run/configuration_result.h"

#include "suite/suite_axes.h"

namespace tcsb {

RunResult configuration_result(const RunResult& result, std::size_t configuration) {
  if (result.suite.configurations.empty()) return result;
  RunResult view;
  view.suite = configuration_suite(result.suite, configuration);
  view.context = result.context;
  for (const CaseResult& c : result.cases)
    if (c.key.configuration == configuration) view.cases.push_back(c);
  view.fidelity = result.fidelity;  // none: a suite with axes has no fidelity pass (suite.cpp)
  view.wall_s = result.wall_s;
  view.shard = result.shard;
  return view;
}

}  // namespace tcsb
