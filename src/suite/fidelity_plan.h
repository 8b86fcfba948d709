// Fidelity plan: which bodies the fidelity pass runs beside the full-resolution reference, per net. TC-SB at each of
// the suite's compression targets and Pareto targets, and — when the suite asks for ablations — four other ways to
// spend the same node budget, and TC-SB with its surface switched instead of geomorphed, each at the budget of the
// TC-SB case it is compared with.
#pragma once

#include <string>
#include <vector>

#include "suite/suite.h"

namespace tcsb {

/// The ways the fidelity pass can simulate a net at a node budget.
enum class FidelityMethod {
  kTcsb,            ///< TC-SB as the suite configures it (the method under test)
  kUniform,         ///< a static coarse grid of about the budget's node count, same size, mass and pins (ablation)
  kSwitch,          ///< full resolution, then a new coarse btSoftBody built from its state when the budget applies (the
                    ///< paper's stated alternative: "a new SoftBody has to be created", §6) (ablation)
  kTcsbRandom,      ///< TC-SB driven by seeded random operations instead of saliency (ablation)
  kTcsbRigid,       ///< TC-SB with the paper's rigid-offset child placement instead of the affine fit (ablation)
  kTcsbNoGeomorph,  ///< TC-SB, the same body, its surface switched at once instead of geomorphed (ablation;
                    ///< fidelity/surface_morph.h)
  kTcsbCalibrated,  ///< TC-SB with the suite calibration's per-level link stiffness (TcSettings::level_stiffness)
  kUniformCalibrated,   ///< the uniform coarse grid with the calibration's stiffness for its budget (the fair rival)
  kTcsbCalibratedFans,  ///< calibrated TC-SB with the paper's fans at interfaces, in a suite whose TC-SB uses
                        ///< hanging interfaces (ablation)
  kTcsbMotionOnly,      ///< TC-SB with the paper's motion-only BSWDF, in a suite whose TC-SB uses the view terms
  kTcsbCalibratedMotionOnly,  ///< the same, calibrated
  /// Under the compliant material: stock Bullet at full resolution with the suite's solver settings (kLST and
  /// piterations), against the same converged reference as every subject.
  kStock,
  /// Full resolution of the suite's material with its link passes a step (its small steps under the compliant
  /// material) divided by FidelitySubjectSpec::solver_divisor: the third curve of error against time, what a user
  /// who wants a cheaper cloth without adaptivity would try (fidelity.curves).
  kFullResolution,
};

/// Name used in reports: "tcsb", "uniform_grid", "switch_body", "tcsb_random", "tcsb_rigid", "tcsb_no_geomorph",
/// "tcsb_calibrated", "uniform_grid_calibrated", "tcsb_calibrated_fans", "tcsb_motion_only",
/// "tcsb_calibrated_motion_only", "stock_bullet", "full_resolution". ("tcsb" is the suite's TC-SB, uncalibrated: the
/// timed one.)
const char* fidelity_method_name(FidelityMethod method);

/// One body of the fidelity pass on every net.
struct FidelitySubjectSpec {
  FidelityMethod method = FidelityMethod::kTcsb;
  double compression = 1.0;  ///< node budget as a fraction of the net's node count
  /// kFullResolution: what the suite's link passes (small steps) a step are divided by; 1 for every other method.
  int solver_divisor = 1;
};

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
