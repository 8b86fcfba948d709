#include "fidelity/fidelity_subject.h"

#include <algorithm>
#include <cmath>

#include "analysis/fidelity_metrics.h"
#include "case/body_factory.h"
#include "case/step_clock.h"
#include "fidelity/grid_state_transfer.h"
#include "fidelity/reconstruction.h"
#include "fidelity/surface_morph.h"
#include "net/grid_resample.h"
#include "softbody/op_sample.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody_impl.h"
#include "suite/fidelity_plan.h"

namespace tcsb {

namespace {

GridSize grid_of(const Net& net) { return {net.width(), net.height()}; }

std::string grid_label(const Net& net) { return std::to_string(net.width()) + "x" + std::to_string(net.height()); }

/// Energy of a stock body built from `net` (node i = grid node i; pinned nodes carry the net's mass, which Bullet
/// does not keep for them).
double stock_energy(const btSoftBody& body, const Net& net, double gravity, std::vector<Eigen::Vector3d>& x,
                    std::vector<Eigen::Vector3d>& v) {
  copy_positions(body, x);
  copy_velocities(body, v);
  return mechanical_energy(net.masses(), x, v, gravity);
}

/// TC-SB with its controller (none at compression 1: the body then never changes its cut).
class TreeCutSubject final : public FidelitySubject {
 public:
  /// `morph`: show the surface geomorphed over `morph_boundaries` (SurfaceMorph); otherwise the committed cut's,
  /// which jumps.
  TreeCutSubject(SceneWorld& world, Body body, bool morph, std::optional<int> morph_boundaries)
      : world_(world), body_(std::move(body)), tc_(*body_.tc) {
    if (morph) morph_.emplace(morph_boundaries);
    tc_.impl().set_op_sink(&ops_);
  }
  ~TreeCutSubject() override { tc_.impl().set_op_sink(nullptr); }
  void boundary(int step) override {
    Controller* controller = body_.controller.get();
    const std::int64_t before = ops_.count;
    tc_.advance_blends(OrderSettling::kByCaller);
    if (controller) controller->before_step(tc_);
    tc_.settle_order();  // (the controllers settle before their snapshot already: then a no-op)
    // A geomorphed surface also moves at a boundary without operations while it spreads an earlier jump.
    changed_ = ops_.count != before || (morph_ && morph_->morphing());
    // The morph records the boundary's jump at the next reconstruct(), which the pass makes right away when the
    // surface changed (untimed, unlike this function), before the body moves.
    morph_pending_ = morph_ && changed_;
    if (controller && !converged_ && tc_.node_count() <= body_.budget) converged_ = step;
  }
  std::optional<int> converged_step() const override { return converged_; }
  bool surface_changed() const override { return changed_; }
  void pause() override {
    if (body_.controller) body_.controller->pause();
  }
  void resume() override {
    if (body_.controller) body_.controller->resume();
  }
  void simulate(btScalar dt) override {
    world_.step(dt);
    if (body_.controller) body_.controller->after_step(tc_);
  }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    if (!morph_) {
      reconstruct_leaves(tc_, leaves);
      return;
    }
    if (morph_pending_) morph_->boundary(tc_);
    morph_pending_ = false;
    morph_->reconstruct(tc_, leaves);
  }
  double energy(double gravity) override {
    copy_positions(tc_, x_);
    copy_velocities(tc_, v_);
    mass_.resize(x_.size());
    for (std::size_t i = 0; i < mass_.size(); ++i) mass_[i] = tc_.simulated_mass(tc_.tree_id(static_cast<int>(i)));
    return mechanical_energy(mass_, x_, v_, gravity);
  }
  const btSoftBody& bullet() const override { return tc_; }

 private:
  SceneWorld& world_;
  Body body_;
  TcSoftBody& tc_;
  std::optional<SurfaceMorph> morph_;
  std::optional<int> converged_;
  OpCounter ops_;
  bool changed_ = false;
  bool morph_pending_ = false;  // a boundary's jump for the morph to record before the body moves
  std::vector<Eigen::Vector3d> x_, v_;
  std::vector<double> mass_;
};

/// A plain Bullet body on a grid — a uniform coarse grid of the same cloth, or the full resolution — compared through
/// bilinear interpolation of its nodes at the fine net's.
class GridSubject final : public FidelitySubject {
 public:
  GridSubject(SceneWorld& world, Body body, std::shared_ptr<const Net> fine)
      : world_(world), body_(std::move(body)), fine_(std::move(fine)) {}
  void boundary(int) override {}
  void simulate(btScalar dt) override { world_.step(dt); }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    copy_positions(*body_.bullet, x_);
    leaves.resize(fine_->node_count());
    resample_bilinear(grid_of(*body_.net), x_, grid_of(*fine_), leaves);
  }
  double energy(double gravity) override { return stock_energy(*body_.bullet, *body_.net, gravity, x_, v_); }
  const btSoftBody& bullet() const override { return *body_.bullet; }
  std::string grid() const override { return grid_label(*body_.net); }

