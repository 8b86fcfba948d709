#include "suite/fidelity_plan.h"

#include <algorithm>
#include <cmath>

#include "net/net_pins.h"

namespace tcsb {

std::vector<FidelitySubjectSpec> fidelity_plan(const Suite& suite) {
  std::vector<FidelitySubjectSpec> plan;
  const bool has_tcsb = std::find(suite.methods.begin(), suite.methods.end(), Method::kTcsb) != suite.methods.end();
  if (!suite.fidelity.enabled || !has_tcsb) return plan;
  std::vector<double> targets = suite.compression;
  targets.insert(targets.end(), suite.fidelity.pareto_targets.begin(), suite.fidelity.pareto_targets.end());
  if (suite.fidelity.curves)
    targets.insert(targets.end(), suite.fidelity.curves->budgets.begin(), suite.fidelity.curves->budgets.end());
  std::sort(targets.begin(), targets.end());
  targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
  for (const double c : targets) plan.push_back(fidelity_subject("tcsb", c));
  const auto add_at_targets = [&](std::string_view m) {
    for (const double c : suite.compression)
      if (c < 1.0) plan.push_back(fidelity_subject(m, c));
  };
  if (suite.fidelity.ablations)
    for (const std::string_view m : {"uniform_grid", "switch_body", "tcsb_random", "tcsb_rigid", "tcsb_no_geomorph"})
      add_at_targets(m);
  if (suite.calibration) {
    // Calibrated TC-SB at every target below 1 of the sweep too, so its maximal compression can be reported (at 1
    // it would be the uncalibrated full-resolution body); its rival, the calibrated grid, at the suite's targets.
    for (const double c : targets)
      if (c < 1.0) plan.push_back(fidelity_subject("tcsb_calibrated", c));
    add_at_targets("uniform_grid_calibrated");
    if (suite.fidelity.ablations && suite.tcsb.interfaces == Interfaces::kHanging)
      add_at_targets("tcsb_calibrated_fans");
  }
  if (suite.feedback.view) {
    add_at_targets("tcsb_motion_only");
    if (suite.calibration) add_at_targets("tcsb_calibrated_motion_only");
  }
  if (suite.solver.compliant_model()) {
    // One material, no calibration: the uniform grid of the same material is TC-SB's rival at every target; and
    // stock Bullet at the suite's iterations, measured against the same converged cloth.
    if (!suite.fidelity.ablations) add_at_targets("uniform_grid");
    plan.push_back(fidelity_subject("stock_bullet", 1.0));
  }
  if (const std::optional<FidelityCurves>& curves = suite.fidelity.curves) {
    const auto planned = [&](std::string_view m, double c) {
      return std::any_of(plan.begin(), plan.end(),
                         [&](const FidelitySubjectSpec& p) { return p.method == m && p.body.compression == c; });
    };
    std::vector<double> grid_budgets = curves->budgets;
    for (const double c : suite.compression)
      if (c < 1.0) grid_budgets.push_back(c);
    std::sort(grid_budgets.begin(), grid_budgets.end());
    for (const double c : grid_budgets)
      if (!planned("uniform_grid", c)) plan.push_back(fidelity_subject("uniform_grid", c));
    if (suite.solver.compliant_model()) plan.push_back(fidelity_subject("full_resolution", 1.0, 1));
    for (const int d : curves->solver_divisors) plan.push_back(fidelity_subject("full_resolution", 1.0, d));
  }
  return plan;
}

CoarseGrid coarse_grid_for(int width, int height, int nodes) {
  const double n = std::max(4, nodes);
  CoarseGrid g;
  g.width = std::clamp(static_cast<int>(std::lround(std::sqrt(n * width / height))), 2, width);
  g.height = std::clamp(static_cast<int>(std::lround(n / g.width)), 2, height);
  return g;
}

NetSpec coarse_net_spec(const NetSpec& fine, int budget) {
  const CoarseGrid g = coarse_grid_for(fine.width, fine.height, budget);
  NetSpec coarse = fine;
  coarse.name = fine.name + "/coarse";
  coarse.width = g.width;
  coarse.height = g.height;
  if (fine.mass_mode != MassMode::kDensity) {  // (a density is the same cloth at any resolution already)
    coarse.mass_mode = MassMode::kTotal;       // the same cloth: the total mass is kept, not the mass per node
    coarse.mass = fine.node_mass() * static_cast<double>(fine.node_count());
  }
  return with_pins_of(fine, coarse);
}

}  // namespace tcsb
