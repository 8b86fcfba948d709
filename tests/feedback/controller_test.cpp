#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "feedback/budget_policy.h"
#include "feedback/controller.h"
#include "feedback/saliency_controller.h"
#include "fixed_field.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/tc_softbody_impl.h"

#include "../softbody/test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

std::shared_ptr<const Net> net_of(int width) {
  NetSpec spec;
  spec.width = spec.height = width;
  return std::make_shared<const Net>(spec);
}

TEST(BudgetPolicy, ThresholdPreventsOscillationOnAConstantField) {
  // A fixed saliency field (a bump in one quadrant), evaluated afresh every step: once the cut has settled, no
  // operation may begin any more — without the threshold, refines and coarsens of equal worth would alternate.
  const auto net = net_of(33);
  testing::StillBody still(net);
  TcSoftBody& body = still.body;
  FeedbackSettings settings;
  settings.max_ops_per_step = 16;
  BudgetState state;
  const int budget = 500;
  const std::vector<int> ops_per_step = testing::run_on_fixed_field(
      body, settings, budget, 400,
      [&](TreeId id) {
        const Eigen::Vector3d& r = net->lod().rest(id);
        return static_cast<float>(std::exp(-((r.x() - 2) * (r.x() - 2) + (r.z() - 2) * (r.z() - 2))));
      },
      state);
  EXPECT_TRUE(state.converged);
  int late_ops = 0;
  for (std::size_t i = 300; i < ops_per_step.size(); ++i) late_ops += ops_per_step[i];
  EXPECT_EQ(late_ops, 0) << "the cut keeps changing on a constant field";
  // And the salient quadrant kept its detail: the node at the bump is finer than the far corner's.
  const TreeId at_bump = net->index(24, 24), far = net->index(4, 4);
  auto active_level = [&](TreeId leaf) {
    for (TreeId id = leaf; id != kNoTreeNode; id = net->lod().node(id).parent)
      if (body.committed(id)) return static_cast<int>(net->lod().node(id).level);
    return -1;
  };
  EXPECT_LT(active_level(at_bump), active_level(far));
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
}

struct Trace {
  std::vector<int> n, l, i;
  int most_displaced_at_step = 0;  ///< displaced() right before a step, at most
  int restorations = 0;            ///< restore_order() runs over the whole run
  std::vector<btVector3> final_positions;
};

/// `pause_every` > 0: the controller is paused and resumed before every such step, as the fidelity pass does
/// between its blocks.
Trace run_swinging(const FeedbackSettings& settings, int steps, int pause_every = 0, const TcSettings& tc = {},
                   OrderSettling settling = OrderSettling::kNow) {
  const auto net = net_of(33);
  SceneWorld world({});
  SolverSettings solver;
  solver.piterations = 2;
  TcSoftBody body(world.info(), net, solver, tc);
  SaliencyController controller(settings, 400);
  Trace t;
  for (int s = 0; s < steps; ++s) {
    if (pause_every > 0 && s % pause_every == 0) {
      controller.pause();
      controller.resume();
    }
    body.advance_blends(settling);
    controller.before_step(body);
    body.settle_order();  // as the runner's loops do (a no-op after OrderSettling::kNow and the controller's own)
    t.most_displaced_at_step = std::max(t.most_displaced_at_step, body.impl().displaced());
    body.simulate_step(kDt);
    controller.after_step(body);
    t.n.push_back(body.node_count());
    t.l.push_back(body.link_count());
    t.i.push_back(body.interpolations());
    if (controller.converged()) {
      EXPECT_LE(body.node_count(), controller.budget()) << "step " << s;
    }
  }
  EXPECT_TRUE(controller.converged());
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
  for (int k = 0; k < body.node_count(); ++k) t.final_positions.push_back(body.m_nodes[k].m_x);
  t.restorations = body.impl().order_restorations();
  return t;
}

