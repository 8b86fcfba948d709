// The fidelity pass end to end on a tiny suite: TC-SB without compression is the reference (zero error, exactly),
// the TC-SB subject retraces the timed case, the switch follows TC-SB's convergence, a net at rest is reproduced by
// every method, and nothing non-finite comes out.
#include "fidelity/fidelity_runner.h"

#include <gtest/gtest.h>

#include <cmath>

#include "fidelity/converged_reference.h"
#include "paper/fidelity_tables.h"
#include "run/runner.h"

namespace tcsb {
namespace {

Suite tiny_suite(double gravity) {
  Suite s;
  s.name = std::string("tiny");  // moved in: GCC 12 -Wrestrict false positive on literal assignment
  NetSpec n;
  n.width = n.height = 17;
  s.nets = {n};
  s.methods = {Method::kPlain, Method::kTcsb};
  s.compression = {1.0, 0.5};
  s.world.gravity = gravity;
  s.steps = 40;
  s.warmup_steps = 30;
  s.repetitions = 1;
  s.feedback.max_ops_per_step = 16;
  s.fidelity.enabled = true;
  s.fidelity.ablations = true;
  s.fidelity.pareto_targets = {0.25};
  return s;
}

const FidelityCase& find(const FidelityResult& r, std::string_view method, double compression) {
  for (const FidelityCase& c : r.cases)
    if (c.subject.method == method && c.subject.body.compression == compression) return c;
  ADD_FAILURE() << method << "@" << compression << " missing";
  return r.cases.front();
}

void expect_all_finite(const MetricSummary& m) {
  EXPECT_TRUE(std::isfinite(m.mean) && std::isfinite(m.p95) && std::isfinite(m.max));
}

TEST(FidelityPass, TcsbWithoutCompressionIsTheReferenceExactly) {
  const Suite s = tiny_suite(9.81);
  const RunResult run = run_suite(s, Context{});
  ASSERT_TRUE(run.fidelity);
  const FidelityResult& f = *run.fidelity;
  EXPECT_EQ(f.cases.size(), fidelity_plan(s).size());
  const FidelityCase& full = find(f, "tcsb", 1.0);
  EXPECT_EQ(full.status, "ok");
  EXPECT_EQ(full.rms_pct.count, 40u);
  EXPECT_EQ(full.popping_pct.count, 70u);  // popping: every step, warm-up included
  EXPECT_EQ(full.rms_pct.max, 0.0);
  EXPECT_EQ(full.max_pct.max, 0.0);
  EXPECT_EQ(full.weighted_rms_pct.max, 0.0);
  EXPECT_EQ(full.popping_pct.max, 0.0);
  EXPECT_EQ(full.energy_drift_pct.max, 0.0);
  // Compressed TC-SB and the ablations really differ from the reference: the pass can report an error.
  EXPECT_GT(find(f, "tcsb", 0.25).rms_pct.mean, 0.0);
  EXPECT_GT(find(f, "uniform_grid", 0.5).rms_pct.mean, 0.0);
  for (const FidelityCase& c : f.cases) {
    EXPECT_EQ(c.status, "ok") << c.subject.method << "@" << c.subject.body.compression;
    for (const MetricSummary* m : {&c.rms_pct, &c.max_pct, &c.weighted_rms_pct, &c.popping_pct, &c.energy_drift_pct})
      expect_all_finite(*m);
    EXPECT_GT(c.step_ms, 0.0);
    EXPECT_GT(c.reference_step_ms, 0.0);
  }
}

TEST(FidelityPass, TcsbSubjectRetracesTheTimedCaseAndTheSwitchFollowsItsConvergence) {
  const Suite s = tiny_suite(9.81);
  const RunResult run = run_suite(s, Context{});
  ASSERT_TRUE(run.fidelity);
  for (const CaseResult& c : run.cases) {
    if (c.key.method != Method::kTcsb) continue;
    EXPECT_EQ(find(*run.fidelity, "tcsb", *c.key.compression).final_state_hash, c.repetitions.front().final_state_hash)
        << c.label;
  }
  const FidelityCase& tc = find(*run.fidelity, "tcsb", 0.5);
  const FidelityCase& sw = find(*run.fidelity, "switch_body", 0.5);
  ASSERT_TRUE(tc.converged_step);
  EXPECT_LT(*tc.converged_step, s.warmup_steps);
  EXPECT_EQ(sw.switch_step, tc.converged_step);
  ASSERT_TRUE(sw.switch_ms);
  EXPECT_GT(*sw.switch_ms, 0.0);
  EXPECT_EQ(sw.grid, "12x12");  // round(sqrt(0.5 * 289)) = 12: 144 nodes for a budget of 145
  EXPECT_NEAR(sw.mean_nodes, 144.0, 1e-9);
  EXPECT_NEAR(find(*run.fidelity, "uniform_grid", 0.5).mean_nodes, 144.0, 1e-9);
}

TEST(FidelityPass, EveryMethodReproducesANetAtRest) {
  const RunResult run = run_suite(tiny_suite(0.0), Context{});
  ASSERT_TRUE(run.fidelity);
  for (const FidelityCase& c : run.fidelity->cases) {
    const std::string what = std::string(c.subject.method) + "@" + std::to_string(c.subject.body.compression);
    EXPECT_EQ(c.status, "ok") << what;
    EXPECT_LT(c.max_pct.max, 1e-4) << what;           // % of the extent: under 8 um
    EXPECT_LT(c.popping_pct.max, 1e-4) << what;       // operations and the switch on a resting net do not pop
    EXPECT_EQ(c.energy_drift_pct.count, 0u) << what;  // no gravity: initial energy 0, drift undefined, left out
  }
  const std::vector<FidelityRow> rows = fidelity_rows(*run.fidelity);
  EXPECT_FALSE(rows.empty());
}

TEST(FidelityPass, NotRunWhenDisabled) {
  Suite s = tiny_suite(9.81);
  s.fidelity.enabled = false;
  EXPECT_FALSE(run_suite(s, Context{}).fidelity);
}

TEST(FidelityPass, FloorsPerNetAreSmallNonNegativeAndZeroAtFullResolution) {
  const Suite s = tiny_suite(9.81);
  const RunResult run = run_suite(s, Context{});
  ASSERT_TRUE(run.fidelity);
  ASSERT_EQ(run.fidelity->floors.size(), 1u);
  const FidelityFloors& f = run.fidelity->floors.front();
  EXPECT_EQ(f.net_name, s.nets.front().name);
  EXPECT_EQ(f.noise_rms_pct.count, 40u);  // every measured step
  EXPECT_GE(f.noise_rms_pct.mean, 0.0);
  EXPECT_LT(f.noise_rms_pct.max, 0.01);  // 1e-6 of the extent, grown over 70 steps: far below any subject's error
  // One floor per distinct budget of the plan, ascending: 0.25 (Pareto), 0.5, 1.
  ASSERT_EQ(f.interpolation.size(), 3u);
  EXPECT_EQ(f.interpolation[0].compression, 0.25);
  EXPECT_EQ(f.interpolation[2].compression, 1.0);
  EXPECT_EQ(f.interpolation[2].grid, "17x17");
  EXPECT_EQ(f.interpolation[2].rms_pct.count, 40u);
  EXPECT_EQ(f.interpolation[2].rms_pct.max, 0.0);   // the full-resolution grid loses nothing
  EXPECT_GT(f.interpolation[1].rms_pct.mean, 0.0);  // a sagging cloth is not bilinear over a coarse grid
  EXPECT_GT(f.interpolation[0].rms_pct.mean, f.interpolation[1].rms_pct.mean);  // coarser loses more
  // Each row stands beside the floors of its budget (one net: its own).
  for (const FidelityRow& r : fidelity_rows(*run.fidelity)) {
    ASSERT_TRUE(r.noise_floor_pct && r.interpolation_floor_pct) << r.method << "@" << r.compression;
    EXPECT_EQ(*r.noise_floor_pct, f.noise_rms_pct.mean);
    for (const InterpolationFloor& i : f.interpolation) {
      if (i.compression == r.compression) {
        EXPECT_EQ(*r.interpolation_floor_pct, i.rms_pct.mean);
      }
    }
  }
}

TEST(FidelityPass, ACompliantSuiteIsMeasuredAgainstItsConvergedReference) {
  // Under the compliant material the reference is full resolution at the small steps the doubling search ends at,
  // and stock Bullet and the uniform grid are subjects; TC-SB without compression (the suite's small steps) then
  // errs against it, where under Bullet's model it is the reference exactly.
  Suite s = tiny_suite(9.81);
  s.nets[0].mass_mode = MassMode::kDensity;
  s.nets[0].mass = 0.1;
  s.nets[0].lod_rest = RestPlacement::kVertex;
  s.tcsb.masses = Masses::kCut;
  s.tcsb.interfaces = Interfaces::kHanging;
  s.fidelity.ablations = false;
  s.steps = 20;
  s.warmup_steps = 10;
  s.solver.model = MaterialModel::kCompliant;
  s.solver.compliant.stretch_stiffness = 50;
  s.solver.compliant.density = 0.1;
  s.solver.compliant.substeps = 4;
  const RunResult run = run_suite(s, Context{});
  ASSERT_TRUE(run.fidelity);
  const FidelityResult& f = *run.fidelity;
  ASSERT_EQ(f.floors.size(), 1u);
  ASSERT_TRUE(f.floors[0].reference);
  const ReferenceSubsteps& r = *f.floors[0].reference;
  ASSERT_FALSE(r.doublings.empty());
  EXPECT_EQ(r.doublings.front().substeps, 4);
  EXPECT_GE(r.substeps, 4);
  EXPECT_LE(r.substeps, 4 << kMaxReferenceDoublings);
  for (std::size_t k = 1; k < r.doublings.size(); ++k)
    EXPECT_EQ(r.doublings[k].substeps, 2 * r.doublings[k - 1].substeps);
  EXPECT_EQ(r.converged, r.doublings.back().change_rms_pct <= r.doublings.back().noise_rms_pct);
  EXPECT_EQ(find(f, "stock_bullet", 1.0).status, "ok");
  EXPECT_EQ(find(f, "uniform_grid", 0.5).status, "ok");
  const FidelityCase& full = find(f, "tcsb", 1.0);
  EXPECT_EQ(full.status, "ok");
  EXPECT_EQ(full.rms_pct.max > 0.0, r.substeps != 4);  // its own small steps' error, unless they converged already
}

/// The points of the reference the camera counts at full resolution (TC-SB without compression), mean over steps.
Camera below_the_corners(int occlusion_cell_px) {
  Camera c;
  c.pose = {{0, 5.5, 14}, {0, 7, 0}};  // below the cloth's corners, looking up at it from beside the net
  c.fov_deg = 60;
  c.width_px = 320;
  c.height_px = 240;
  c.occlusion_cell_px = occlusion_cell_px;
  return c;
}

double points_counted(Suite s, int occlusion_cell_px) {
  s.scene.camera = below_the_corners(occlusion_cell_px);
  s.fidelity.ablations = false;
  s.fidelity.pareto_targets.clear();
  const RunResult run = run_suite(s, Context{});
  const FidelityCase& full = find(*run.fidelity, "tcsb", 1.0);
  EXPECT_TRUE(full.screen);
  return full.screen ? full.screen->points_in_view : 0.0;
}

TEST(FidelityPass, WithOcclusionThePixelErrorCountsOnlyThePointsTheCameraSees) {
  // Flat (no gravity), the sheet seen obliquely hides none of itself: the tolerance of a link's length keeps a surface
  // from hiding its own points. Sagging between its pinned corners, it is a dome seen from below: its far side hides
  // behind its near side.
  const double flat = points_counted(tiny_suite(0.0), 0);
  EXPECT_GT(flat, 0.0);
  EXPECT_EQ(points_counted(tiny_suite(0.0), 1), flat);
  const double sagging = points_counted(tiny_suite(9.81), 0);
  const double seen = points_counted(tiny_suite(9.81), 1);
  EXPECT_LT(seen, 0.9 * sagging);
  EXPECT_GT(seen, 0.2 * sagging);
}

TEST(FidelityPass, WithOcclusionTheWeightsHideWhatTheReferencesSurfaceHides) {
  // The uniform grid does not depend on the feedback, so only its weights (the reference's saliency with the view
  // terms) can tell the two runs apart: its error is the same, its weighted error is not.
  const auto uniform_grid = [](int occlusion_cell_px) {
    Suite s = tiny_suite(9.81);
    s.feedback.view = true;
    s.scene.camera = below_the_corners(occlusion_cell_px);
    s.fidelity.pareto_targets.clear();
    const RunResult run = run_suite(s, Context{});
    return find(*run.fidelity, "uniform_grid", 0.5);
  };
  const FidelityCase see_through = uniform_grid(0), occluded = uniform_grid(1);
  EXPECT_EQ(occluded.rms_pct.mean, see_through.rms_pct.mean);
  EXPECT_NE(occluded.weighted_rms_pct.mean, see_through.weighted_rms_pct.mean);
}

}  // namespace
}  // namespace tcsb
