// The compliant material (softbody/material.h, compliant_solver.h): masses lumped by area, each link's compliance
// from the membrane rule, small steps in double precision, and one material at every level of TC-SB's cut.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_world.h"
#include "softbody/compliant_solver.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody_impl.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

constexpr double kStiffness = 50.0;  // N/m
constexpr double kDensity = 0.1;     // kg/m^2

SolverSettings compliant_solver(int substeps) {
  SolverSettings s;
  s.model = MaterialModel::kCompliant;
  s.compliant.stretch_stiffness = kStiffness;
  s.compliant.density = kDensity;
  s.compliant.substeps = substeps;
  s.step_dt = testing::kDt;
  return s;
}

/// A square 4 x 4 m net of the compliant material, its blocks resting on their first leaf (masses that follow the
/// cut need it).
std::shared_ptr<const Net> compliant_net(int width, unsigned pinned = kAllCorners, double elevation = 8.0,
                                         double size = 4.0) {
  NetSpec spec;
  spec.name = "compliant";
  spec.width = spec.height = width;
  spec.size_x = spec.size_z = size;
  spec.elevation = elevation;
  spec.pinned_corners = pinned;
  spec.mass_mode = MassMode::kDensity;
  spec.mass = kDensity;
  return std::make_shared<const Net>(spec, RestPlacement::kVertex);
}

TcSettings cut_settings() {
  TcSettings t;
  t.masses = Masses::kCut;
  t.interfaces = Interfaces::kHanging;
  return t;
}

/// The inverse of a link's compliance term alpha / h^2 = 1 / (k h^2) in its constant: k.
double stiffness_of(const btSoftBody::Link& l, double substep_dt) {
  const double compliance = static_cast<double>(l.m_c0) - (l.m_n[0]->m_im + l.m_n[1]->m_im);
  return 1.0 / (compliance * substep_dt * substep_dt);
}

TEST(CompliantMaterial, MassesAreLumpedByArea) {
  const auto net = compliant_net(5);
  const double cell = kDensity * 1.0 * 1.0;                                               // 1 m cells
  EXPECT_DOUBLE_EQ(net->masses()[static_cast<std::size_t>(net->index(2, 2))], cell);      // inside
  EXPECT_DOUBLE_EQ(net->masses()[static_cast<std::size_t>(net->index(2, 0))], cell / 2);  // on a border
  EXPECT_DOUBLE_EQ(net->masses()[static_cast<std::size_t>(net->index(4, 4))], cell / 4);  // at a corner
  EXPECT_NEAR(net->total_mass(), kDensity * 16.0, 1e-12);
}

TEST(CompliantMaterial, APlainBodysLinksCarryTheMembraneRule) {
  const auto net = compliant_net(5);
  SceneWorld world({});
  const SolverSettings solver = compliant_solver(8);
  const auto body = make_plain_softbody(world.info(), *net, solver);
  ASSERT_NE(compliant_settings(*body), nullptr);
  for (int i = 0; i < body->m_links.size(); ++i) {
    const NetLink& l = net->links()[static_cast<std::size_t>(i)];
    const int xa = l.a % 5, za = l.a / 5, xb = l.b % 5;
    const int across = xb != xa ? za : xa;
    const double expected = across == 0 || across == 4 ? kStiffness / 2 : kStiffness;  // one cell or two beside it
    EXPECT_NEAR(stiffness_of(body->m_links[i], solver.substep_dt()), expected, 1e-3 * expected) << "link " << i;
  }
}

TEST(CompliantMaterial, EveryWholeLevelOfTheCutIsTheSameMaterial) {
  // The membrane rule gives a link inside any whole level the same stiffness, where Bullet's kLST would make each
  // coarser level's spring four times stiffer.
  const auto net = compliant_net(33);
  SceneWorld world({});
  const SolverSettings solver = compliant_solver(8);
  for (const int level : {0, 1, 2, 3}) {
    SCOPED_TRACE("level " + std::to_string(level));
    TcSoftBody tc(world.info(), net, solver, cut_settings());
    tc.coarsen_to_level(level);
    ASSERT_TRUE(tc.validate().ok()) << tc.validate().summary();
    int inner = 0;
    for (int i = 0; i < tc.link_count(); ++i) {
      const CutLink& m = tc.cut_links()[static_cast<std::size_t>(i)];
      const LodNode& a = net->lod().node(net->lod().rest_leaf(m.a));
      const LodNode& b = net->lod().node(net->lod().rest_leaf(m.b));
      const int across = a.gy == b.gy ? a.gy : a.gx;
      if (across == 0 || across == 32) continue;  // the border's links carry half
      EXPECT_NEAR(stiffness_of(tc.m_links[i], solver.substep_dt()), kStiffness, 1e-3 * kStiffness) << "link " << i;
      ++inner;
    }
    EXPECT_GT(inner, 0);
  }
}

