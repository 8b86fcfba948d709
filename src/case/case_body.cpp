#include "case/case_body.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "case/step_clock.h"

namespace tcsb {

namespace {

#if TCSB_INJECT_SLOWDOWN
/// The slowdown asked for (environment variable TCSB_INJECT_STEP_PERCENT, a percentage; unset: none), read once.
double injected_fraction() {
  static const double fraction = [] {
    const char* text = std::getenv("TCSB_INJECT_STEP_PERCENT");
    if (!text || !*text) return 0.0;
    char* end = nullptr;
    const double percent = std::strtod(text, &end);
    if (*end != '\0' || !(percent >= 0.0 && percent <= 1000.0)) {
      std::fprintf(stderr, "tcsb: error: TCSB_INJECT_STEP_PERCENT: expected a percentage in [0, 1000], got \"%s\"\n",
                   text);
      std::exit(2);
    }
    return percent / 100.0;
  }();
  return fraction;
}
#endif

/// Gate self-test builds only (CMake option TCSB_INJECT_SLOWDOWN): TC-SB's step made p % more expensive in what the
/// run measures (p from TCSB_INJECT_STEP_PERCENT), so the gates can be shown to catch a slowdown of a known fraction
/// of the step, whatever the net. Wall time: a busy-wait of p % of the step's own time so far (t0: when the step
/// began). Instructions (`measure_instructions`): a busy-wait would count differently in every run, so a loop of a
/// fixed number of instructions per Bullet node and link instead, sized from TC-SB's counted instructions per node
/// and link: the count it adds is exact, and `tcsb compare` of the two builds prints it per case. Nothing in other
/// builds: no branch, no clock read.
void injected_step_work([[maybe_unused]] StepClock::time_point t0, [[maybe_unused]] const btSoftBody& body,
                        [[maybe_unused]] bool measure_instructions) {
#if TCSB_INJECT_SLOWDOWN
  const double fraction = injected_fraction();
  if (fraction <= 0.0) return;
  if (measure_instructions) {
    // ci-instructions' TC-SB steps count about 300 instructions per Bullet node plus link (own work and Bullet's
    // step together, 268-308 over its cases), and the loop below about 6 per iteration: with 1 %, `tcsb compare`
    // shows +0.98 to +1.12 % per TC-SB case (docs/methodology.md, "The gates' error rates").
    constexpr double kStepInstructionsPerElement = 300.0;
    constexpr double kLoopInstructions = 6.0;
    const double elements = static_cast<double>(body.m_nodes.size() + body.m_links.size());
    const auto iterations =
        static_cast<std::uint64_t>(fraction * kStepInstructionsPerElement * elements / kLoopInstructions);
    volatile std::uint64_t sink = 0;
    for (std::uint64_t i = 0; i < iterations; ++i) sink = sink + i;
    return;
  }
  const StepClock::time_point now = StepClock::now();
  const auto until = now + std::chrono::duration_cast<StepClock::duration>((now - t0) * fraction);
  while (StepClock::now() < until) {
  }
#endif
}

/// A plain Bullet body: the baseline, stock Bullet, CreatePatch or a uniform grid.
class StockBody final : public CaseBody {
 public:
  StockBody(SceneWorld& world, Body body) : world_(world), body_(std::move(body)) {}
  void step(btScalar dt) override {
    world_.step(dt);
    end_part(StepPart::kBullet);
  }
  const btSoftBody& bullet() const override { return *body_.bullet; }

 private:
  SceneWorld& world_;
  Body body_;
};

/// TC-SB with its controller (none at NoCompression: the body then never changes its cut).
class TreeCutBody final : public CaseBody {
 public:
  TreeCutBody(SceneWorld& world, Body body) : world_(world), body_(std::move(body)), tc_(*body_.tc) {}
  void step(btScalar dt) override {
    // Five clock reads a step (tens of ns against a step of 0.1 ms and more), none inside Bullet's loops.
    Controller* controller = body_.controller.get();
    const StepClock::time_point t0 = StepClock::now();
    tc_.advance_blends(OrderSettling::kByCaller);
    const StepClock::time_point t1 = StepClock::now();
    if (controller) controller->before_step(tc_);
    tc_.settle_order();  // (the controllers settle before their snapshot already: then a no-op)
    const StepClock::time_point t2 = StepClock::now();
    end_part(StepPart::kOwn);
    world_.step(dt);
    end_part(StepPart::kBullet);
    const StepClock::time_point t3 = StepClock::now();
    if (controller) controller->after_step(tc_);
    injected_step_work(t0, tc_, counting());
    const StepClock::time_point t4 = StepClock::now();
    end_part(StepPart::kOwn);
    phases_ = {ms_between(t0, t1), ms_between(t1, t2) + ms_between(t3, t4), ms_between(t2, t3)};
  }
  const StepPhases* phases() const override { return &phases_; }
  const btSoftBody& bullet() const override { return tc_; }
  int interpolations() const override { return tc_.interpolations(); }
  FeedbackCost feedback_cost() const override {
    return body_.controller ? body_.controller->last_cost() : FeedbackCost{};
  }
  TcSoftBody* tc() override { return &tc_; }
  void pause() override {
    if (body_.controller) body_.controller->pause();
  }
  void resume() override {
    if (body_.controller) body_.controller->resume();
  }

 private:
  SceneWorld& world_;
  Body body_;
  TcSoftBody& tc_;
  StepPhases phases_;
};

}  // namespace

int target_node_count(const Net& net, const CaseKey& key) {
  if ((key.method != Method::kTcsb && key.method != Method::kPlainEqual) || !key.compression) return 0;
  return node_budget(net, *key.compression);
}

BodySpec case_body_spec(const CaseKey& key) {
  BodySpec spec;
  spec.compression = key.compression.value_or(0.0);  // (node budget 0, as target_node_count, without a target)
  switch (key.method) {
    case Method::kPlain: spec.kind = BodyKind::kPlain; break;
    case Method::kStock:
      spec.kind = BodyKind::kPlain;
      spec.stock_solver = true;
      break;
    case Method::kBulletPatch: spec.kind = BodyKind::kBulletPatch; break;
    // The fidelity pass's uniform grid, sized by the budget, not by TC-SB's measured mean node count, which is known
    // only after TC-SB ran (it holds the budget, blends included, so it stays at most that).
    case Method::kPlainEqual: spec.kind = BodyKind::kUniform; break;
    case Method::kTcsb: spec.kind = BodyKind::kTcsb; break;
  }
  return spec;
}

std::unique_ptr<CaseBody> make_case_body(const Suite& suite, const CaseKey& key, SceneWorld& world,
                                         std::shared_ptr<const Net> net, std::uint64_t seed) {
  const BodySpec spec = case_body_spec(key);
  Body body = make_body(suite, spec, world, std::move(net), seed);
  if (spec.kind == BodyKind::kTcsb) return std::make_unique<TreeCutBody>(world, std::move(body));
  return std::make_unique<StockBody>(world, std::move(body));
}

}  // namespace tcsb
