// Fixed cuts seen by a view suite's camera: what any cut of a given shape errs in pixels, without the feedback's
// choices in the way. The cloth the reference shows in view is set at one level, the cloth near it at another, the
// rest at a third, at step 0 and left so; beside them the uniform level cut and the calibrated uniform grid, each
// also with its stiffness 1 % off the calibration's. The frontier of docs/investigations/view-cut-frontier.md.
// Under the compliant material (a suite's `material` block) there is no calibration: the cuts and the uniform grid are
// of the suite's one material, the reference is full resolution at kConvergedFactor x the suite's small steps (what
// the fidelity pass's search ends at on these nets), and the mixed cut runs a second time at that many small steps
// too (its iteration independence; docs/investigations/compliant-material.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "analysis/fidelity_metrics.h"
#include "fidelity/fidelity_subject.h"
#include "fidelity/reconstruction.h"
#include "fidelity/screen_error.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody.h"
#include "suite/suite.h"

namespace tcsb {
namespace {

/// The reference's measured frames and, per grid node, on how many of them it was in view.
struct ReferenceRun {
  std::vector<std::vector<Eigen::Vector3d>> frames;
  std::vector<int> steps_in_view;
};

ScreenProjection view_at(const Suite& suite, int step) {
  return view_after_steps(*suite.scene.camera, step + 1, suite.world.dt);
}

/// Under the compliant material, the reference's small steps and the mixed cut's second run's: 8 x the suite's.
constexpr int kConvergedFactor = 8;

/// The suite's solver settings, under the compliant material with `factor` x its small steps.
SolverSettings solver_at(const Suite& suite, int factor) {
  SolverSettings solver = suite.solver;
  solver.compliant.substeps *= factor;
  return solver;
}

ReferenceRun run_reference(const Suite& suite, const std::shared_ptr<const Net>& net) {
  SceneWorld world(suite.world, suite.scene);
  const SolverSettings solver = solver_at(suite, suite.solver.compliant_model() ? kConvergedFactor : 1);
  const auto body = make_plain_softbody(world.info(), *net, solver);
  const SceneWorld::Attachment attachment = world.attach(*body);
  ReferenceRun run;
  run.steps_in_view.assign(net->node_count(), 0);
  std::vector<Eigen::Vector3d> x;
  for (int s = 0; s < suite.warmup_steps + suite.steps; ++s) {
    world.step(static_cast<btScalar>(suite.world.dt));
    if (s < suite.warmup_steps) continue;
    copy_positions(*body, x);
    const ScreenProjection view = view_at(suite, s);
    for (std::size_t i = 0; i < x.size(); ++i)
      if (view.project(x[i]).in_view) ++run.steps_in_view[i];
    run.frames.push_back(x);
  }
  return run;
}

/// One body's error over the measured steps: pixels (mean over steps of the per-step p95) and % RMS.
struct BodyError {
  int nodes = 0;
  double p95_px = 0, rms_pct = 0;
};

/// Runs a body through the suite's steps (`step(s)` advances it by one, `reconstruct` gives its surface) and measures
/// it against the reference on the measured ones.
template <class Step, class Reconstruct>
BodyError measure(const Suite& suite, const Net& net, const ReferenceRun& reference, Step step,
                  Reconstruct reconstruct) {
  std::vector<Eigen::Vector3d> surface;
  std::vector<double> scratch;
  ScreenErrorSeries series;
  double rms = 0;
  for (int s = 0; s < suite.warmup_steps + suite.steps; ++s) {
    step(s);
    if (s < suite.warmup_steps) continue;
    reconstruct(surface);
    const std::vector<Eigen::Vector3d>& truth = reference.frames[static_cast<std::size_t>(s - suite.warmup_steps)];
    series.add(screen_error(view_at(suite, s), surface, truth, {}, scratch));
    rms += surface_error(surface, truth).rms;
  }
  return {0, series.finish().p95_px.mean, 100 * rms / suite.steps / net.extent()};
}

/// Where each grid node (leaf) lies for the camera: 0 in view (the reference shows it on at least `share` of the
/// measured steps), 1 near (at rest within `near_m` of such a leaf), 2 elsewhere. A block takes its finest leaf's.
std::vector<int> leaf_regions(const Net& net, const ReferenceRun& reference, double share, double near_m) {
  const LodTree& tree = net.lod();
  const std::size_t n = net.node_count();
  std::vector<int> region(n, 2);
  std::vector<TreeId> seen;
  for (std::size_t i = 0; i < n; ++i)
    if (reference.steps_in_view[i] >= share * static_cast<double>(reference.frames.size()))
      seen.push_back(static_cast<TreeId>(i));
  for (std::size_t i = 0; i < n; ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const TreeId j : seen) nearest = std::min(nearest, (tree.rest(static_cast<TreeId>(i)) - tree.rest(j)).norm());
    region[i] = nearest == 0 ? 0 : nearest < near_m ? 1 : 2;
  }
  return region;
}

/// The fixed cut whose blocks are at level `levels[r]` for their finest region r (the calibration's level stiffness,
/// level 1's times `level1_scale`), coarsened level by level at step 0.
BodyError fixed_cut(const Suite& suite, const std::shared_ptr<const Net>& net, const ReferenceRun& reference,
                    const std::vector<int>& region, const int (&levels)[3], double level1_scale = 1.0,
                    int substep_factor = 1) {
  SceneWorld world(suite.world, suite.scene);
  TcSettings settings = suite.tcsb;
  settings.start_level = 0;
  if (suite.calibration) {
    settings.level_stiffness = suite.calibration->level_stiffness();
    settings.level_stiffness[0] *= level1_scale;
  }
  TcSoftBody body(world.info(), net, solver_at(suite, substep_factor), settings);
  const LodTree& tree = net->lod();
  for (int level = 1; level < tree.level_count(); ++level)
    for (bool began = true; began;) {
      began = false;
      for (int gy = 0; gy < tree.level_height(level); ++gy)
        for (int gx = 0; gx < tree.level_width(level); ++gx) {
          const TreeId id = tree.at(level, gx, gy);
          int finest = 2;
          for_each_leaf(tree, id,
                        [&](TreeId leaf) { finest = std::min(finest, region[static_cast<std::size_t>(leaf)]); });
          if (levels[finest] >= level && body.can_coarsen(id).ok) {
            body.begin_coarse(id);
            began = true;
          }
        }
      while (body.interpolations() > 0) body.advance_blends();  // no time passes: the next round may begin
    }
  body.settle_order();
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
  const SceneWorld::Attachment attachment = world.attach(body);
  BodyError e = measure(
      suite, *net, reference, [&](int) { world.step(static_cast<btScalar>(suite.world.dt)); },
      [&](std::vector<Eigen::Vector3d>& surface) { reconstruct_leaves(body, surface); });
  e.nodes = body.node_count();
  return e;
}

/// The calibrated uniform grid at `compression`, its stiffness times `scale`.
BodyError uniform_grid(Suite suite, const std::shared_ptr<const Net>& net, const ReferenceRun& reference,
                       double compression, double scale) {
  if (suite.calibration)
    for (StiffnessFit& fit : suite.calibration->uniform_grid) fit.linear_stiffness *= scale;
  SceneWorld world(suite.world, suite.scene);
  const FidelitySubjectSpec spec =
      fidelity_subject(suite.calibration ? "uniform_grid_calibrated" : "uniform_grid", compression);
  const auto grid = make_fidelity_subject(suite, spec.body, world, net, 1, nullptr, suite.warmup_steps);
  BodyError e = measure(
      suite, *net, reference,
      [&](int s) {
        grid->boundary(s);
        grid->simulate(static_cast<btScalar>(suite.world.dt));
      },
      [&](std::vector<Eigen::Vector3d>& surface) { grid->reconstruct(surface); });
  e.nodes = grid->bullet().m_nodes.size();
  return e;
}

// The tables of docs/investigations/view-cut-frontier.md (30 s on suites/viewer-corner.json, 90 s at 128 iterations):
// run with
//   build/tests_fidelity --gtest_also_run_disabled_tests --gtest_filter='FixedViewCuts.DISABLED_*'
// TCSB_FRONTIER_SUITE names another view suite (with its calibration) instead of suites/viewer-corner.json.
TEST(FixedViewCuts, DISABLED_Frontier) {
  const char* other = std::getenv("TCSB_FRONTIER_SUITE");
  const Suite suite = parse_suite(other ? std::filesystem::path(other)
                                        : std::filesystem::path(TCSB_SOURCE_DIR) / "suites/viewer-corner.json");
  const bool compliant = suite.solver.compliant_model();
  ASSERT_TRUE(suite.scene.camera && (suite.calibration || compliant));
  const double compression = 0.3;
  if (compliant)
    std::printf("suite %s, compliant, %d small steps of %d link passes (reference: %d small steps); p95 px (mean "
                "over steps) / %% RMS / nodes (%% of the net)\n\n",
                suite.name.c_str(), suite.solver.compliant.substeps, suite.solver.compliant.passes,
                kConvergedFactor * suite.solver.compliant.substeps);
  else
    std::printf("suite %s, %d solver iterations; p95 px (mean over steps) / %% RMS / nodes (%% of the net)\n\n",
                suite.name.c_str(), suite.solver.piterations);
  // Under the compliant material there is no stiffness to move by 1 %: one row of each.
  const std::vector<double> scales = compliant ? std::vector<double>{1.0} : std::vector<double>{1.0, 0.99, 1.01};
  const std::string grid_name = compliant ? "uniform grid at 30 %" : "calibrated uniform grid at 30 %";
  std::printf("| net | body | nodes | p95 px | RMS %% |\n|---|---|---|---|---|\n");
  for (const NetSpec& spec : suite.nets) {
    const auto net = std::make_shared<const Net>(spec);
    const ReferenceRun reference = run_reference(suite, net);
    const auto row = [&](const std::string& body, const BodyError& e) {
      std::printf("| %s | %s | %d (%.1f %%) | %.3f | %.3f |\n", spec.name.c_str(), body.c_str(), e.nodes,
                  100.0 * e.nodes / static_cast<double>(net->node_count()), e.p95_px, e.rms_pct);
    };
    for (const double scale : scales)
      row(grid_name + ", stiffness x " + std::to_string(scale).substr(0, 4),
          uniform_grid(suite, net, reference, compression, scale));
    const std::vector<int> everywhere(net->node_count(), 2);
    for (const double scale : scales)
      row("level 1 everywhere, stiffness x " + std::to_string(scale).substr(0, 4),
          fixed_cut(suite, net, reference, everywhere, {1, 1, 1}, scale));
    if (compliant) {
      row("level 0 everywhere", fixed_cut(suite, net, reference, everywhere, {0, 0, 0}));
      const std::vector<int> in_view = leaf_regions(*net, reference, 1.0, 1.0);
      row("level 0 in view at every step, level 1 elsewhere, " + std::to_string(kConvergedFactor) +
              " x the small steps",
          fixed_cut(suite, net, reference, in_view, {0, 1, 1}, 1.0, kConvergedFactor));
    }
    for (const double share : {1.0, 0.5}) {
      const std::string seen = share == 1.0 ? "in view at every step" : "in view on half the steps";
      const std::vector<int> regions = leaf_regions(*net, reference, share, 1.0);
      row("level 0 " + seen + ", level 1 elsewhere", fixed_cut(suite, net, reference, regions, {0, 1, 1}));
      row("level 0 " + seen + ", level 1 within 1 m, level 2 elsewhere",
          fixed_cut(suite, net, reference, regions, {0, 1, 2}));
      row("level 0 " + seen + " and within 1 m, level 1 elsewhere",
          fixed_cut(suite, net, reference, regions, {0, 0, 1}));
    }
  }
}

}  // namespace
}  // namespace tcsb