TEST(CompliantMaterial, FullResolutionTcsbIsThePlainBodyBitForBit) {
  for (const int passes : {1, 3}) {
    SCOPED_TRACE("passes " + std::to_string(passes));
    const auto net = compliant_net(17);
    SolverSettings solver = compliant_solver(6);
    solver.compliant.passes = passes;
    SceneWorld plain_world({}), tc_world({});
    const auto plain = make_plain_softbody(plain_world.info(), *net, solver);
    TcSoftBody tc(tc_world.info(), net, solver, cut_settings());
    const auto a = plain_world.attach(*plain);
    const auto b = tc_world.attach(tc);
    for (int s = 0; s < 30; ++s) {
      plain_world.step(testing::kDt);
      tc_world.step(testing::kDt);
    }
    for (int i = 0; i < plain->m_nodes.size(); ++i) {
      ASSERT_EQ(plain->m_nodes[i].m_x, tc.m_nodes[i].m_x) << "node " << i;
      ASSERT_EQ(plain->m_nodes[i].m_v, tc.m_nodes[i].m_v) << "node " << i;
    }
  }
}

TEST(CompliantMaterial, PassesThatKeepLambdaHoldThroughBlendsAndInterfaces) {
  // Half the net coarsened while it hangs: links fading in and out (their constants divided by the blend weight, so
  // their alpha~ read back from m_c0 is a softer spring) and hanging interfaces, whose lambda the caller keeps, in
  // every pass. The body stays valid and finite and ends near where one pass a small step ends.
  const auto net = compliant_net(17);
  std::vector<std::vector<btVector3>> ends;
  for (const int passes : {1, 3}) {
    SCOPED_TRACE("passes " + std::to_string(passes));
    SceneWorld world({});
    SolverSettings solver = compliant_solver(6);
    solver.compliant.passes = passes;
    solver.compliant.damping = 4.0;
    TcSoftBody tc(world.info(), net, solver, cut_settings());
    const auto attached = world.attach(tc);
    for (int s = 0; s < 30; ++s) world.step(testing::kDt);
    for (TreeId id = 0; id < static_cast<TreeId>(net->lod().size()); ++id) {
      const LodNode& n = net->lod().node(id);
      if (n.level == 1 && n.leaf_x1 <= 8 && tc.can_coarsen(id).ok) tc.begin_coarse(id);
    }
    for (int s = 0; s < 90; ++s) {
      world.step(testing::kDt);
      tc.advance_blends();
      ASSERT_TRUE(tc.validate().ok()) << "step " << s << ": " << tc.validate().summary();
    }
    EXPECT_FALSE(tc.impl().interface_constraints().empty());
    std::vector<btVector3> end;
    for (int i = 0; i < tc.node_count(); ++i) {
      ASSERT_TRUE(std::isfinite(tc.m_nodes[i].m_x.length2())) << "node " << i;
      end.push_back(tc.m_nodes[i].m_x);
    }
    ends.push_back(std::move(end));
  }
  ASSERT_EQ(ends[0].size(), ends[1].size());
  double farthest = 0;
  for (std::size_t i = 0; i < ends[0].size(); ++i)
    farthest = std::max(farthest, static_cast<double>((ends[0][i] - ends[1][i]).length()));
  EXPECT_LT(farthest, 0.05);  // measured 0.024 m on the 4 m net: one pass's softness at k h^2 w = 0.12
}

