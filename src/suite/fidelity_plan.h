// Fidelity plan: which bodies the fidelity pass runs beside the full-resolution reference, per net. TC-SB at each of
// the suite's compression targets and Pareto targets, and — when the suite asks for ablations — four other ways to
// spend the same node budget, and TC-SB with its surface switched instead of geomorphed, each at the budget of the
// TC-SB case it is compared with.
#pragma once

#include <string>
#include <vector>

#include "suite/fidelity_variant.h"
#include "suite/suite.h"

namespace tcsb {

/// The subjects, in report order: TC-SB at every target of compression and fidelity.pareto_targets (ascending,
/// each once), then, with fidelity.ablations, the five ablations at every suite compression target below 1 (at 1
/// they would all be the full-resolution body), then, with a calibration, calibrated TC-SB at every target of the
/// sweep below 1 and the calibrated uniform grid at the suite's targets below 1, and, when the suite's TC-SB uses
/// hanging interfaces and asks for ablations, calibrated TC-SB with the paper's fans at the suite's targets below 1;
/// when the suite's TC-SB uses the view terms (feedback.view), TC-SB with the motion-only BSWDF at the suite's targets
/// below 1, and with a calibration the calibrated one too, so the spectator's effect is measured in the same pass;
/// under the compliant material the uniform grid at the suite's targets below 1 (if the ablations did not add it)
/// and stock Bullet at full resolution. With fidelity.curves, TC-SB at every curve budget too (with the targets
/// above), the uniform grid at every curve budget and suite target below 1 not already planned, and full resolution
/// at every divisor (under the compliant material also at divisor 1: its reference takes more small steps than the
/// suite, so the suite's own full-resolution body is a point of its own).
/// Empty unless fidelity.enabled and the suite runs TC-SB.
std::vector<FidelitySubjectSpec> fidelity_plan(const Suite& suite);

/// Grid of the uniform coarse net holding about `nodes` nodes with the aspect of a width x height net:
/// width' = round(sqrt(nodes width / height)), height' = round(nodes / width'), each clamped to [2, the original].
struct CoarseGrid {
  int width = 2;   ///< nodes along x
  int height = 2;  ///< nodes along z
};
CoarseGrid coarse_grid_for(int width, int height, int nodes);

/// The spec of the uniform coarse net for a budget (the fidelity pass's uniform grid and the
/// plain_equal method): coarse_grid_for() nodes, the same physical size, elevation and
/// total mass, and the same pins carried to its grid (net/net_pins.h: corners and edges stay, a listed node goes to
/// the nearest coarse node).
NetSpec coarse_net_spec(const NetSpec& fine, int budget);

}  // namespace tcsb
