// The compliant model's step (material.h), for every body of a compliant suite alike — the full-resolution body, the
// uniform grids and TC-SB — so comparisons between them stay fair.
//
// A step of dt is Bullet's btSoftBody::predictMotion (the step's forces, and the predicted positions the collision
// detection meets), then `substeps` small steps of h = dt / substeps, each: the step's forces for h, positions
// advanced from the small step's start, the configured position solvers (anchors and rigid contacts once — the step's
// contact set reused in every small step, as Macklin et al. 2019 do —, `passes` passes over the links with XPBD's
// correction and the compliant constants, in double precision, each followed by the caller's own constraints: TC-SB's
// interfaces), and velocities from the positions, damped by exp(-damping h).
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

#include "../net/net.h"
#include "../softbody/solver_settings.h"

namespace tcsb {

/// Before a compliant body's predictMotion: keeps each node's velocity at the start of the step in Node::m_vn, which
/// Bullet's step does not use (only its deformable solvers do), so the small steps can apply the step's forces a
/// part at a time. O(N).
void keep_start_velocities(btSoftBody& body);

/// The positions the small steps work on, in double precision, one per Bullet node (index as in m_nodes), reused
/// from step to step. Bullet's floats cannot carry a small step: at 1/60 s and 192 small steps a node at rest gains
/// g h^2 = 7e-8 m a step, a tenth of a float's ulp at 8 m, and the cloth's response to doubling the small steps grew
/// instead of shrinking (docs/design.md, "Precision"). Bullet's nodes get the positions back, as floats, at the end
/// of the step.
struct SubstepPositions {
  std::vector<Eigen::Vector3d> x;    ///< now
  std::vector<Eigen::Vector3d> q;    ///< at the small step's start
  std::vector<double> inverse_mass;  ///< Bullet's m_im, read once a step
  /// With more than one pass a small step (CompliantMaterial::passes), XPBD's lambda of each link (index as in
  /// m_links) and of each of the caller's constraints (index as the caller's; the caller sizes it), summed over the
  /// passes of the small step and zeroed at its start: lambda lives one small step, so links that come and go between
  /// steps need nothing kept. Empty with one pass, whose lambda is 0.
  std::vector<double> link_lambda;
  std::vector<double> constraint_lambda;
};

/// The small steps of a compliant body (after predictMotion and the world's collision detection): what
/// btSoftBody::solveConstraints does for a Bullet body. Anchors and contacts are solved once a small step (their
/// hardness is shared among the small steps), the links `passes` times; `after_links` runs after every pass, on the
/// double positions (may be empty), and reads `positions.constraint_lambda` when passes > 1.
/// O(substeps x (N + passes x L + contacts)).
void solve_in_substeps(btSoftBody& body, const SolverSettings& solver, SubstepPositions& positions,
                       const std::function<void(SubstepPositions&)>& after_links);

/// Bullet's per-step anchor constants (btSoftBody::solveConstraints' "prepare anchors", for m_sst.sdt): what every
/// constraint loop of ours runs before its position solvers.
void prepare_anchors(btSoftBody& body);

/// A plain body of a compliant suite (the full-resolution body, a uniform grid): a btSoftBody that remembers its
/// material, so the solver steps it in small steps (tc_softbody_solver.h).
class CompliantSoftBody : public btSoftBody {
 public:
  CompliantSoftBody(btSoftBodyWorldInfo& world, const SolverSettings& solver)
      : btSoftBody(&world, 0, nullptr, nullptr), solver_(solver) {}
  const SolverSettings& solver() const { return solver_; }
  void solve_constraints() { solve_in_substeps(*this, solver_, positions_, {}); }

 private:
  SolverSettings solver_;
  SubstepPositions positions_;
};

/// Rewrites every link constant of a body built from `net`'s links in their canonical order (append_net_links) for
/// the compliant material: each link carries the membrane rule with the grid cells on either side of it.
void write_compliant_grid_constants(btSoftBody& body, const Net& net, const SolverSettings& solver);

/// The stiffness the membrane rule gives a straight link of `length` cells of the grid, `adjacent` cells' worth of
/// area on its sides (both in units of the grid's spacing along and across it), N/m: one expression for every
/// body, so a full-resolution TC-SB and the plain body get the same constants bit for bit.
double grid_link_stiffness(const SolverSettings& solver, double adjacent, double length, double spacing_along,
                           double spacing_across);

/// The settings a compliant body steps with, or null for a body of Bullet's model (stock stepping).
const SolverSettings* compliant_settings(const btSoftBody& body);

}  // namespace tcsb