TEST(SaliencyController, HoldsTheNodeBudgetAndIsIdenticalSyncAndParallel) {
  FeedbackSettings sync;
  sync.max_ops_per_step = 32;
  const Trace reference = run_swinging(sync, 300);
  int changed = 0;
  for (std::size_t s = 1; s < reference.n.size(); ++s) changed += reference.n[s] != reference.n[s - 1];
  EXPECT_GT(changed, 10) << "the feedback loop should be changing the cut while the net swings";
  for (int threads : {1, 2, 3}) {
    for (int pause_every : {0, 20}) {  // with and without the worker parked and woken again
      FeedbackSettings parallel = sync;
      parallel.parallel = true;
      parallel.threads = threads;
      const Trace t = run_swinging(parallel, 300, pause_every);
      const std::string what = std::to_string(threads) + " threads, pause every " + std::to_string(pause_every);
      EXPECT_EQ(t.n, reference.n) << what;
      EXPECT_EQ(t.l, reference.l) << what;
      EXPECT_EQ(t.i, reference.i) << what;
      ASSERT_EQ(t.final_positions.size(), reference.final_positions.size());
      for (std::size_t k = 0; k < t.final_positions.size(); ++k)
        ASSERT_EQ(t.final_positions[k], reference.final_positions[k]) << what << ", node " << k;
    }
  }
}

TEST(SaliencyController, WithExactOrderEveryStepStartsInAPlainBodysOrderAndParallelStaysIdentical) {
  // The controller settles the order after beginning its operations and before its worker reads the cut
  // (TcSettings::exact_order): no step begins displaced, and the worker never sees the arrays move under it.
  TcSettings tc;
  tc.exact_order = true;
  FeedbackSettings sync;
  sync.max_ops_per_step = 32;
  const Trace reference = run_swinging(sync, 300, 0, tc);
  EXPECT_EQ(reference.most_displaced_at_step, 0);
  EXPECT_GT(run_swinging(sync, 300).most_displaced_at_step, 0);  // without it the operations leave their order
  FeedbackSettings parallel = sync;
  parallel.parallel = true;
  const Trace t = run_swinging(parallel, 300, 0, tc);
  EXPECT_EQ(t.n, reference.n);
  EXPECT_EQ(t.l, reference.l);
  ASSERT_EQ(t.final_positions.size(), reference.final_positions.size());
  for (std::size_t k = 0; k < t.final_positions.size(); ++k)
    ASSERT_EQ(t.final_positions[k], reference.final_positions[k]) << "node " << k;
}

TEST(SaliencyController, WithExactOrderOneRestorePerBoundaryGivesTheSameCloth) {
  // OrderSettling::kByCaller: the operations advance_blends() ends and those the controller begins are put in order
  // by one restore instead of two; restore_order() makes one order of any arrangement, so nothing else changes.
  TcSettings tc;
  tc.exact_order = true;
  tc.blend_steps = 4;  // as the bundled suites: operations end at the boundaries where the next evaluation's begin
  FeedbackSettings settings;
  settings.max_ops_per_step = 32;
  settings.evaluation_interval = 4;
  for (const bool parallel : {false, true}) {
    settings.parallel = parallel;
    const Trace twice = run_swinging(settings, 300, 0, tc, OrderSettling::kNow);
    const Trace once = run_swinging(settings, 300, 0, tc, OrderSettling::kByCaller);
    EXPECT_EQ(once.most_displaced_at_step, 0);
    EXPECT_LT(once.restorations, twice.restorations);
    EXPECT_EQ(once.n, twice.n);
    EXPECT_EQ(once.l, twice.l);
    EXPECT_EQ(once.i, twice.i);
    ASSERT_EQ(once.final_positions.size(), twice.final_positions.size());
    for (std::size_t k = 0; k < once.final_positions.size(); ++k)
      ASSERT_EQ(once.final_positions[k], twice.final_positions[k]) << "node " << k << (parallel ? ", parallel" : "");
  }
}

