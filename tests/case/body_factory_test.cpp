// The body factory builds each kind from its description: the nodes it simulates, whether a controller drives it,
// and the settings the description changes (calibration, interfaces, solver) applied to the suite's.
#include "case/body_factory.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "case/case_body.h"
#include "suite/fidelity_plan.h"

namespace tcsb {
namespace {

Suite factory_suite() {
  Suite s;
  NetSpec spec;
  spec.width = spec.height = 17;
  s.nets = {spec};
  s.solver.piterations = 8;
  return s;
}

std::shared_ptr<const Net> factory_net(const Suite& s) { return std::make_shared<const Net>(s.nets.front()); }

Calibration factory_calibration() {
  Calibration c;
  c.levels = {{.level = 1, .linear_stiffness = 0.6}, {.level = 2, .linear_stiffness = 0.4}};
  c.uniform_grid = {{.compression = 0.25, .linear_stiffness = 0.7}};
  return c;
}

TEST(BodyFactory, PlainAndPatchSimulateEveryNodeOfTheNet) {
  const Suite s = factory_suite();
  const auto net = factory_net(s);
  for (const BodyKind kind : {BodyKind::kPlain, BodyKind::kBulletPatch, BodyKind::kSwitch}) {
    SceneWorld world(s.world);
    const Body body = make_body(s, {.kind = kind}, world, net, 1);
    EXPECT_EQ(body.bullet->m_nodes.size(), static_cast<int>(net->node_count()));
    EXPECT_EQ(body.net, net);
    EXPECT_EQ(body.tc, nullptr);
    EXPECT_EQ(body.controller, nullptr);
  }
}

TEST(BodyFactory, UniformGridIsTheCoarseNetOfTheBudget) {
  const Suite s = factory_suite();
  const auto net = factory_net(s);
  SceneWorld world(s.world);
  const Body body = make_body(s, {.kind = BodyKind::kUniform, .compression = 0.25}, world, net, 1);
  const CoarseGrid g = coarse_grid_for(17, 17, node_budget(*net, 0.25));
  EXPECT_EQ(body.budget, node_budget(*net, 0.25));
  EXPECT_EQ(body.net->width(), g.width);
  EXPECT_EQ(body.net->height(), g.height);
  EXPECT_EQ(body.bullet->m_nodes.size(), g.width * g.height);
  EXPECT_LT(body.bullet->m_nodes.size(), static_cast<int>(net->node_count()));
}

TEST(BodyFactory, TcsbHasAControllerOnlyUnderItsBudget) {
  const Suite s = factory_suite();
  const auto net = factory_net(s);
  SceneWorld compressed_world(s.world), full_world(s.world);
  const Body compressed = make_body(s, {.kind = BodyKind::kTcsb, .compression = 0.3}, compressed_world, net, 1);
  ASSERT_NE(compressed.tc, nullptr);
  EXPECT_EQ(compressed.tc, compressed.bullet.get());
  EXPECT_NE(compressed.controller, nullptr);
  const Body full = make_body(s, {.kind = BodyKind::kTcsb}, full_world, net, 1);
  ASSERT_NE(full.tc, nullptr);
  EXPECT_EQ(full.controller, nullptr) << "at every node the cut never changes";
  EXPECT_EQ(full.tc->node_count(), static_cast<int>(net->node_count()));
}

TEST(BodyFactory, WholeLevelStartsCoarseWithoutAController) {
  const Suite s = factory_suite();
  const auto net = factory_net(s);
  SceneWorld world(s.world);
  const Body body = make_body(s, {.kind = BodyKind::kTcsb, .whole_level = 1}, world, net, 1);
  EXPECT_EQ(body.controller, nullptr);
  EXPECT_EQ(body.tc->node_count(), 9 * 9) << "level 1 of a 17 x 17 grid";
}

TEST(BodyFactory, TcsbSettingsChangeOnlyWhereTheSpecSays) {
  Suite s = factory_suite();
  s.tcsb.interfaces = Interfaces::kHanging;
  s.calibration = factory_calibration();
  const auto net = factory_net(s);
  SceneWorld suites_world(s.world), changed_world(s.world);
  const Body suites = make_body(s, {.kind = BodyKind::kTcsb, .compression = 0.5}, suites_world, net, 1);
  EXPECT_EQ(suites.tc->settings().interfaces, Interfaces::kHanging);
  EXPECT_TRUE(suites.tc->settings().level_stiffness.empty());
  const BodySpec spec = fidelity_subject("tcsb_calibrated_fans", 0.5).body;
  const Body changed = make_body(s, spec, changed_world, net, 1);
  EXPECT_EQ(changed.tc->settings().interfaces, Interfaces::kLinks);
  EXPECT_EQ(changed.tc->settings().level_stiffness, (std::vector<double>{0.6, 0.4}));
}

TEST(BodyFactory, CalibratedBodiesNeedTheSuitesCalibration) {
  Suite s = factory_suite();
  const auto net = factory_net(s);
  SceneWorld world(s.world);
  const BodySpec tcsb{.kind = BodyKind::kTcsb, .compression = 0.25, .calibration = BodyCalibration::kSuite};
  const BodySpec grid{.kind = BodyKind::kUniform, .compression = 0.25, .calibration = BodyCalibration::kSuite};
  EXPECT_THROW(make_body(s, tcsb, world, net, 1), std::invalid_argument);
  EXPECT_THROW(body_solver(s, grid), std::invalid_argument);
  s.calibration = factory_calibration();
  EXPECT_EQ(body_solver(s, grid).linear_stiffness, 0.7);
  BodySpec other_budget = grid;
  other_budget.compression = 0.5;
  EXPECT_THROW(body_solver(s, other_budget), std::invalid_argument) << "no fit for this budget";
}

TEST(BodyFactory, SolverFieldsChangeTheSuitesSolver) {
  Suite s = factory_suite();
  EXPECT_EQ(body_solver(s, {.kind = BodyKind::kUniform, .solver_divisor = 4}).piterations, 2);
  s.solver.model = MaterialModel::kCompliant;
  s.solver.compliant.substeps = 16;
  EXPECT_EQ(body_solver(s, {.kind = BodyKind::kUniform, .solver_divisor = 4}).compliant.substeps, 4);
  EXPECT_EQ(body_solver(s, {.kind = BodyKind::kPlain, .stock_solver = true}).model, MaterialModel::kBullet);
  EXPECT_EQ(body_solver(s, {.kind = BodyKind::kPlain}).model, MaterialModel::kCompliant);
}

TEST(BodyFactory, CaseMethodsAreDescriptions) {
  const auto spec_of = [](Method method, std::optional<double> compression = std::nullopt) {
    CaseKey key;
    key.method = method;
    key.compression = compression;
    return case_body_spec(key);
  };
  EXPECT_EQ(spec_of(Method::kPlain).kind, BodyKind::kPlain);
  EXPECT_EQ(spec_of(Method::kStock).kind, BodyKind::kPlain);
  EXPECT_TRUE(spec_of(Method::kStock).stock_solver);
  EXPECT_EQ(spec_of(Method::kBulletPatch).kind, BodyKind::kBulletPatch);
  EXPECT_EQ(spec_of(Method::kPlainEqual, 0.3).kind, BodyKind::kUniform);
  EXPECT_EQ(spec_of(Method::kPlainEqual, 0.3).compression, 0.3);
  EXPECT_EQ(spec_of(Method::kTcsb, 0.75).kind, BodyKind::kTcsb);
}

}  // namespace
}  // namespace tcsb
