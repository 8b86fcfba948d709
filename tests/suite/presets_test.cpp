// The library's presets (feedback/presets.h) are the settings of the suites that measure their kinds of scene: one
// recommendation, in the library, in the suites and in docs/library.md alike.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "feedback/presets.h"
#include "suite/suite.h"

namespace tcsb {
namespace {

void expect_suite_matches(const Preset& p, const std::string& suite_name) {
  SCOPED_TRACE(suite_name);
  const Suite s = parse_suite(std::filesystem::path(TCSB_SOURCE_DIR) / "suites" / (suite_name + ".json"));
  EXPECT_EQ(p.solver.piterations, s.solver.piterations);
  EXPECT_EQ(p.solver.viterations, s.solver.viterations);
  EXPECT_EQ(p.solver.diterations, s.solver.diterations);
  EXPECT_EQ(p.solver.damping, s.solver.damping);
  EXPECT_EQ(p.solver.linear_stiffness, s.solver.linear_stiffness);

  EXPECT_EQ(p.tcsb.blend_steps, s.tcsb.blend_steps);
  EXPECT_EQ(p.tcsb.start_level, s.tcsb.start_level);
  EXPECT_EQ(p.tcsb.placement, s.tcsb.placement);
  EXPECT_EQ(p.tcsb.interfaces, s.tcsb.interfaces);
  EXPECT_EQ(p.tcsb.masses, s.tcsb.masses);
  EXPECT_EQ(p.tcsb.restore_order, s.tcsb.restore_order);
  EXPECT_EQ(p.tcsb.restore_order_min_nodes, s.tcsb.restore_order_min_nodes);
  EXPECT_EQ(p.tcsb.exact_order, s.tcsb.exact_order);
  EXPECT_EQ(p.tcsb.rebuild_dbvt, s.tcsb.rebuild_dbvt);
  EXPECT_EQ(p.tcsb.arrivals_collide, s.tcsb.arrivals_collide);

  const FeedbackSettings& a = p.feedback;
  const FeedbackSettings& b = s.feedback;
  EXPECT_EQ(a.policy, b.policy);
  EXPECT_EQ(a.threshold, b.threshold);
  EXPECT_EQ(a.max_ops_per_step, b.max_ops_per_step);
  EXPECT_EQ(a.evaluation_interval, b.evaluation_interval);
  EXPECT_EQ(a.global_motion_scale, b.global_motion_scale);
  EXPECT_EQ(a.illumination, b.illumination);
  EXPECT_EQ(a.light_direction, b.light_direction);
  EXPECT_EQ(a.parallel, b.parallel);
  EXPECT_EQ(a.threads, b.threads);
  EXPECT_EQ(a.max_step_ms, b.max_step_ms);
  EXPECT_EQ(a.popping_charge, b.popping_charge);
  EXPECT_EQ(a.interface_charge, b.interface_charge);
  EXPECT_EQ(a.interface_tension, b.interface_tension);
  EXPECT_EQ(a.pin_level_pull, b.pin_level_pull);
  EXPECT_EQ(a.contact_saliency, b.contact_saliency);
  EXPECT_EQ(a.view, b.view);
  EXPECT_EQ(a.view_motion_scale, b.view_motion_scale);
  EXPECT_EQ(a.view_detail_px, b.view_detail_px);
  EXPECT_EQ(a.view_static_share, b.view_static_share);
  for (const NetSpec& net : s.nets) EXPECT_EQ(p.lod_rest, net.lod_rest) << net.name;
}

TEST(Presets, AreTheSettingsOfTheSuitesThatMeasureThem) {
  expect_suite_matches(hanging_cloth_preset(), "converged");
  expect_suite_matches(drape_preset(), "drape");
  expect_suite_matches(flag_preset(), "flag");
  expect_suite_matches(close_up_preset(), "viewer-corner");
}

}  // namespace
}  // namespace tcsb
