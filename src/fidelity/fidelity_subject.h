// FidelitySubject: a body the fidelity pass compares with the full-resolution reference — TC-SB (saliency, random,
// rigid placement; its surface geomorphed or not), a uniform coarse grid, or a body switched to a coarse btSoftBody —
// behind one interface, so the fidelity loop is the same code for all of them. Each can reconstruct a surface with one
// point per grid node.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "net/net.h"
#include "scene/scene_world.h"
#include "suite/body_spec.h"
#include "suite/suite.h"

namespace tcsb {

/// A body under test in the fidelity pass. A step is boundary() then simulate(); popping is measured between them.
class FidelitySubject {
 public:
  virtual ~FidelitySubject() = default;
  /// Step-boundary work before Bullet steps: blends, feedback and operations for TC-SB; the switch for switch_body
  /// at its switch step. `step` counts from 0, warm-up included.
  virtual void boundary(int step) = 0;
  /// Whether the last boundary() may have moved the reconstructed surface (an operation began or ended, or the
  /// body was switched). When false the surface is the same as after the previous step: no popping to measure.
  virtual bool surface_changed() const { return false; }
  /// One Bullet step, and whatever must follow it (joining a feedback worker).
  virtual void simulate(btScalar dt) = 0;
  /// The full-resolution surface: one point per grid node of the fine net, indexed as the net's nodes.
  virtual void reconstruct(std::vector<Eigen::Vector3d>& leaves) = 0;
  /// Mechanical energy of the simulated body over its own nodes and masses (pinned nodes included), joules; see
  /// mechanical_energy() for the convention.
  virtual double energy(double gravity) = 0;
  /// The Bullet body simulated now (node count, divergence checks, state hash).
  virtual const btSoftBody& bullet() const = 0;
  /// The coarse grid ("44x44") of a uniform or switched body; empty otherwise.
  virtual std::string grid() const { return {}; }
  /// Time the switch took, once it happened (switch_body only), milliseconds.
  virtual std::optional<double> switch_ms() const { return std::nullopt; }
  /// Step at whose boundary the body first fitted its node budget (simulated nodes, blends included, at most the
  /// budget: when the controller's budget starts to hold); TC-SB under a budget only.
  virtual std::optional<int> converged_step() const { return std::nullopt; }
  /// The pass moves on to other subjects for a while (see Controller::pause()).
  virtual void pause() {}
  /// The pass comes back to this subject (see Controller::resume()).
  virtual void resume() {}
  /// Step at whose boundary the body switched (switch_body only).
  virtual std::optional<int> switch_step() const { return std::nullopt; }
};

/// Builds the subject `spec` describes on `net` (make_body: the suite's settings, changed where the spec says; `seed`
/// drives random choices). The node budget is round(compression x grid nodes), as for TC-SB cases.
///
/// A switch_body subject switches when the budget starts to hold for TC-SB: at the first boundary at which `pace`
/// (the TC-SB subject at the same target, stepped up to at least that boundary first) reports converged_step(), so
/// both are coarse from the same step on (if TC-SB never fits its budget, the body never switches and says so with
/// an empty switch_ms); without a pace, at the boundary of `fallback_switch_step`.
std::unique_ptr<FidelitySubject> make_fidelity_subject(const Suite& suite, const BodySpec& spec, SceneWorld& world,
                                                       std::shared_ptr<const Net> net, std::uint64_t seed,
                                                       const FidelitySubject* pace, int fallback_switch_step);

}  // namespace tcsb
