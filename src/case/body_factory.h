// The body factory: the one place a body is built from its description (suite/body_spec.h) — plain Bullet, Bullet's
// patch, a uniform coarse grid, the body a switch starts from, or TC-SB with its controller — for the timed cases,
// the fidelity pass, the calibration and the figure frames alike.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <cstdint>
#include <memory>

#include "feedback/controller.h"
#include "net/net.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody.h"
#include "suite/body_spec.h"
#include "suite/suite.h"

namespace tcsb {

/// A body in its world, with what stepping it needs. Movable; leaves its world when destroyed.
struct Body {
  /// The net the Bullet body is built on: the uniform coarse grid for BodyKind::kUniform, else the net given.
  std::shared_ptr<const Net> net;
  std::unique_ptr<btSoftBody> bullet;  ///< the TcSoftBody for TC-SB
  TcSoftBody* tc = nullptr;            ///< `bullet` as TC-SB, or nullptr
  int budget = 0;                      ///< node budget (node_budget() of the spec on the net given)
  SceneWorld::Attachment attachment;   // after the body: leaves the world first
  /// TC-SB's controller while the budget is below the net's node count; else nullptr (the cut never changes).
  std::unique_ptr<Controller> controller;
};

/// A node budget: the compression target times the net's node count, rounded.
int node_budget(const Net& net, double compression);

/// The solver settings `spec`'s body steps with in `suite`: the suite's (Bullet's own with stock_solver), its link
/// passes divided by solver_divisor, and for a calibrated uniform grid the calibration's stiffness for the budget.
/// Throws std::invalid_argument when a calibrated uniform grid's calibration has no fit for the budget.
SolverSettings body_solver(const Suite& suite, const BodySpec& spec);

/// Builds `spec`'s body on `net` inside `world` (which steps it; it must outlive the body), from the suite's solver,
/// TC-SB and feedback settings and its spectator, changed where the spec says. `seed` drives the controller's random
/// choices (same seed, same run). Throws std::invalid_argument for a calibrated body in a suite without a calibration
/// (or without a fit for the budget).
Body make_body(const Suite& suite, const BodySpec& spec, SceneWorld& world, std::shared_ptr<const Net> net,
               std::uint64_t seed);

}  // namespace tcsb