TEST(SaliencyController, ATimeBudgetLowersTheNodeBudget) {
  // A step can never take 1 ns, so the time budget must keep shrinking the node budget: a mechanism check, not a
  // timing assertion (any real step is slower than the target).
  FeedbackSettings settings;
  settings.max_step_ms = 1e-6;
  const auto net = net_of(17);
  SceneWorld world({});
  TcSoftBody body(world.info(), net, {}, {});
  SaliencyController controller(settings, 250);
  for (int s = 0; s < 60; ++s) {
    body.advance_blends();
    controller.before_step(body);
    body.simulate_step(kDt);
    controller.after_step(body);
  }
  EXPECT_LT(controller.budget(), 250 / 2);
  EXPECT_LT(body.committed_count(), 250);
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
}

TEST(SaliencyController, ATimeBudgetDoesNotCountAPauseAsAStep) {
  // The fidelity pass pauses a body while the others run their blocks. Counted as a step period, this 300 ms pause
  // would lift the step-time average above the 20 ms target (0.1 x 300 ms) and cut the node budget; a 17 x 17 net's
  // real steps take well under a millisecond, so nothing else can.
  FeedbackSettings settings;
  settings.max_step_ms = 20;
  const auto net = net_of(17);
  SceneWorld world({});
  TcSoftBody body(world.info(), net, {}, {});
  SaliencyController controller(settings, 250);
  const auto step = [&] {
    body.advance_blends();
    controller.before_step(body);
    body.simulate_step(kDt);
    controller.after_step(body);
  };
  for (int s = 0; s < 10; ++s) step();
  ASSERT_EQ(controller.budget(), 250);
  controller.pause();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  controller.resume();
  for (int s = 0; s < 3; ++s) step();
  EXPECT_EQ(controller.budget(), 250);
}

TEST(SaliencyController, AnEvaluationThatThrowsReachesTheSimulationThreadInBothModes) {
  // A camera looking along its up direction (the parser and make_controller refuse it; the controller itself takes
  // it as given) makes every evaluation throw. Synchronous, before_step throws; parallel, the worker's exception is
  // rethrown at the join in after_step — and destroying the controller afterwards returns: before, the worker died
  // (std::terminate) or the destructor waited forever for a job that would never finish.
  Camera camera;
  camera.pose = {{0, 5, 0}, {0, 0, 0}};
  const auto net = net_of(17);
  for (const bool parallel : {false, true}) {
    SCOPED_TRACE(parallel ? "parallel" : "synchronous");
    FeedbackSettings settings;
    settings.view = true;
    settings.parallel = parallel;
    SceneWorld world({});
    TcSoftBody body(world.info(), net, {}, {});
    auto controller = std::make_unique<SaliencyController>(settings, 200, Spectator{camera, kDt});
    EXPECT_THROW(
        {
          for (int s = 0; s < 3; ++s) {
            body.advance_blends();
            controller->before_step(body);
            body.simulate_step(kDt);
            controller->after_step(body);
          }
        },
        std::invalid_argument);
    controller.reset();
  }
}

