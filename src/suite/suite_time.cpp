#include "suite/suite_time.h"

#include <algorithm>

#include "suite/case_plan.h"
#include "suite/suite_axes.h"

namespace tcsb {

double estimate_wall_seconds(const Suite& suite) {
  const std::vector<Suite> configurations = configuration_suites(suite);
  double seconds = 0;
  for (const CaseKey& key : expand_cases(suite)) {
    if (!runs_unit(suite, key.configuration, key.net)) continue;
    const Suite& s = configurations[key.configuration];
    const double nodes = static_cast<double>(s.nets[key.net].node_count()) * key.compression.value_or(1.0);
    const double steps = static_cast<double>(steps_per_repetition(s));
    const int iterations = s.solver.piterations + s.solver.viterations + s.solver.diterations;
    seconds += nodes * steps * kNodeStepSeconds * std::max(1, iterations) / 2.0;
  }
  return seconds * suite.repetitions;
}

}  // namespace tcsb
