#include "fidelity/fidelity_subject.h"

#include <algorithm>
#include <cmath>

#include "analysis/fidelity_metrics.h"
#include "case/case_body.h"
#include "case/step_clock.h"
#include "feedback/controller.h"
#include "fidelity/converged_reference.h"
#include "fidelity/reconstruction.h"
#include "fidelity/surface_morph.h"
#include "net/grid_resample.h"
#include "softbody/bullet_setup.h"
#include "softbody/op_sample.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody_impl.h"
#include "softbody/vector_conversion.h"

namespace tcsb {

namespace {

GridSize grid_of(const Net& net) { return {net.width(), net.height()}; }

/// The solver of the curves' full-resolution body: the suite's link passes a step (its small steps under the compliant
/// material) divided by `divisor`, at least 1.
SolverSettings with_passes_divided(const SolverSettings& solver, int divisor) {
  if (solver.compliant_model()) return with_substeps(solver, std::max(1, solver.compliant.substeps / divisor));
  SolverSettings divided = solver;
  divided.piterations = std::max(1, solver.piterations / divisor);
  return divided;
}

std::string grid_label(const Net& net) { return std::to_string(net.width()) + "x" + std::to_string(net.height()); }

/// Energy of a stock body built from `net` (node i = grid node i; pinned nodes carry the net's mass, which Bullet
/// does not keep for them).
double stock_energy(const btSoftBody& body, const Net& net, double gravity, std::vector<Eigen::Vector3d>& x,
                    std::vector<Eigen::Vector3d>& v) {
  copy_positions(body, x);
  copy_velocities(body, v);
  return mechanical_energy(net.masses(), x, v, gravity);
}

/// Counts operations begun or ended, so the pass knows when the surface may have jumped.
class OpCounter final : public OpSink {
 public:
  void record(const OpSample&) override { ++count; }
  std::int64_t count = 0;
};

/// TC-SB with its controller (none at compression 1: the body then never changes its cut).
class TreeCutSubject final : public FidelitySubject {
 public:
  /// `morph`: show the geomorphed surface (SurfaceMorph); otherwise the committed cut's, which jumps.
  TreeCutSubject(SceneWorld& world, std::unique_ptr<TcSoftBody> body, std::unique_ptr<Controller> controller,
                 int budget, bool morph)
      : world_(world), body_(std::move(body)), attachment_(world.attach(*body_)), controller_(std::move(controller)),
        budget_(budget) {
    if (morph) morph_.emplace();
    body_->impl().set_op_sink(&ops_);
  }
  ~TreeCutSubject() override { body_->impl().set_op_sink(nullptr); }
  void boundary(int step) override {
    const std::int64_t before = ops_.count;
    body_->advance_blends(OrderSettling::kByCaller);
    if (controller_) controller_->before_step(*body_);
    body_->settle_order();  // (the controllers settle before their snapshot already: then a no-op)
    // A geomorphed surface also moves at a boundary without operations while it spreads an earlier jump.
    changed_ = ops_.count != before || (morph_ && morph_->morphing());
    // The morph records the boundary's jump at the next reconstruct(), which the pass makes right away when the
    // surface changed (untimed, unlike this function), before the body moves.
    morph_pending_ = morph_ && changed_;
    if (controller_ && !converged_ && body_->node_count() <= budget_) converged_ = step;
  }
  std::optional<int> converged_step() const override { return converged_; }
  bool surface_changed() const override { return changed_; }
  void pause() override {
    if (controller_) controller_->pause();
  }
  void resume() override {
    if (controller_) controller_->resume();
  }
  void simulate(btScalar dt) override {
    world_.step(dt);
    if (controller_) controller_->after_step(*body_);
  }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    if (!morph_) {
      reconstruct_leaves(*body_, leaves);
      return;
    }
    if (morph_pending_) morph_->boundary(*body_);
    morph_pending_ = false;
    morph_->reconstruct(*body_, leaves);
  }
  double energy(double gravity) override {
    copy_positions(*body_, x_);
    copy_velocities(*body_, v_);
    mass_.resize(x_.size());
    for (std::size_t i = 0; i < mass_.size(); ++i)
      mass_[i] = body_->simulated_mass(body_->tree_id(static_cast<int>(i)));
    return mechanical_energy(mass_, x_, v_, gravity);
  }
  const btSoftBody& bullet() const override { return *body_; }