TEST(CompliantMaterial, AWholeLevelCutHangsAsThePlainGridOfItsNodes) {
  // A whole-level cut rests on an evenly spaced sub-grid of the leaves, with the masses of its own cells and the
  // membrane rule of its own links: the plain uniform grid of its nodes, so it errs against the fine cloth by that
  // grid's resolution and nothing more (docs/investigations/compliant-material.md, "Level 2 is the resolution"),
  // one second after release, still moving.
  const auto net = compliant_net(33);
  for (const int level : {1, 2}) {
    SCOPED_TRACE("level " + std::to_string(level));
    const int stride = 1 << level, width = 32 / stride + 1;
    const auto grid_net = compliant_net(width);
    SolverSettings solver = compliant_solver(8);
    solver.compliant.damping = 4.0;
    SceneWorld grid_world({}), tc_world({});
    const auto grid = make_plain_softbody(grid_world.info(), *grid_net, solver);
    TcSettings settings = cut_settings();
    settings.exact_order = true;  // the plain grid's link order, so Gauss-Seidel sweeps them alike
    TcSoftBody tc(tc_world.info(), net, solver, settings);
    tc.coarsen_to_level(level);
    ASSERT_EQ(tc.node_count(), width * width);
    const auto a = grid_world.attach(*grid);
    const auto b = tc_world.attach(tc);
    for (int s = 0; s < 60; ++s) {
      grid_world.step(testing::kDt);
      tc_world.step(testing::kDt);
    }
    double farthest = 0;
    for (int i = 0; i < tc.node_count(); ++i) {
      const TreeId leaf = net->lod().rest_leaf(tc.tree_id(i));
      const int g = grid_net->index(leaf % 33 / stride, leaf / 33 / stride);
      farthest = std::max(farthest, static_cast<double>((tc.m_nodes[i].m_x - grid->m_nodes[g].m_x).length()));
    }
    // Measured: under 1e-9 m in this build. Ten float ulps at 8 m leave room for another build's rounding; the same
    // cut swept in its own link order (without exact_order) ends 1 to 4 mm away.
    EXPECT_LT(farthest, 1e-5) << "m, on a 4 m net";
  }
}

/// The sag at rest of the middle of a 17 x 17 net hanging from its corners (4 x 4 m, 50 N/m, 0.1 kg/m^2, damped to
/// rest in two seconds), metres below the corners, at `substeps` small steps of `passes` link passes.
double sag_at_rest(int substeps, int passes) {
  const auto net = compliant_net(17);
  SceneWorld world({});
  SolverSettings solver = compliant_solver(substeps);
  solver.compliant.passes = passes;
  solver.compliant.damping = 4.0;
  const auto body = make_plain_softbody(world.info(), *net, solver);
  const auto attached = world.attach(*body);
  for (int s = 0; s < 120; ++s) world.step(testing::kDt);
  return 8.0 - static_cast<double>(body->m_nodes[17 * 8 + 8].m_x.y());
}

TEST(CompliantMaterial, PassesThatKeepLambdaHangAsTheMaterialAtLargeSmallSteps) {
  // At 2 small steps k h^2 w is 1.1 on this net's links: one pass a small step is a spring of k / (1 + k h^2 w),
  // softer than the material, and sags more than the cloth of many small steps; passes that sum lambda over the small
  // step converge to the implicit Euler step, whose rest is the material's whatever h.
  const double converged = sag_at_rest(64, 4);
  const double one_pass = sag_at_rest(2, 1) - converged, summed = sag_at_rest(2, 16) - converged;
  EXPECT_GT(one_pass, 0.0);  // softer
  EXPECT_LT(std::abs(summed), 0.1 * one_pass) << "one pass " << one_pass << " m";
}

TEST(CompliantMaterial, SmallStepsKeepTheirPrecisionAtMetreScale) {
  // A net with no pins falls freely: after one step of n small steps every node has fallen g h^2 n (n + 1) / 2. At
  // 8 m in Bullet's floats an increment of g h^2 (7e-8 m at 192 small steps) is a tenth of an ulp and would be lost.
  const int n = 192;
  const auto net = compliant_net(5, 0, 8.0);
  SceneWorld world({});
  const auto body = make_plain_softbody(world.info(), *net, compliant_solver(n));
  const auto attached = world.attach(*body);
  world.step(testing::kDt);
  const double h = static_cast<double>(testing::kDt) / n;
  const double fallen = 9.81 * h * h * n * (n + 1) / 2;
  for (int i = 0; i < body->m_nodes.size(); ++i)
    EXPECT_NEAR(8.0 - body->m_nodes[i].m_x.y(), fallen, 2e-6) << "node " << i;  // (an ulp at 8 m: 9.5e-7)
}

