#include "case/body_factory.h"

#include <cmath>
#include <stdexcept>

#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "suite/fidelity_plan.h"

namespace tcsb {

namespace {

/// The suite's TC-SB settings changed where `spec` says.
TcSettings body_tc_settings(const Suite& suite, const BodySpec& spec) {
  TcSettings tc = suite.tcsb;
  if (spec.placement) tc.placement = *spec.placement;
  if (spec.interfaces) tc.interfaces = *spec.interfaces;
  if (spec.calibration == BodyCalibration::kSuite) {
    if (!suite.calibration) throw std::invalid_argument("calibrated TC-SB: the suite has no calibration");
    tc.level_stiffness = suite.calibration->level_stiffness();
  }
  if (spec.whole_level > 0) tc.start_level = 0;  // the whole cut is set below, whatever cut the suite starts at
  return tc;
}

/// The suite's feedback settings changed where `spec` says.
FeedbackSettings body_feedback_settings(const Suite& suite, const BodySpec& spec) {
  FeedbackSettings feedback = suite.feedback;
  if (spec.policy) feedback.policy = *spec.policy;
  if (spec.view_terms) feedback.view = *spec.view_terms;
  return feedback;
}

Body make_tcsb_body(const Suite& suite, const BodySpec& spec, SceneWorld& world, Body body, std::uint64_t seed) {
  auto tc =
      std::make_unique<TcSoftBody>(world.info(), body.net, body_solver(suite, spec), body_tc_settings(suite, spec));
  if (spec.whole_level > 0) tc->coarsen_to_level(spec.whole_level);
  // The suite's spectator even where the spec turns the view terms off: what the suite's own body sees through.
  if (body.budget < static_cast<int>(body.net->node_count()))
    body.controller = make_controller(body_feedback_settings(suite, spec), body.budget, seed, suite_spectator(suite));
  body.tc = tc.get();
  body.bullet = std::move(tc);
  return body;
}

}  // namespace

int node_budget(const Net& net, double compression) {
  return static_cast<int>(std::lround(compression * static_cast<double>(net.node_count())));
}

SolverSettings body_solver(const Suite& suite, const BodySpec& spec) {
  SolverSettings solver = spec.stock_solver ? stock_bullet(suite.solver) : suite.solver;
  if (spec.solver_divisor != 1) solver = with_passes_divided(solver, spec.solver_divisor);
  if (spec.calibration == BodyCalibration::kSuite && spec.kind == BodyKind::kUniform) {
    const std::optional<double> k =
        suite.calibration ? suite.calibration->uniform_stiffness(spec.compression) : std::nullopt;
    if (!k) throw std::invalid_argument("calibrated uniform grid: the calibration has no fit for this budget");
    solver.linear_stiffness = *k;
  }
  return solver;
}

Body make_body(const Suite& suite, const BodySpec& spec, SceneWorld& world, std::shared_ptr<const Net> net,
               std::uint64_t seed) {
  Body body;
  body.budget = node_budget(*net, spec.compression);
  body.net = std::move(net);
  switch (spec.kind) {
    case BodyKind::kPlain:
    case BodyKind::kSwitch: body.bullet = make_plain_softbody(world.info(), *body.net, body_solver(suite, spec)); break;
    case BodyKind::kBulletPatch:
      body.bullet = make_bullet_patch(world.info(), *body.net, body_solver(suite, spec));
      break;
    case BodyKind::kUniform:
      body.net = std::make_shared<const Net>(coarse_net_spec(body.net->spec(), body.budget));
      body.bullet = make_plain_softbody(world.info(), *body.net, body_solver(suite, spec));
      break;
    case BodyKind::kTcsb: body = make_tcsb_body(suite, spec, world, std::move(body), seed); break;
  }
  body.attachment = world.attach(*body.bullet);
  return body;
}

}  // namespace tcsb