 private:
  SceneWorld& world_;
  std::unique_ptr<TcSoftBody> body_;
  SceneWorld::Attachment attachment_;  // after the body: leaves the world first
  std::unique_ptr<Controller> controller_;
  int budget_;
  std::optional<SurfaceMorph> morph_;
  std::optional<int> converged_;
  OpCounter ops_;
  bool changed_ = false;
  bool morph_pending_ = false;  // a boundary's jump for the morph to record before the body moves
  std::vector<Eigen::Vector3d> x_, v_;
  std::vector<double> mass_;
};

/// A static coarse grid of the same cloth, compared through bilinear interpolation of its nodes.
class UniformSubject final : public FidelitySubject {
 public:
  /// `solver`: the suite's, or with the calibration's stiffness for the budget.
  UniformSubject(SceneWorld& world, const SolverSettings& solver, std::shared_ptr<const Net> fine, int budget)
      : world_(world), fine_(std::move(fine)), coarse_(coarse_net_spec(fine_->spec(), budget)),
        body_(make_plain_softbody(world.info(), coarse_, solver)), attachment_(world.attach(*body_)) {}
  void boundary(int) override {}
  void simulate(btScalar dt) override { world_.step(dt); }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    copy_positions(*body_, x_);
    leaves.resize(fine_->node_count());
    resample_bilinear(grid_of(coarse_), x_, grid_of(*fine_), leaves);
  }
  double energy(double gravity) override { return stock_energy(*body_, coarse_, gravity, x_, v_); }
  const btSoftBody& bullet() const override { return *body_; }
  std::string grid() const override { return grid_label(coarse_); }

 private:
  SceneWorld& world_;
  std::shared_ptr<const Net> fine_;
  Net coarse_;
  std::unique_ptr<btSoftBody> body_;
  SceneWorld::Attachment attachment_;  // after the body: leaves the world first
  std::vector<Eigen::Vector3d> x_, v_;
};

/// The paper's alternative to a TreeCut: simulate at full resolution, and when the budget applies build a new,
/// coarser btSoftBody from the running one's state. The coarse net (the precomputed level) exists from the start;
/// the switch builds the Bullet body, samples positions and velocities bilinearly at its nodes and frees the fine
/// body, and that is what switch_ms times.
class SwitchSubject final : public FidelitySubject {
 public:
  SwitchSubject(SceneWorld& world, const Suite& suite, std::shared_ptr<const Net> fine, int budget,
                const FidelitySubject* pace, int fallback_step)
      : world_(world), suite_(suite), fine_(std::move(fine)), coarse_(coarse_net_spec(fine_->spec(), budget)),
        pace_(pace), fallback_step_(fallback_step), body_(make_plain_softbody(world.info(), *fine_, suite.solver)),
        attachment_(world.attach(*body_)) {}
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
    std::unique_ptr<btSoftBody> coarse = make_plain_softbody(world_.info(), coarse_, suite_.solver);
    copy_positions(*body_, x_);
    copy_velocities(*body_, v_);
    cx_.resize(coarse_.node_count());
    cv_.resize(coarse_.node_count());
    resample_bilinear(grid_of(*fine_), x_, grid_of(coarse_), cx_);
    resample_bilinear(grid_of(*fine_), v_, grid_of(coarse_), cv_);
    for (int i = 0; i < coarse->m_nodes.size(); ++i) {
      btSoftBody::Node& n = coarse->m_nodes[i];
      if (coarse_.pinned()[static_cast<std::size_t>(i)]) continue;  // corners stay at rest (the fine ones are too)
      const Eigen::Vector3d& p = cx_[static_cast<std::size_t>(i)];
      const Eigen::Vector3d& u = cv_[static_cast<std::size_t>(i)];
      n.m_x = n.m_q = to_bullet(p);
      n.m_v = to_bullet(u);
    }
    coarse->updateBounds();
    attachment_.release();
    body_ = std::move(coarse);  // frees the fine body: part of what a switch costs
    attachment_ = world_.attach(*body_);
    switch_ms_ = ms_between(t0, StepClock::now());
    changed_ = true;
  }
  bool surface_changed() const override { return changed_; }
  void simulate(btScalar dt) override { world_.step(dt); }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    copy_positions(*body_, x_);
    if (!switched_at_) {
      leaves = x_;
      return;
    }
    leaves.resize(fine_->node_count());
    resample_bilinear(grid_of(coarse_), x_, grid_of(*fine_), leaves);
  }
  double energy(double gravity) override {
    return stock_energy(*body_, switched_at_ ? coarse_ : *fine_, gravity, x_, v_);
  }
  const btSoftBody& bullet() const override { return *body_; }
  std::string grid() const override { return grid_label(coarse_); }
  std::optional<double> switch_ms() const override { return switched_at_ ? std::optional(switch_ms_) : std::nullopt; }
  std::optional<int> switch_step() const override { return switched_at_; }

 private:
  SceneWorld& world_;
  const Suite& suite_;
  std::shared_ptr<const Net> fine_;
  Net coarse_;
  const FidelitySubject* pace_;
  int fallback_step_;
  std::unique_ptr<btSoftBody> body_;
  SceneWorld::Attachment attachment_;  // after the body: leaves the world first
  std::optional<int> switched_at_;
  bool changed_ = false;
  double switch_ms_ = 0;
  std::vector<Eigen::Vector3d> x_, v_, cx_, cv_;
};

}  // namespace