TEST(CompliantMaterial, DampingTakesTheSameShareOfASecondWhateverTheSmallSteps) {
  // No gravity, no pins: the net drifts as one and only the damping slows it, exp(-c) in a second.
  const double rate = 0.7;
  for (const int n : {3, 24}) {
    SCOPED_TRACE("substeps " + std::to_string(n));
    const auto net = compliant_net(5, 0);
    WorldSettings w;
    w.gravity = 0;
    SceneWorld world(w);
    SolverSettings solver = compliant_solver(n);
    solver.compliant.damping = rate;
    const auto body = make_plain_softbody(world.info(), *net, solver);
    const auto attached = world.attach(*body);
    for (int i = 0; i < body->m_nodes.size(); ++i) body->m_nodes[i].m_v = btVector3(1, 0, 0);
    for (int s = 0; s < 60; ++s) world.step(testing::kDt);
    for (int i = 0; i < body->m_nodes.size(); ++i)
      EXPECT_NEAR(body->m_nodes[i].m_v.x(), std::exp(-rate * 60 * static_cast<double>(testing::kDt)), 1e-4);
  }
}

TEST(SolverSettingsCheck, EveryBodyFactoryRefusesSettingsNoBodyCanStepWith) {
  // A kLST of 0 divided every link constant by zero; the compliant material's fields, as the suite reader's ranges.
  const auto net = compliant_net(5);
  const std::vector<std::pair<std::string, std::function<void(SolverSettings&)>>> bad = {
      {"piterations", [](SolverSettings& s) { s.piterations = 0; }},
      {"linear_stiffness", [](SolverSettings& s) { s.linear_stiffness = 0; }},
      {"damping", [](SolverSettings& s) { s.damping = 1; }},
      {"compliant.stretch_stiffness", [](SolverSettings& s) { s.compliant.stretch_stiffness = -1; }},
      {"compliant.density", [](SolverSettings& s) { s.compliant.density = 0; }},
      {"compliant.substeps", [](SolverSettings& s) { s.compliant.substeps = 0; }},
      {"compliant.passes", [](SolverSettings& s) { s.compliant.passes = 0; }},
      {"step_dt", [](SolverSettings& s) { s.step_dt = std::nan(""); }},
  };
  SceneWorld world({});
  for (const auto& [field, edit] : bad) {
    SCOPED_TRACE(field);
    SolverSettings solver = compliant_solver(4);
    edit(solver);
    for (const bool tc : {false, true}) {
      try {
        if (tc)
          TcSoftBody body(world.info(), net, solver, cut_settings());
        else
          make_plain_softbody(world.info(), *net, solver);
        ADD_FAILURE() << "accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("SolverSettings: " + field + " "), std::string::npos) << e.what();
      }
    }
  }
}

/// The level consistency, in the hanging net of the viewer and converged suites' compliant twins (8 m, 65 x
/// 65, corners pinned, 100 N/m, 1/64 kg/m^2, damped to rest in two seconds): each cut against the full-resolution
/// cloth at 192 small steps of one pass (k h^2 w = 0.014 on its finest links), RMS over the cut's nodes (each
/// against the grid node it rests on), % of the extent.
class HangingNetLevels {
 public:
  static constexpr int kWidth = 65;
  static constexpr int kSteps = 120;
  static constexpr int kMixedCut = -1;  ///< level 1 on the half x < 4 m, level 0 on the rest

  /// One body's error against the reference, % of the extent (RMS over its nodes, each against the grid node it
  /// rests on), as a whole and split by rest distance from the nearest pinned corner.
  struct ErrorMap {
    double all = 0;
    double near_pins = 0;  ///< nodes within kPinNeighbourhood of a pinned corner
    double elsewhere = 0;
    double centre_height = 0;  ///< the middle node's height minus the reference's, m (< 0: it sags more)
    int near_count = 0;
    int far_count = 0;
  };
  /// The pins' neighbourhood: an eighth of the 8 m net, two cells of a 17 x 17 grid, eight of the 65 x 65 one.
  static constexpr double kPinNeighbourhood = 1.0;

  HangingNetLevels() : net_(make_net(kWidth)), reference_(hang_plain(*net_, 8 * 24)) {}

  /// A plain uniform `width` x `width` net of the same material (its nodes on every (64 / (width - 1))-th grid node
  /// of the reference's), hung at `substeps` small steps of one pass, against the reference.
  ErrorMap plain_grid_error(int width, int substeps) const {
    const auto coarse = make_net(width);
    const std::vector<btVector3> positions = hang_plain(*coarse, substeps);
    const int stride = (kWidth - 1) / (width - 1);
    std::vector<std::pair<std::size_t, btVector3>> nodes;
    for (int i = 0; i < static_cast<int>(positions.size()); ++i)
      nodes.emplace_back(static_cast<std::size_t>(net_->index(i % width * stride, i / width * stride)),
                         positions[static_cast<std::size_t>(i)]);
    return error_map(nodes);
  }