 private:
  SceneWorld& world_;
  Body body_;
  std::shared_ptr<const Net> fine_;
  std::vector<Eigen::Vector3d> x_, v_;
};

/// The paper's alternative to a TreeCut: simulate at full resolution, and when the budget applies build a new,
/// coarser btSoftBody from the running one's state. The coarse net (the precomputed level) exists from the start;
/// the switch builds the Bullet body, samples positions and velocities bilinearly at its nodes and frees the fine
/// body, and that is what switch_ms times.
class SwitchSubject final : public FidelitySubject {
 public:
  /// `body`: the full-resolution body it starts as; `solver`: that body's, which the coarse one steps with too.
  SwitchSubject(SceneWorld& world, Body body, const SolverSettings& solver, const FidelitySubject* pace,
                int fallback_step)
      : world_(world), solver_(solver), fine_(body.net), coarse_(coarse_net_spec(fine_->spec(), body.budget)),
        pace_(pace), fallback_step_(fallback_step), body_(std::move(body)) {}
  void boundary(int step) override {
    changed_ = false;
    if (switched_at_) return;
    if (pace_) {
      const std::optional<int> converged = pace_->converged_step();
      if (!converged || *converged > step) return;
    } else if (step < fallback_step_) {
      return;
    }
    switched_at_ = step;
    const StepClock::time_point t0 = StepClock::now();
    std::unique_ptr<btSoftBody> coarse = make_plain_softbody(world_.info(), coarse_, solver_);
    transfer_grid_state(*body_.bullet, grid_of(*fine_), *coarse, coarse_, x_, v_, cx_, cv_);
    body_.attachment.release();
    body_.bullet = std::move(coarse);  // frees the fine body: part of what a switch costs
    body_.attachment = world_.attach(*body_.bullet);
    switch_ms_ = ms_between(t0, StepClock::now());
    changed_ = true;
  }
  bool surface_changed() const override { return changed_; }
  void simulate(btScalar dt) override { world_.step(dt); }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    copy_positions(*body_.bullet, x_);
    if (!switched_at_) {
      leaves = x_;
      return;
    }
    leaves.resize(fine_->node_count());
    resample_bilinear(grid_of(coarse_), x_, grid_of(*fine_), leaves);
  }
  double energy(double gravity) override {
    return stock_energy(*body_.bullet, switched_at_ ? coarse_ : *fine_, gravity, x_, v_);
  }
  const btSoftBody& bullet() const override { return *body_.bullet; }
  std::string grid() const override { return grid_label(coarse_); }
  std::optional<double> switch_ms() const override { return switched_at_ ? std::optional(switch_ms_) : std::nullopt; }
  std::optional<int> switch_step() const override { return switched_at_; }

 private:
  SceneWorld& world_;
  SolverSettings solver_;
  std::shared_ptr<const Net> fine_;
  Net coarse_;
  const FidelitySubject* pace_;
  int fallback_step_;
  Body body_;  // its net stays the fine one: coarse_ is the switched body's
  std::optional<int> switched_at_;
  bool changed_ = false;
  double switch_ms_ = 0;
  std::vector<Eigen::Vector3d> x_, v_, cx_, cv_;
};

}  // namespace

std::unique_ptr<FidelitySubject> make_fidelity_subject(const Suite& suite, const BodySpec& spec, SceneWorld& world,
                                                       std::shared_ptr<const Net> net, std::uint64_t seed,
                                                       const FidelitySubject* pace, int fallback_switch_step) {
  Body body = make_body(suite, spec, world, net, seed);
  switch (spec.kind) {
    case BodyKind::kTcsb:
      return std::make_unique<TreeCutSubject>(world, std::move(body), spec.geomorph,
                                              suite.fidelity.geomorph_boundaries);
    case BodyKind::kSwitch:
      return std::make_unique<SwitchSubject>(world, std::move(body), body_solver(suite, spec), pace,
                                             fallback_switch_step);
    case BodyKind::kPlain:
    case BodyKind::kBulletPatch:
    case BodyKind::kUniform: return std::make_unique<GridSubject>(world, std::move(body), std::move(net));
  }
  return nullptr;
}

}  // namespace tcsb