/// The message of the std::invalid_argument `make` throws ("" if it throws none).
template <class Make>
std::string refusal(Make make) {
  try {
    make();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MakeController, RefusesImpossibleFeedbackSettingsNamingTheField) {
  // Issue 60: evaluation_interval = 0 was a SIGFPE at the first step (boundary % 0); every setting the suite parser
  // bounds is bounded here too, for a library user who fills FeedbackSettings in code.
  const std::vector<std::pair<std::string, std::function<void(FeedbackSettings&)>>> edits = {
      {"evaluation_interval", [](FeedbackSettings& f) { f.evaluation_interval = 0; }},
      {"max_ops_per_step", [](FeedbackSettings& f) { f.max_ops_per_step = 0; }},
      {"threads", [](FeedbackSettings& f) { f.threads = 0; }},
      {"threads", [](FeedbackSettings& f) { f.threads = 1000; }},
      {"threshold", [](FeedbackSettings& f) { f.threshold = -1; }},
      {"threshold", [](FeedbackSettings& f) { f.threshold = std::nan(""); }},
      {"global_motion_scale", [](FeedbackSettings& f) { f.global_motion_scale = 0; }},
      {"light_direction",
       [](FeedbackSettings& f) {
         f.light_direction = {0, 0, 0};
       }},
      {"max_step_ms", [](FeedbackSettings& f) { f.max_step_ms = -1; }},
      {"popping_charge", [](FeedbackSettings& f) { f.popping_charge = -0.5; }},
      {"interface_charge", [](FeedbackSettings& f) { f.interface_charge = INFINITY; }},
      {"interface_tension", [](FeedbackSettings& f) { f.interface_tension = -1; }},
      {"pin_level_pull", [](FeedbackSettings& f) { f.pin_level_pull = -1; }},
      {"contact_saliency", [](FeedbackSettings& f) { f.contact_saliency = 2; }},
      {"view_motion_scale", [](FeedbackSettings& f) { f.view_motion_scale = 0; }},
      {"view_detail_px", [](FeedbackSettings& f) { f.view_detail_px = -8; }},
      {"view_static_share", [](FeedbackSettings& f) { f.view_static_share = 1.5; }},
  };
  for (const auto& [field, edit] : edits) {
    FeedbackSettings settings;
    edit(settings);
    const std::string why = refusal([&] { make_controller(settings, 100, 1); });
    EXPECT_NE(why.find("FeedbackSettings: " + field), std::string::npos) << field << ": " << why;
  }
  EXPECT_EQ(refusal([] { make_controller(FeedbackSettings{}, 100, 1); }), "");
}

TEST(MakeController, RefusesASpectatorThatGivesNoImageNamingTheField) {
  FeedbackSettings settings;
  settings.view = true;
  Camera good;
  good.pose = {{0, 5, 10}, {0, 0, 0}};
  EXPECT_EQ(refusal([&] { make_controller(settings, 100, 1, Spectator{good, kDt}); }), "");
  const std::vector<std::pair<std::string, std::function<void(Spectator&)>>> edits = {
      {"dt", [](Spectator& s) { s.dt = 0; }},
      {"camera.fov_deg", [](Spectator& s) { s.camera.fov_deg = 180; }},
      {"camera.width_px", [](Spectator& s) { s.camera.height_px = 0; }},
      {"camera.occlusion_cell_px", [](Spectator& s) { s.camera.occlusion_cell_px = -1; }},
      {"camera.occlusion_cell_px", [](Spectator& s) { s.camera.occlusion_cell_px = Camera::kMaxOcclusionCellPx + 1; }},
      {"camera.up",
       [](Spectator& s) {
         s.camera.up = {0, 0, 0};
       }},
      {"camera.pose.target", [](Spectator& s) { s.camera.pose.target = s.camera.pose.position; }},
      {"camera.pose.target",
       [](Spectator& s) {
         s.camera.pose = {{0, 5, 0}, {0, 0, 0}};
       }},
      {"camera.pose.position", [](Spectator& s) { s.camera.pose.position[0] = INFINITY; }},
      {"camera.path[1].time",
       [](Spectator& s) {
         s.camera.path = {{1.0, {{0, 5, 10}, {0, 0, 0}}}, {1.0, {{0, 5, 9}, {0, 0, 0}}}};
       }},
      // A crane shot over the target: both keyframes valid, straight down halfway.
      {"camera.path[1]",
       [](Spectator& s) {
         s.camera.path = {{0.0, {{0, 5, -5}, {0, 0, 0}}}, {2.0, {{0, 5, 5}, {0, 0, 0}}}};
       }},
  };
  for (const auto& [field, edit] : edits) {
    Spectator spectator{good, kDt};
    edit(spectator);
    const std::string why = refusal([&] { make_controller(settings, 100, 1, spectator); });
    EXPECT_NE(why.find("Spectator: " + field), std::string::npos) << field << ": " << why;
  }
}

}  // namespace
}  // namespace tcsb
