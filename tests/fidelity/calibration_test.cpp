// The calibration: its file (round trip, one-line errors), the check that ties it to a suite's regime, the body it
// fits (a TC-SB cut coarsened to one level), the fit itself on a tiny suite, and a suite that refers to one.
#include "fidelity/calibration.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fidelity/fidelity_runner.h"
#include "fidelity/figure_frames.h"
#include "paper/fidelity_tables.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "suite/fidelity_plan.h"

namespace tcsb {
namespace {

namespace fs = std::filesystem;

const char* kTinySuite = R"({
  "name": "tiny",
  "nets": [{"name": "n17", "width": 17, "height": 17}],
  "methods": ["plain", "tcsb"],
  "compression": [1.0, 0.3],
  "dt": 0.016666666666666666, "steps": 30, "warmup_steps": 20, "repetitions": 1, "seed": 1,
  "solver": {"piterations": 16},
  "fidelity": {"enabled": true, "ablations": false, "pareto_targets": []CALIBRATION}
})";

std::string tiny_suite_text(const std::string& calibration = "") {
  std::string text = kTinySuite;
  text.replace(text.find("CALIBRATION"), 11, calibration.empty() ? "" : ", \"calibration\": \"" + calibration + "\"");
  return text;
}

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("tcsb_calibration_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

Calibration sample(const Suite& suite) {
  Calibration c;
  c.suite = suite.name;
  c.key = calibration_key(suite);
  c.piterations = suite.solver.piterations;
  c.linear_stiffness = suite.solver.linear_stiffness;
  c.levels = {{1, 1.0, 0.42, 0.5, 3.0, 17}, {2, 1.0, 0.25, 1.0, 6.0, 17}};
  c.uniform_grid = {{0, 0.3, 0.6, 0.9, 4.0, 17}};
  return c;
}

TEST(CalibrationFile, RoundTripsAndRefusesABadFieldInOneLine) {
  const Suite suite = parse_suite_text(tiny_suite_text(), "tiny.json");
  const fs::path dir = temp_dir();
  const Calibration c = sample(suite);
  write_file(dir / "c.json", calibration_json_text(c));
  const Calibration back = parse_calibration_file(dir / "c.json");
  EXPECT_EQ(back.key, c.key);
  EXPECT_EQ(back.level_stiffness(), (std::vector<double>{0.42, 0.25}));
  EXPECT_EQ(back.uniform_stiffness(0.3), 0.6);
  EXPECT_FALSE(back.uniform_stiffness(0.75));
  EXPECT_EQ(back.levels[1].uncalibrated_rms_pct, 6.0);
  EXPECT_EQ(calibration_mismatch(back, suite), "");
  std::string text = calibration_json_text(c);
  text.replace(text.find("0.42"), 4, "1.42");
  write_file(dir / "bad.json", text);
  try {
    parse_calibration_file(dir / "bad.json");
    ADD_FAILURE() << "accepted a stiffness above 1";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("levels[0].linear_stiffness"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(CalibrationFile, FitsOnlyTheRegimeItWasFittedIn) {
  const Suite suite = parse_suite_text(tiny_suite_text(), "tiny.json");
  const Calibration c = sample(suite);
  Suite other = suite;
  other.solver.piterations = 2;
  EXPECT_NE(calibration_mismatch(c, other).find("solver iterations"), std::string::npos);
  other = suite;
  other.solver.linear_stiffness = 0.5;
  EXPECT_NE(calibration_mismatch(c, other).find("material stiffness"), std::string::npos);
  other = suite;
  other.world.gravity = 9.81 / 2;
  EXPECT_NE(calibration_mismatch(c, other).find("tcsb calibrate"), std::string::npos);
  other = suite;
  other.compression = {1.0, 0.75};
  EXPECT_NE(calibration_mismatch(c, other).find("uniform-grid fit"), std::string::npos);
  other = suite;
  Collider sphere;
  other.scene.colliders.push_back(sphere);  // a fit made without colliders does not hold with one
  EXPECT_NE(calibration_mismatch(c, other).find("tcsb calibrate"), std::string::npos);
  Suite moved = other;
  moved.scene.colliders[0].position[1] += 0.5;  // nor with the collider elsewhere
  EXPECT_NE(calibration_key(moved), calibration_key(other));
  other = suite;
  other.tcsb.masses = Masses::kCut;  // nor with TC-SB's masses following the cut: every coarse level is other cloth
  EXPECT_NE(calibration_mismatch(c, other).find("tcsb calibrate"), std::string::npos);
  other = suite;
  other.tcsb.exact_order = true;  // nor with the links solved in a plain body's order: the order is the material
  EXPECT_NE(calibration_mismatch(c, other).find("tcsb calibrate"), std::string::npos);
  other = suite;
  other.name = "renamed";  // name, description, repetitions and fidelity settings do not matter
  other.repetitions = 9;
  EXPECT_EQ(calibration_mismatch(c, other), "");
}

TEST(Calibration, CoarsenToLevelMakesTheWholeCutThatLevel) {
  NetSpec spec;
  spec.width = spec.height = 17;
  const auto net = std::make_shared<const Net>(spec);
  SceneWorld world({});
  TcSoftBody body(world.info(), net, SolverSettings{}, TcSettings{});
  EXPECT_EQ(body.coarsen_to_level(1), 9 * 9);
  EXPECT_EQ(body.interpolations(), 0);
  EXPECT_EQ(body.node_count(), 9 * 9);
  EXPECT_TRUE(body.validate().ok()) << body.validate().summary();
  EXPECT_EQ(body.coarsen_to_level(2), 5 * 5);
}

TEST(Calibration, TheFitNeverDoesWorseThanTheSolversStiffnessAndASuiteUsesIt) {
  const fs::path dir = temp_dir();
  const Suite suite = parse_suite_text(tiny_suite_text(), (dir / "tiny.json").string());
  const std::vector<std::shared_ptr<const Net>> nets{std::make_shared<const Net>(suite.nets[0])};
  CalibrationSearch search;
  search.scan_points = 4;
  search.tolerance = 0.1;
  std::vector<std::string> lines;
  const Calibration c = calibrate_suite(suite, nets, search, [&](const std::string& l) { lines.push_back(l); });
  ASSERT_EQ(c.levels.size(), 2u);  // 17 -> 9 -> 5 (then 3: under 5 x 5)
  ASSERT_EQ(c.uniform_grid.size(), 1u);
  EXPECT_EQ(lines.size(), 3u);
  for (const StiffnessFit& f : c.levels) {
    EXPECT_GT(f.linear_stiffness, 0.0);
    EXPECT_LE(f.linear_stiffness, 1.0);
    EXPECT_LE(f.rms_pct, f.uncalibrated_rms_pct);  // k = 1 is the scan's end point: never worse
    EXPECT_GT(f.uncalibrated_rms_pct, 0.0);
  }
  EXPECT_LE(c.uniform_grid[0].rms_pct, c.uniform_grid[0].uncalibrated_rms_pct);
  EXPECT_EQ(calibration_mismatch(c, suite), "");
  // A suite referring to it gets calibrated TC-SB and the calibrated uniform grid at its targets below 1.
  write_file(dir / "tiny.calibration.json", calibration_json_text(c));
  const Suite calibrated = parse_suite_text(tiny_suite_text("tiny.calibration.json"), (dir / "tiny.json").string());
  ASSERT_TRUE(calibrated.calibration);
  EXPECT_EQ(calibrated.calibration->level_stiffness(), c.level_stiffness());
  int added = 0;
  for (const FidelitySubjectSpec& s : fidelity_plan(calibrated))
    if (s.method == "tcsb_calibrated" || s.method == "uniform_grid_calibrated") {
      EXPECT_EQ(s.body.compression, 0.3);
      ++added;
    }
  EXPECT_EQ(added, 2);
  // The pass simulates them: the calibrated uniform grid is the body the fit measured, so it reaches the fitted error.
  const FidelityResult pass = run_fidelity(calibrated, nets);
  bool seen_tcsb = false, seen_grid = false;
  for (const FidelityCase& fc : pass.cases) {
    if (fc.subject.method == "uniform_grid_calibrated") {
      seen_grid = true;
      EXPECT_NEAR(fc.rms_pct.mean, c.uniform_grid[0].rms_pct, 1e-9);
    }
    if (fc.subject.method == "tcsb_calibrated") {
      seen_tcsb = true;
      EXPECT_EQ(fc.status, "ok");
    }
  }
  EXPECT_TRUE(seen_tcsb && seen_grid);
  // Figure 6 can show it too (`tcsb frames --calibrated`): the same plain body, another TC-SB.
  const FigureFrames frames = record_figure_frames(calibrated, 0, 0.3, {40});
  const FigureFrames calibrated_frames = record_figure_frames(calibrated, 0, 0.3, {40}, true);
  EXPECT_TRUE(calibrated_frames.calibrated);
  ASSERT_EQ(calibrated_frames.frames.size(), 1u);
  EXPECT_EQ(calibrated_frames.frames[0].plain, frames.frames[0].plain);
  EXPECT_NE(calibrated_frames.frames[0].tcsb_surface, frames.frames[0].tcsb_surface);
  EXPECT_THROW(record_figure_frames(suite, 0, 0.3, {40}, true), std::invalid_argument);  // no calibration
  // Fitted for 16 iterations: a suite at 2 refuses it, naming the field.
  std::string two = tiny_suite_text("tiny.calibration.json");
  two.replace(two.find("\"piterations\": 16"), 17, "\"piterations\": 2");
  try {
    parse_suite_text(two, (dir / "tiny.json").string());
    ADD_FAILURE() << "accepted a calibration fitted at other iterations";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fidelity.calibration"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tcsb
