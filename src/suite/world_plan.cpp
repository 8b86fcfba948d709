#include "suite/world_plan.h"

#include <algorithm>

#include "suite/scene_bodies.h"

namespace tcsb {

std::vector<double> world_budgets(const Suite& suite) {
  std::vector<double> budgets;
  for (const double c : suite.compression)
    if (c < 1.0) budgets.push_back(c);
  if (!suite.fidelity.curves) return budgets;
  budgets.insert(budgets.end(), suite.fidelity.curves->budgets.begin(), suite.fidelity.curves->budgets.end());
  std::sort(budgets.begin(), budgets.end());
  budgets.erase(std::unique(budgets.begin(), budgets.end()), budgets.end());
  return budgets;
}

WorldTracks world_tracks(const Suite& suite) {
  if (!is_world_suite(suite)) return {};
  const int budgets = static_cast<int>(world_budgets(suite).size());
  WorldTracks t;
  t.tcsb = budgets * (suite.feedback.budget_scope == BudgetScope::kWorld ? 2 : 1);
  t.plain = 1 + budgets;
  if (suite.fidelity.curves) t.plain += 1 + static_cast<int>(suite.fidelity.curves->solver_divisors.size());
  return t;
}

}  // namespace tcsb