int subject_budget(const Net& net, const FidelitySubjectSpec& spec) { return node_budget(net, spec.compression); }

std::unique_ptr<FidelitySubject> make_fidelity_subject(const Suite& suite, const FidelitySubjectSpec& spec,
                                                       SceneWorld& world, std::shared_ptr<const Net> net,
                                                       std::uint64_t seed, const FidelitySubject* pace,
                                                       int fallback_switch_step) {
  const int budget = subject_budget(*net, spec);
  switch (spec.method) {
    case FidelityMethod::kUniform: return std::make_unique<UniformSubject>(world, suite.solver, std::move(net), budget);
    case FidelityMethod::kUniformCalibrated: {
      SolverSettings solver = suite.solver;
      const std::optional<double> k =
          suite.calibration ? suite.calibration->uniform_stiffness(spec.compression) : std::nullopt;
      if (!k) throw std::invalid_argument("uniform_grid_calibrated: the calibration has no fit for this budget");
      solver.linear_stiffness = *k;
      return std::make_unique<UniformSubject>(world, solver, std::move(net), budget);
    }
    case FidelityMethod::kStock:  // a uniform grid of every node: the plain body, stepped by Bullet itself
      return std::make_unique<UniformSubject>(world, stock_bullet(suite.solver), std::move(net), budget);
    case FidelityMethod::kFullResolution:
      return std::make_unique<UniformSubject>(world, with_passes_divided(suite.solver, spec.solver_divisor),
                                              std::move(net), budget);
    case FidelityMethod::kSwitch:
      return std::make_unique<SwitchSubject>(world, suite, std::move(net), budget, pace, fallback_switch_step);
    case FidelityMethod::kTcsb:
    case FidelityMethod::kTcsbRandom:
    case FidelityMethod::kTcsbRigid:
    case FidelityMethod::kTcsbNoGeomorph:
    case FidelityMethod::kTcsbCalibrated:
    case FidelityMethod::kTcsbCalibratedFans:
    case FidelityMethod::kTcsbMotionOnly:
    case FidelityMethod::kTcsbCalibratedMotionOnly: {
      TcSettings tc = suite.tcsb;
      if (spec.method == FidelityMethod::kTcsbRigid) tc.placement = Placement::kRigid;
      if (spec.method == FidelityMethod::kTcsbCalibrated || spec.method == FidelityMethod::kTcsbCalibratedFans ||
          spec.method == FidelityMethod::kTcsbCalibratedMotionOnly) {
        if (!suite.calibration) throw std::invalid_argument("tcsb_calibrated: the suite has no calibration");
        tc.level_stiffness = suite.calibration->level_stiffness();
      }
      if (spec.method == FidelityMethod::kTcsbCalibratedFans) tc.interfaces = Interfaces::kLinks;
      FeedbackSettings feedback = suite.feedback;
      if (spec.method == FidelityMethod::kTcsbRandom) feedback.policy = PolicyKind::kRandom;
      if (spec.method == FidelityMethod::kTcsbMotionOnly || spec.method == FidelityMethod::kTcsbCalibratedMotionOnly)
        feedback.view = false;
      const bool compressed = budget < static_cast<int>(net->node_count());
      auto body = std::make_unique<TcSoftBody>(world.info(), std::move(net), suite.solver, tc);
      std::unique_ptr<Controller> controller;
      if (compressed) controller = make_controller(feedback, budget, seed, suite_spectator(suite));
      const bool morph = spec.method != FidelityMethod::kTcsbNoGeomorph;
      return std::make_unique<TreeCutSubject>(world, std::move(body), std::move(controller), budget, morph);
    }
  }
  return nullptr;
}

}  // namespace tcsb