  /// The whole-level cut `level` of TC-SB at `substeps` small steps of one pass, against the reference.
  ErrorMap level_error(int level, int substeps) const {
    SceneWorld world({});
    TcSoftBody tc(world.info(), net_, solver(substeps, 1), cut_settings());
    tc.coarsen_to_level(level);
    const auto attached = world.attach(tc);
    for (int s = 0; s < kSteps; ++s) world.step(testing::kDt);
    return error_map(rest_leaves(tc));
  }

  /// RMS % of the extent per cut: whole levels 0, 1, 2 and kMixedCut, at `substeps` small steps of `passes` passes.
  std::map<int, double> errors(int substeps, int passes) const {
    std::map<int, double> error;
    for (const int cut : {0, 1, 2, kMixedCut}) {
      SCOPED_TRACE("cut " + std::to_string(cut));
      SceneWorld world({});
      TcSoftBody tc(world.info(), net_, solver(substeps, passes), cut_settings());
      if (cut >= 0) {
        tc.coarsen_to_level(cut);
      } else {
        for (TreeId id = 0; id < static_cast<TreeId>(net_->lod().size()); ++id) {
          const LodNode& n = net_->lod().node(id);
          if (n.level == 1 && n.leaf_x1 <= kWidth / 2 && tc.can_coarsen(id).ok) tc.begin_coarse(id);
        }
        for (int k = 0; k <= tc.settings().blend_steps; ++k) tc.advance_blends();
      }
      EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
      const auto attached = world.attach(tc);
      for (int s = 0; s < kSteps; ++s) world.step(testing::kDt);
      EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
      error[cut] = error_map(rest_leaves(tc)).all;
    }
    return error;
  }

 private:
  static std::shared_ptr<const Net> make_net(int width) {
    NetSpec spec;
    spec.name = "hanging";
    spec.width = spec.height = width;
    spec.mass_mode = MassMode::kDensity;
    spec.mass = 1.0 / 64;
    return std::make_shared<const Net>(spec, RestPlacement::kVertex);
  }
  static std::vector<btVector3> hang_plain(const Net& net, int substeps) {
    SceneWorld world({});
    const auto body = make_plain_softbody(world.info(), net, solver(substeps, 1));
    const auto attached = world.attach(*body);
    for (int s = 0; s < kSteps; ++s) world.step(testing::kDt);
    std::vector<btVector3> positions;
    for (int i = 0; i < body->m_nodes.size(); ++i) positions.push_back(body->m_nodes[i].m_x);
    return positions;
  }
  static SolverSettings solver(int substeps, int passes) {
    SolverSettings s = compliant_solver(substeps);
    s.compliant.passes = passes;
    s.compliant.stretch_stiffness = 100;
    s.compliant.damping = 4.0;  // to rest in the two seconds
    return s;
  }
  std::vector<std::pair<std::size_t, btVector3>> rest_leaves(const TcSoftBody& tc) const {
    std::vector<std::pair<std::size_t, btVector3>> nodes;
    for (int i = 0; i < tc.node_count(); ++i)
      nodes.emplace_back(static_cast<std::size_t>(net_->lod().rest_leaf(tc.tree_id(i))), tc.m_nodes[i].m_x);
    return nodes;
  }
  /// `nodes`: each node's reference grid node and position.
  ErrorMap error_map(const std::vector<std::pair<std::size_t, btVector3>>& nodes) const {
    const int last = kWidth - 1;
    const double cell = net_->extent() / last;
    double all = 0, near = 0, far = 0;
    ErrorMap map;
    for (const auto& [leaf, x] : nodes) {
      const double e = static_cast<double>((x - reference_[leaf]).length2());
      const int gx = static_cast<int>(leaf) % kWidth, gz = static_cast<int>(leaf) / kWidth;
      const double to_corner = cell * std::hypot(std::min(gx, last - gx), std::min(gz, last - gz));
      all += e;
      if (to_corner <= kPinNeighbourhood) {
        near += e;
        ++map.near_count;
      } else {
        far += e;
        ++map.far_count;
      }
      if (gx == last / 2 && gz == last / 2) map.centre_height = static_cast<double>(x.y() - reference_[leaf].y());
    }
    const auto pct = [&](double sum, int count) { return 100.0 * std::sqrt(sum / count) / net_->extent(); };
    map.all = pct(all, static_cast<int>(nodes.size()));
    map.near_pins = pct(near, map.near_count);
    map.elsewhere = pct(far, map.far_count);
    return map;
  }

