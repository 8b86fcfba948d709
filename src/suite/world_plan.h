// World plan: what the world pass of a scene of many bodies (world/world_runner.h) will run, known from the suite
// alone — the budgets its methods run at and how many tracks (each method's bodies in a world of their own) it holds
// — so the runner builds them and the memory estimate counts them from one rule.
#pragma once

#include <vector>

#include "suite/suite.h"

namespace tcsb {

/// Steps per block of the world pass's round-robin, as in the fidelity pass (fidelity_runner.cpp): a body's
/// cache-cold first step after the other methods ran is 1 in 20, and machine drift hits every method alike. The
/// reference's surfaces are kept a block at a time.
constexpr int kWorldBlockSteps = 20;

/// The budgets every method but full resolution runs at: the suite's targets below 1 in the suite's order; with
/// fidelity.curves, those and the curve budgets, ascending.
std::vector<double> world_budgets(const Suite& suite);

/// The world pass's tracks by the kind of body they hold, all alive at once: TC-SB (tcsb_world with a world budget,
/// tcsb_body, at every budget) and plain (full resolution, discrete LOD's grids at every budget, and with curves the
/// noise floor and full resolution at each divisor). Zero of both for a suite that is not a world suite.
struct WorldTracks {
  int tcsb = 0;
  int plain = 0;
};
WorldTracks world_tracks(const Suite& suite);

/// What discrete LOD switches on (fidelity/discrete_lod.h), step-major over the first `steps` steps: the camera's
/// distance to each body's placed position (scene_body_nets) at the end of the step, which a game knows in advance from
/// its camera's path. With feedback.view_lookahead_s the game anticipates for its LOD as TC-SB's view terms do, and a
/// body's distance is the nearer of the camera's now and that many seconds later: both methods see the same future.
std::vector<double> lod_camera_distances(const Suite& suite, int steps);

}  // namespace tcsb
