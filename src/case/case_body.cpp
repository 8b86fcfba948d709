#include "case/case_body.h"

#include <chrono>
#include <cmath>

#include "case/step_clock.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "suite/fidelity_plan.h"

namespace tcsb {

namespace {

/// Gate self-test builds only (CMake option TCSB_INJECT_STEP_DELAY_US): a real, measurable slowdown of TC-SB's
/// step. Nothing in other builds.
void injected_step_delay() {
#if TCSB_INJECT_STEP_DELAY_US > 0
  const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(TCSB_INJECT_STEP_DELAY_US);
  while (std::chrono::steady_clock::now() < until) {
  }
#endif
}

/// Stock Bullet: the plain baseline or CreatePatch.
class StockBody final : public CaseBody {
 public:
  StockBody(SceneWorld& world, std::unique_ptr<btSoftBody> body)
      : world_(world), body_(std::move(body)), attachment_(world.attach(*body_)) {}
  void step(btScalar dt) override { world_.step(dt); }
  const btSoftBody& bullet() const override { return *body_; }

 private:
  SceneWorld& world_;
  std::unique_ptr<btSoftBody> body_;
  SceneWorld::Attachment attachment_;  // after the body: leaves the world first
};

/// TC-SB with its controller (none at NoCompression: the body then never changes its cut).
class TreeCutBody final : public CaseBody {
 public:
  TreeCutBody(SceneWorld& world, std::unique_ptr<TcSoftBody> body, std::unique_ptr<Controller> controller)
      : world_(world), body_(std::move(body)), attachment_(world.attach(*body_)), controller_(std::move(controller)) {}
  void step(btScalar dt) override {
    // Five clock reads a step (tens of ns against a step of 0.1 ms and more), none inside Bullet's loops.
    const StepClock::time_point t0 = StepClock::now();
    body_->advance_blends();
    const StepClock::time_point t1 = StepClock::now();
    if (controller_) controller_->before_step(*body_);
    const StepClock::time_point t2 = StepClock::now();
    world_.step(dt);
    injected_step_delay();
    const StepClock::time_point t3 = StepClock::now();
    if (controller_) controller_->after_step(*body_);
    const StepClock::time_point t4 = StepClock::now();
    phases_ = {ms_between(t0, t1), ms_between(t1, t2) + ms_between(t3, t4), ms_between(t2, t3)};
  }
  const StepPhases* phases() const override { return &phases_; }
  const btSoftBody& bullet() const override { return *body_; }
  int interpolations() const override { return body_->interpolations(); }
  FeedbackCost feedback_cost() const override { return controller_ ? controller_->last_cost() : FeedbackCost{}; }
  TcSoftBody* tc() override { return body_.get(); }
  void pause() override {
    if (controller_) controller_->pause();
  }
  void resume() override {
    if (controller_) controller_->resume();
  }

 private:
  SceneWorld& world_;
  std::unique_ptr<TcSoftBody> body_;
  SceneWorld::Attachment attachment_;  // after the body: leaves the world first
  std::unique_ptr<Controller> controller_;
  StepPhases phases_;
};

}  // namespace

int node_budget(const Net& net, double compression) {
  return static_cast<int>(std::lround(compression * static_cast<double>(net.node_count())));
}

int target_node_count(const Net& net, const CaseKey& key) {
  if ((key.method != Method::kTcsb && key.method != Method::kPlainEqual) || !key.compression) return 0;
  return node_budget(net, *key.compression);
}

std::unique_ptr<CaseBody> make_case_body(const Suite& suite, const CaseKey& key, SceneWorld& world,
                                         std::shared_ptr<const Net> net, std::uint64_t seed) {
  switch (key.method) {
    case Method::kPlain:
      return std::make_unique<StockBody>(world, make_plain_softbody(world.info(), *net, suite.solver));
    case Method::kBulletPatch:
      return std::make_unique<StockBody>(world, make_bullet_patch(world.info(), *net, suite.solver));
    case Method::kPlainEqual: {
      // The fidelity pass's uniform grid (coarse_net_spec): sized by the budget, not by TC-SB's measured mean node
      // count, which is known only after TC-SB ran (it holds the budget, blends included, so it stays at most that).
      const Net coarse(coarse_net_spec(net->spec(), target_node_count(*net, key)));
      return std::make_unique<StockBody>(world, make_plain_softbody(world.info(), coarse, suite.solver));
    }
    case Method::kTcsb: {
      const int target = target_node_count(*net, key);
      auto body = std::make_unique<TcSoftBody>(world.info(), net, suite.solver, suite.tcsb);
      std::unique_ptr<Controller> controller;
      if (target < static_cast<int>(net->node_count()))
        controller = make_controller(suite.feedback, target, seed, suite_spectator(suite));
      return std::make_unique<TreeCutBody>(world, std::move(body), std::move(controller));
    }
  }
  return nullptr;
}

}  // namespace tcsb
