#include "run/configuration_result.h"

#include "suite/suite_axes.h"

namespace tcsb {

RunResult configuration_result(const RunResult& result, std::size_t configuration) {
  if (result.suite.configurations.empty()) return result;
  RunResult view;
  view.suite = configuration_suite(result.suite, configuration);
  view.context = result.context;
  for (const std::size_t i : configuration_cases(result, configuration)) view.cases.push_back(result.cases[i]);
  view.fidelity = result.fidelity;  // none: a suite with axes has no fidelity pass (suite.cpp)
  view.wall_s = result.wall_s;
  view.shard = result.shard;
  return view;
}

std::vector<std::size_t> configuration_cases(const RunResult& result, std::size_t configuration) {
  std::vector<std::size_t> cases;
  const bool axes = !result.suite.configurations.empty();
  for (std::size_t i = 0; i < result.cases.size(); ++i)
    if (!axes || result.cases[i].key.configuration == configuration) cases.push_back(i);
  return cases;
}

}  // namespace tcsb