  std::shared_ptr<const Net> net_;
  std::vector<btVector3> reference_;
};

TEST(CompliantMaterial, WholeLevelsAndAMixedCutHangAsTheConvergedCloth) {
  // At the twins' 24 small steps of one pass: measured 0.88, 0.40, 1.30 and 0.64 %. Level 2 (17 x 17 nodes) misses
  // the 1 % by its spatial resolution (the plain 17 x 17 grid errs as much: DISABLED_LevelTwo* below), and the
  // mixed cut errs less than the worse of its two levels, so the levels compose.
#ifdef __SANITIZE_ADDRESS__
  // A measurement of the physics, not of memory: 8 minutes at -O0 under the sanitizers (482 s in CI's sanitized
  // tree), 3 s in Release. The sanitized tree runs the compliant solver through the other tests here.
  GTEST_SKIP() << "a physics measurement: run in the Release tree";
#endif
  const HangingNetLevels levels;
  std::map<int, double> error = levels.errors(24, 1);
  EXPECT_LT(error[0], 1.0);
  EXPECT_LT(error[1], 1.0);
  EXPECT_LT(error[2], 1.4);
  EXPECT_LT(error[HangingNetLevels::kMixedCut], 1.0);
  EXPECT_LE(error[HangingNetLevels::kMixedCut], std::max(error[0], error[1]));  // the levels compose
}

TEST(CompliantMaterial, DISABLED_LevelErrorsAtEqualCost) {
  // The measurement behind docs/investigations/compliant-material.md, "Passes at equal cost": the level-consistency
  // errors at pairs of (small steps, passes), grouped by their cost in link passes a step (24: the twins').
  // Run: build/tests_softbody --gtest_also_run_disabled_tests --gtest_filter='CompliantMaterial.DISABLED_Level*'
  const HangingNetLevels levels;
  std::printf(
      "link passes a step | substeps x passes | level 0 | level 1 | level 2 | mixed 0/1  (RMS %% of the extent)\n");
  // Costs of 24, 48, 96, 192 (192 x 1: the reference itself) and 384 link passes a step.
  const std::vector<std::pair<int, int>> pairs = {{24, 1},  {12, 2}, {8, 3},  {6, 4},  {4, 6},   {3, 8},
                                                  {48, 1},  {24, 2}, {12, 4}, {96, 1}, {48, 2},  {24, 4},
                                                  {192, 1}, {96, 2}, {64, 3}, {48, 4}, {12, 16}, {24, 16}};
  for (const auto& [substeps, passes] : pairs) {
    std::map<int, double> error = levels.errors(substeps, passes);
    std::printf("%d | %d x %d | %.3f | %.3f | %.3f | %.3f\n", substeps * passes, substeps, passes, error[0], error[1],
                error[2], error[HangingNetLevels::kMixedCut]);
  }
}

TEST(CompliantMaterial, DISABLED_LevelTwoAgainstThePlainGridOfItsNodes) {
  // The measurement behind docs/investigations/compliant-material.md, "Level 2 is the resolution": each whole-level
  // cut beside the plain uniform grid of its nodes (the same material, masses and membrane rule of its own cells), at
  // the twins' 24 small steps and converged (192), against the reference, with the error split between the pins'
  // neighbourhood and the rest of the net.
  // Run: build/tests_softbody --gtest_also_run_disabled_tests --gtest_filter='CompliantMaterial.DISABLED_LevelTwo*'
  const HangingNetLevels levels;
  std::printf(
      "body | small steps | RMS %% | near the pins (nodes) | elsewhere (nodes) | centre height - reference, mm\n");
  const auto print = [](const char* body, int substeps, const HangingNetLevels::ErrorMap& e) {
    std::printf("%s | %d | %.3f | %.3f (%d) | %.3f (%d) | %.1f\n", body, substeps, e.all, e.near_pins, e.near_count,
                e.elsewhere, e.far_count, 1000.0 * e.centre_height);
  };
  for (const int substeps : {24, 192}) {
    print("level 1 cut", substeps, levels.level_error(1, substeps));
    print("plain 33 x 33", substeps, levels.plain_grid_error(33, substeps));
    print("level 2 cut", substeps, levels.level_error(2, substeps));
    print("plain 17 x 17", substeps, levels.plain_grid_error(17, substeps));
    print("level 3 cut", substeps, levels.level_error(3, substeps));
    print("plain 9 x 9", substeps, levels.plain_grid_error(9, substeps));
  }
}

}  // namespace
}  // namespace tcsb
