// The fidelity plan: which subjects run, at which budgets, with which seeds and coarse grids.
#include "suite/fidelity_plan.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <tuple>

#include "fidelity/fidelity_runner.h"
#include "fidelity/fidelity_subject.h"
#include "suite/calibration_file.h"
#include "suite/case_plan.h"

namespace tcsb {
namespace {

Suite suite_with_fidelity(bool ablations) {
  Suite s;
  s.name = std::string("t");  // moved in, not copied from a literal: GCC 12 -Wrestrict false positive
  NetSpec n;
  n.width = n.height = 17;
  s.nets = {n, n};
  s.nets[1].name = std::string("other");
  s.methods = {Method::kPlain, Method::kTcsb};
  s.compression = {1.0, 0.75, 0.3};
  s.fidelity.enabled = true;
  s.fidelity.ablations = ablations;
  s.fidelity.pareto_targets = {0.1, 0.3, 0.5, 1.0};
  return s;
}

TEST(FidelityPlan, TcsbAtEveryTargetOnceAscendingThenTheAblationsBelowOne) {
  const std::vector<FidelitySubjectSpec> plan = fidelity_plan(suite_with_fidelity(true));
  std::vector<std::pair<std::string, double>> got;
  for (const FidelitySubjectSpec& s : plan) got.emplace_back(s.method, s.body.compression);
  const std::vector<std::pair<std::string, double>> want{{"tcsb", 0.1},
                                                         {"tcsb", 0.3},
                                                         {"tcsb", 0.5},
                                                         {"tcsb", 0.75},
                                                         {"tcsb", 1.0},
                                                         {"uniform_grid", 0.75},
                                                         {"uniform_grid", 0.3},
                                                         {"switch_body", 0.75},
                                                         {"switch_body", 0.3},
                                                         {"tcsb_random", 0.75},
                                                         {"tcsb_random", 0.3},
                                                         {"tcsb_rigid", 0.75},
                                                         {"tcsb_rigid", 0.3},
                                                         {"tcsb_no_geomorph", 0.75},
                                                         {"tcsb_no_geomorph", 0.3}};
  EXPECT_EQ(got, want);
}

TEST(FidelityPlan, CalibratedTcsbAtEverySweepTargetBelowOneAndTheCalibratedGridAtTheSuitesTargets) {
  Suite s = suite_with_fidelity(false);
  s.calibration = Calibration{};
  std::vector<std::pair<std::string, double>> got;
  for (const FidelitySubjectSpec& spec : fidelity_plan(s))
    if (spec.method == "tcsb_calibrated" || spec.method == "uniform_grid_calibrated")
      got.emplace_back(spec.method, spec.body.compression);
  const std::vector<std::pair<std::string, double>> want{
      {"tcsb_calibrated", 0.1},  {"tcsb_calibrated", 0.3},          {"tcsb_calibrated", 0.5},
      {"tcsb_calibrated", 0.75}, {"uniform_grid_calibrated", 0.75}, {"uniform_grid_calibrated", 0.3}};
  EXPECT_EQ(got, want);
}

TEST(FidelityPlan, WithHangingInterfacesTheFannedBodyIsAnAblationAtTheSuitesTargets) {
  Suite s = suite_with_fidelity(true);
  s.calibration = Calibration{};
  const auto fans = [](const Suite& suite) {
    std::vector<double> at;
    for (const FidelitySubjectSpec& spec : fidelity_plan(suite))
      if (spec.method == "tcsb_calibrated_fans") at.push_back(spec.body.compression);
    return at;
  };
  EXPECT_TRUE(fans(s).empty());  // the paper's fans are the suite's own TC-SB
  s.tcsb.interfaces = Interfaces::kHanging;
  EXPECT_EQ(fans(s), (std::vector<double>{0.75, 0.3}));
  const BodySpec fanned = fidelity_subject("tcsb_calibrated_fans", 0.3).body;
  EXPECT_EQ(fanned.interfaces, Interfaces::kLinks);
  EXPECT_EQ(fanned.calibration, BodyCalibration::kSuite);
  s.fidelity.ablations = false;
  EXPECT_TRUE(fans(s).empty());
}

TEST(FidelityPlan, EmptyWhenDisabledOrWithoutTcsb) {
  Suite s = suite_with_fidelity(true);
  s.fidelity.enabled = false;
  EXPECT_TRUE(fidelity_plan(s).empty());
  s = suite_with_fidelity(true);
  s.methods = {Method::kPlain};
  EXPECT_TRUE(fidelity_plan(s).empty());
  s = suite_with_fidelity(false);
  EXPECT_EQ(fidelity_plan(s).size(), 5u);  // TC-SB only
}

TEST(FidelityPlan, CurvesAddTheGridsAtEveryBudgetAndFullResolutionAtEveryDivisor) {
  Suite s = suite_with_fidelity(false);
  s.fidelity.pareto_targets.clear();
  s.fidelity.curves = FidelityCurves{{0.1, 0.5}, {2, 4}};
  std::vector<std::tuple<std::string, double, int>> got;
  for (const FidelitySubjectSpec& spec : fidelity_plan(s))
    got.emplace_back(spec.method, spec.body.compression, spec.body.solver_divisor);
  const std::vector<std::tuple<std::string, double, int>> want{{"tcsb", 0.1, 1},           {"tcsb", 0.3, 1},
                                                               {"tcsb", 0.5, 1},           {"tcsb", 0.75, 1},
                                                               {"tcsb", 1.0, 1},           {"uniform_grid", 0.1, 1},
                                                               {"uniform_grid", 0.3, 1},   {"uniform_grid", 0.5, 1},
                                                               {"uniform_grid", 0.75, 1},  {"full_resolution", 1.0, 2},
                                                               {"full_resolution", 1.0, 4}};
  EXPECT_EQ(got, want);
  // Under the compliant material the reference takes more small steps than the suite: its own count is a point.
  s.solver.model = MaterialModel::kCompliant;
  s.tcsb.masses = Masses::kCut;
  int full_at_one = 0, grids = 0;
  for (const FidelitySubjectSpec& spec : fidelity_plan(s)) {
    full_at_one += spec.method == "full_resolution" && spec.body.solver_divisor == 1;
    grids += spec.method == "uniform_grid";
  }
  EXPECT_EQ(full_at_one, 1);
  EXPECT_EQ(grids, 4);  // each budget once, though the compliant material plans the suite's targets' grids too
}

TEST(FidelityPlan, CoarseGridHoldsAboutTheBudgetWithTheNetsAspect) {
  EXPECT_EQ(coarse_grid_for(81, 81, 1968).width, 44);   // round(sqrt(1968)) = 44: 1936 nodes
  EXPECT_EQ(coarse_grid_for(81, 81, 1968).height, 45);  // round(1968 / 44) = 45: 1980 nodes, nearer the budget
  const CoarseGrid wide = coarse_grid_for(100, 25, 625);
  EXPECT_EQ(wide.width, 50);
  EXPECT_EQ(wide.height, 13);
  EXPECT_EQ(coarse_grid_for(17, 17, 1).width, 2);        // never below 2 x 2
  EXPECT_EQ(coarse_grid_for(17, 17, 100000).width, 17);  // never above the net
}

TEST(FidelityPlan, CoarseNetKeepsTheClothsSizeMassAndPins) {
  NetSpec fine;
  fine.width = fine.height = 45;
  fine.mass_mode = MassMode::kPerNode;
  fine.mass = 0.01;
  fine.pinned_corners = kCornerMinMin | kCornerMaxMax;
  const NetSpec coarse = coarse_net_spec(fine, 600);
  EXPECT_EQ(coarse.width * coarse.height, 24 * 25);
  EXPECT_EQ(coarse.size_x, fine.size_x);
  EXPECT_EQ(coarse.elevation, fine.elevation);
  EXPECT_EQ(coarse.pinned_corners, fine.pinned_corners);
  EXPECT_NEAR(coarse.node_mass() * static_cast<double>(coarse.node_count()), 0.01 * 45 * 45, 1e-12);
}

TEST(FidelityVariant, EachNameIsABodyDescription) {
  const BodySpec both = fidelity_subject("tcsb_calibrated_motion_only", 0.3).body;
  EXPECT_EQ(both.kind, BodyKind::kTcsb);
  EXPECT_EQ(both.compression, 0.3);
  EXPECT_EQ(both.calibration, BodyCalibration::kSuite);
  EXPECT_EQ(both.view_terms, false);
  EXPECT_FALSE(both.policy);
  const BodySpec stock = fidelity_subject("stock_bullet", 1.0).body;
  EXPECT_EQ(stock.kind, BodyKind::kUniform);
  EXPECT_TRUE(stock.stock_solver);
  EXPECT_EQ(fidelity_subject("full_resolution", 1.0, 4).body.solver_divisor, 4);
  EXPECT_EQ(fidelity_subject("tcsb_random", 0.5).body.policy, PolicyKind::kRandom);
  EXPECT_EQ(fidelity_subject("tcsb_rigid", 0.5).body.placement, Placement::kRigid);
  EXPECT_FALSE(fidelity_subject("tcsb_no_geomorph", 0.5).body.geomorph);
  EXPECT_EQ(fidelity_subject("switch_body", 0.5).body.kind, BodyKind::kSwitch);
  EXPECT_THROW(fidelity_subject("tcsb_calibrated_random", 0.5), std::invalid_argument);
  // The seeds of results already written number the variants in this order.
  EXPECT_EQ(fidelity_variant_index("tcsb"), 0);
  EXPECT_EQ(fidelity_variant_index("tcsb_random"), 3);
  EXPECT_EQ(fidelity_variant_index("full_resolution"), 12);
}

TEST(FidelitySeed, TcsbAtASuiteTargetRetracesItsTimedCase) {
  const Suite s = suite_with_fidelity(true);
  const std::vector<CaseKey> keys = expand_cases(s);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (keys[i].method != Method::kTcsb) continue;
    EXPECT_EQ(fidelity_seed(s, keys[i].net, fidelity_subject("tcsb", *keys[i].compression)), case_seed(s, i));
  }
  // Ablations and Pareto-only targets get seeds of their own, past every case.
  const std::uint64_t random = fidelity_seed(s, 1, fidelity_subject("tcsb_random", 0.3));
  EXPECT_GT(random, case_seed(s, keys.size()));
  EXPECT_NE(random, fidelity_seed(s, 0, fidelity_subject("tcsb_random", 0.3)));
  EXPECT_NE(random, fidelity_seed(s, 1, fidelity_subject("tcsb_random", 0.75)));
}

}  // namespace
}  // namespace tcsb
