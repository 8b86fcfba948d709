// The native output conforms to results/schema/tcsb-result.schema.json: synthetic runs here (every key, diverged
// cases, the optional sections other commands add), and the committed CI baseline — a real `tcsb run` — too. The
// CLI tests validate a fresh run of the real binary.
#include "result/result_schema.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "render_run.h"
#include "report/json_report.h"
#include "suite/suite_settings_table.h"
#include "synthetic_run.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;
using Lines = std::vector<std::string>;

const std::filesystem::path kSource = TCSB_SOURCE_DIR;

ojson read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  return ojson::parse(in);
}

Lines problems(const ojson& doc) {
  Lines out;
  for (const SchemaViolation& v : check_result_document(doc)) out.push_back(describe(v));
  return out;
}

RunResult run_with_cases() {
  RunResult r;
  r.suite = testing::synthetic_suite(2);
  r.suite.compression = {1.0, 0.3};
  r.cases = {testing::make_case(r.suite, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0, {1.0, 1.2}),
             testing::make_case(r.suite, 0, Method::kTcsb, 0.3, 30, 60, 4, 0.5, {0.6, 0.48}),
             testing::make_case(r.suite, 1, Method::kPlain, std::nullopt, 400, 800, 0, 3.0, {3.0, 3.0}),
             testing::make_case(r.suite, 1, Method::kTcsb, 0.3, 120, 240, 4, 1.0, {1.0, 1.0})};
  r.cases[1].ops.samples = {testing::op(OpKind::kRefine, 1000, 500, 30, 60)};
  r.context.cpu_model = "Test CPU";
  r.context.bullet_precision = "single";
  r.wall_s = 2.0;
  return r;
}

TEST(ResultSchema, EmbeddedSchemaIsTheFileInTheRepository) {
  EXPECT_EQ(result_schema(), read_json(kSource / "results/schema/tcsb-result.schema.json"))
      << "reconfigure: the build embeds the schema at configure time";
}

TEST(ResultSchema, PinsTheCurrentSchemaVersion) {
  EXPECT_EQ(result_schema()["properties"]["schema_version"]["enum"], ojson::array({kNativeJsonSchemaVersion}));
}

TEST(ResultSchema, NativeJsonConforms) { EXPECT_EQ(problems(testing::native_json_of(run_with_cases())), Lines{}); }

TEST(ResultSchema, DivergedAndEmptyRunsConform) {
  RunResult r = run_with_cases();
  testing::diverge(r.cases[3], 17);
  r.cases[2].step_ms = Summary{};
  EXPECT_EQ(problems(testing::native_json_of(r)), Lines{});
  r.cases.clear();
  EXPECT_EQ(problems(testing::native_json_of(r)), Lines{});
}

TEST(ResultSchema, ARunWithAxesConforms) {
  RunResult r = run_with_cases();
  r.suite.axes = {{"tcsb.placement", {"affine", "rigid"}}};
  r.suite.configurations = {{{0}, "placement=affine"}, {{1}, "placement=rigid"}};
  for (std::size_t i = 0, n = r.cases.size(); i < n; ++i) {
    r.cases.push_back(r.cases[i]);
    r.cases.back().key.configuration = 1;
  }
  for (CaseResult& c : r.cases) c.label = case_label(r.suite, c.key);
  ojson doc = testing::native_json_of(r);
  ASSERT_TRUE(doc.contains("configurations"));
  EXPECT_EQ(problems(doc), Lines{});
  doc["cases"][0]["configuration"].erase("label");
  doc["suite"]["axes"]["tcsb.placement"] = ojson::array();
  doc["configurations"][1]["extra"] = 1;
  EXPECT_EQ(problems(doc).size(), 3u) << ::testing::PrintToString(problems(doc));
}

TEST(ResultSchema, AScenesSettingsConform) {
  RunResult r = run_with_cases();
  r.suite.scene.colliders.push_back(Collider{});
  r.suite.scene.camera = Camera{};
  r.suite.scene.wind = Wind{AeroModel::kVTwoSidedLiftDrag, {0, 0, 6}, 0.2, 0.5, 1.2};
  const ojson doc = testing::native_json_of(r);
  EXPECT_EQ(doc["suite"]["scene"]["wind"]["model"], "V_TwoSidedLiftDrag");
  EXPECT_EQ(problems(doc), Lines{});
  ojson broken = doc;
  broken["suite"]["scene"]["wind"]["model"] = "V_Sail";
  EXPECT_FALSE(problems(broken).empty());
}

TEST(ResultSchema, EverySettingWrittenOnlyWhenItMattersConforms) {
  // Each such setting away from its default (and the view on): the block then holds every optional setting.
  RunResult r = run_with_cases();
  r.suite.tcsb.rebuild_dbvt = false;
  r.suite.tcsb.interfaces = Interfaces::kHanging;
  r.suite.tcsb.masses = Masses::kCut;
  r.suite.tcsb.exact_order = true;
  r.suite.tcsb.arrivals_collide = false;
  r.suite.tcsb.start_level = 2;
  FeedbackSettings& f = r.suite.feedback;
  f.popping_charge = f.interface_charge = f.interface_tension = f.pin_level_pull = f.contact_saliency = 0.5;
  f.view_offscreen_share = 0.5;
  f.view_lookahead_s = 0.5;
  f.view_popping_charge = 0.5;
  f.view = true;
  f.budget_scope = BudgetScope::kWorld;
  const ojson doc = testing::native_json_of(r);
  for (const SuiteSetting& row : suite_settings()) {
    if (row.written == Written::kNever) continue;
    const ojson& section = row.section().empty() ? doc["suite"] : doc["suite"][std::string(row.section())];
    EXPECT_TRUE(section.contains(std::string(row.key()))) << row.path;
  }
  EXPECT_EQ(problems(doc), Lines{});
}

