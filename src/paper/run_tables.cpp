#include "paper/run_tables.h"

#include <utility>

#include "run/configuration_result.h"

namespace tcsb {
namespace {

TableSet table_set(const RunResult& run, std::vector<std::size_t> cases) {
  TableSet t;
  t.cases = std::move(cases);
  t.table1 = table1(run);
  t.table2 = table2(run);
  t.step_fits = step_ms_vs_nodes(run);
  t.op_fits = op_ms_vs_nodes(run);
  return t;
}

}  // namespace

RunTables run_tables(const RunResult& result) {
  RunTables t;
  t.case_ratios.reserve(result.cases.size());
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    CaseRatios r;
    if (const auto plain = plain_case_for(result, i)) r.vs_plain = paired_ratio(result, i, *plain);
    if (const auto equal = equal_plain_case_for(result, i)) {
      r.has_equal_plain = true;
      r.vs_equal_plain = paired_ratio(result, i, *equal);
    }
    t.case_ratios.push_back(r);
  }
  if (result.suite.configurations.empty()) {
    t.whole = table_set(result, configuration_cases(result, 0));
  } else {
    for (std::size_t c = 0; c < result.suite.configurations.size(); ++c)
      t.configurations.push_back(table_set(configuration_result(result, c), configuration_cases(result, c)));
  }
  if (result.fidelity) t.fidelity = fidelity_tables(*result.fidelity);
  if (result.world) t.world_equal_error = world_equal_error(*result.world);
  return t;
}

}  // namespace tcsb
