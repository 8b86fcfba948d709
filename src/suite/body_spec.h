// BodySpec: how a body is built on a net, as data — its kind, its budget, and each way it differs from the suite's
// own body, one field a difference. The timed cases (case_body_spec) and the fidelity pass (fidelity_plan's variants)
// describe their bodies with it, and one factory (case/body_factory.h) builds them all.
#pragma once

#include <optional>

#include "feedback/feedback_settings.h"
#include "softbody/tc_settings.h"

namespace tcsb {

/// What a body is.
enum class BodyKind {
  kPlain,        ///< plain Bullet on the net itself (full resolution)
  kBulletPatch,  ///< Bullet's own CreatePatch on the net
  /// plain Bullet on the uniform coarse grid of the budget (coarse_net_spec: same size, mass and pins); at a budget
  /// of every node the full-resolution body as the fidelity pass measures it
  kUniform,
  /// plain Bullet at full resolution, which the fidelity pass rebuilds as the uniform coarse grid of the budget once
  /// the budget applies (the paper's stated alternative to a TreeCut, §6)
  kSwitch,
  kTcsb,  ///< TC-SB, driven by a controller while its budget is below the net's node count
};

/// Whose link stiffness a body uses.
enum class BodyCalibration {
  kNone,   ///< the solver's
  kSuite,  ///< the suite calibration's: per LOD level for TC-SB, the fit for the budget for a uniform grid
};

/// A body, relative to the suite it runs in: every field at its default gives the suite's own body of the kind.
struct BodySpec {
  BodyKind kind = BodyKind::kTcsb;
  double compression = 1.0;   ///< node budget as a fraction of the net's node count (node_budget())
  bool stock_solver = false;  ///< stepped by Bullet itself (stock_bullet()) instead of the suite's material model
  int solver_divisor = 1;     ///< the suite's link passes (small steps under the compliant material) a step, divided
  BodyCalibration calibration = BodyCalibration::kNone;
  // TC-SB only (the suite's setting where empty):
  std::optional<Placement> placement = std::nullopt;    ///< child placement: affine fit or the paper's rigid offsets
  std::optional<Interfaces> interfaces = std::nullopt;  ///< interface links: hanging constraints or the paper's fans
  std::optional<PolicyKind> policy = std::nullopt;      ///< the controller: BSWDF saliency or seeded random operations
  std::optional<bool> view_terms = std::nullopt;        ///< the BSWDF with the view terms, or motion only
  /// The fidelity pass shows the surface geomorphed (fidelity/surface_morph.h), or switched at once at each operation.
  bool geomorph = true;
  /// The whole cut at this LOD level from the start, before the body enters its world (0: the suite's start cut);
  /// the calibration's bodies, which run at one level without a controller.
  int whole_level = 0;
};

}  // namespace tcsb