TEST(ResultSchema, TheCompliantMaterialConformsWithAndWithoutPasses) {
  RunResult r = run_with_cases();
  r.suite.solver.model = MaterialModel::kCompliant;
  EXPECT_EQ(problems(testing::native_json_of(r)), Lines{});
  r.suite.solver.compliant.passes = 3;
  const ojson doc = testing::native_json_of(r);
  EXPECT_EQ(problems(doc), Lines{});
  ojson broken = doc;
  broken["suite"]["material"]["passes"] = 0;
  EXPECT_FALSE(problems(broken).empty());
}

TEST(ResultSchema, OptionalSectionsOfOtherCommandsConform) {
  ojson doc = testing::native_json_of(run_with_cases());
  doc["reproduction"] = {{"pass", true}};
  doc["fidelity"] = ojson::object();
  doc["pareto"] = ojson::array();
  doc["max_compression"] = ojson::array();
  EXPECT_EQ(problems(doc), Lines{});  // an earlier reproduction's layout stays valid
  doc["reproduction"] = {{"verdict", "undecided"},
                         {"claims", ojson::array({{{"id", "a"}, {"verdict", "pass"}, {"look", 2}, {"repetitions", 10}},
                                                  {{"id", "b"}, {"verdict", "undecided"}, {"look", nullptr}}})}};
  EXPECT_EQ(problems(doc), Lines{});
}

TEST(ResultSchema, FidelityFloorsArePinned) {
  ojson doc = testing::native_json_of(run_with_cases());
  doc["fidelity"] = {{"rows", ojson::array({{{"method", "tcsb"}, {"noise_floor_pct", 0.01}}})},
                     {"floors",
                      ojson::array({{{"net", "n0"},
                                     {"noise_floor_pct", nullptr},
                                     {"interpolation_floor_pct",
                                      ojson::array({{{"compression", 0.5}, {"grid", "7x7"}, {"rms_pct", 0.2}}})}}})}};
  EXPECT_EQ(problems(doc), Lines{});
  doc["fidelity"]["rows"][0]["interpolation_floor_pct"] = "low";
  doc["fidelity"]["floors"][0].erase("noise_floor_pct");
  EXPECT_EQ(problems(doc).size(), 2u) << ::testing::PrintToString(problems(doc));
}

TEST(ResultSchema, AReproductionVerdictIsOneOfThree) {
  ojson doc = testing::native_json_of(run_with_cases());
  doc["reproduction"] = {{"verdict", "maybe"}, {"claims", ojson::array({{{"id", "a"}, {"verdict", true}}})}};
  const Lines p = problems(doc);
  ASSERT_EQ(p.size(), 2u) << ::testing::PrintToString(p);
  EXPECT_NE(p[0].find("reproduction.verdict"), std::string::npos) << p[0];
  EXPECT_NE(p[1].find("reproduction.claims[0].verdict"), std::string::npos) << p[1];
}

TEST(ResultSchema, OpWorkIsOptionalButPinnedWhenPresent) {
  ojson doc = testing::native_json_of(run_with_cases());
  ASSERT_TRUE(doc["cases"][1].contains("op_work"));
  ojson without = doc;
  without["cases"][1].erase("op_work");  // a result written before op_work existed
  EXPECT_EQ(problems(without), Lines{});
  doc["cases"][1]["op_work"]["refine"].erase("links");
  doc["cases"][1]["op_work"]["coarse"]["nodes"]["max"] = -1;
  doc["cases"][1]["op_work"]["end-coarse"].erase("relocation_links");
  EXPECT_EQ(problems(doc).size(), 3u);
}

TEST(ResultSchema, RejectsWhatIsNotANativeResult) {
  ojson doc = testing::native_json_of(run_with_cases());
  doc["schema_version"] = 1;
  doc["cases"][1]["repetitions"][0].erase("final_state_hash");
  doc["cases"][0]["status"] = "fine";
  doc["suite"]["sha256"] = "abc";
  doc["extra"] = 1;
  EXPECT_EQ(problems(doc),
            (Lines{"schema_version: must be one of [2], got 1", "suite.sha256: must have at least 64 characters, got 3",
                   "cases[0].status: must be one of [\"ok\",\"diverged\"], got \"fine\"",
                   "cases[1].repetitions[0].final_state_hash: missing (required)", "extra: unexpected key"}));
}

TEST(ResultSchema, TheCommittedCiBaselineConforms) {
  // A real run of suites/ci.json (scripts/refresh-baseline.sh), so the schema is checked against actual output.
  const std::filesystem::path baseline = kSource / "results/baselines/ci.json";
  ASSERT_TRUE(std::filesystem::exists(baseline)) << baseline;
  const ojson doc = read_json(baseline);
  EXPECT_EQ(problems(doc), Lines{});
  EXPECT_EQ(doc["suite"]["name"], "ci");
  EXPECT_FALSE(doc["cases"].empty());
}

}  // namespace
}  // namespace tcsb
