// The world pass: a scene of many bodies (the suite's scene.bodies) simulated by each method a game could pick, every
// method's bodies in one SceneWorld of its own, the methods stepped in turn in blocks of steps as the fidelity pass
// steps its subjects, so time ratios are of the same moments of the machine:
//   full_resolution  every body plain at full resolution; also the reference the others are measured against, and
//                    the denominator of every time ratio (its own steps)
//   tcsb_world       TC-SB bodies sharing one node budget (feedback/world_budget.h), re-split every step; run when
//                    feedback.budget_scope is "world"
//   tcsb_body        TC-SB bodies, each holding the budget's fraction of its own nodes
//   discrete_lod     per body a few uniform grids (the net, then about a quarter of the nodes each level), switched
//                    at distance thresholds fitted so the run's mean node count is the largest within the budget
//                    (fidelity/discrete_lod.h), the state resampled onto the new grid at each switch
// at each of the suite's compression targets below 1, a fraction of the scene's nodes. With fidelity.curves, the
// curves the speed-up at equal error is read from (paper/world_equal_error.h): those three methods at every curve
// budget too, full resolution at the suite's passes divided by each divisor, and noise_floor, the reference started
// perturbed as the fidelity pass's noise floor is (fidelity/fidelity_floors.h). Errors are pixels on the camera's
// image over every reference point it sees (with occlusion, any body may hide another).
#pragma once

#include "suite/suite.h"
#include "world/world_observer.h"
#include "world/world_result.h"

namespace tcsb {

/// Runs the world pass of `suite` (is_world_suite). Deterministic but for the times. An `observer` sees every method's
/// scene after each step it wants (world_observer.h), and the initial state as after 0 steps.
WorldResult run_world(const Suite& suite, WorldObserver* observer = nullptr);

}  // namespace tcsb
