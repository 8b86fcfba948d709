// The native JSON contract: every key present in a stable order, null (never NaN or Infinity) for anything not
// measured, and the format registry.
#include "report/json_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "paper/run_tables.h"
#include "render_run.h"
#include "report/console_report.h"
#include "report/format_registry.h"
#include "report/native_json_format.h"
#include "run/configuration_result.h"
#include "synthetic_run.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;
using testing::diverge;
using testing::make_case;
using testing::op;
using testing::synthetic_suite;

std::vector<std::string> keys(const ojson& object) {
  std::vector<std::string> out;
  for (const auto& item : object.items()) out.push_back(item.key());
  return out;
}

RunResult small_run() {
  RunResult r;
  r.suite = synthetic_suite(2);
  r.suite.compression = {1.0, 0.3};
  const Suite& s = r.suite;
  r.cases = {make_case(s, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0, {1.0, 1.2}),
             make_case(s, 0, Method::kTcsb, 0.3, 30, 60, 4, 0.5, {0.6, 0.48}),
             make_case(s, 1, Method::kPlain, std::nullopt, 400, 800, 0, 3.0, {3.0, 3.0}),
             make_case(s, 1, Method::kTcsb, 0.3, 120, 240, 4, 1.0, {1.0, 1.0})};
  r.cases[1].ops.samples = {op(OpKind::kRefine, 1000, 500, 30, 60)};
  r.cases[3].ops.samples = {op(OpKind::kRefine, 1000, 600, 120, 240)};
  r.wall_s = 12.5;
  return r;
}

TEST(NativeJson, TopLevelKeysInContractOrder) {
  const ojson doc = testing::native_json_of(small_run());
  EXPECT_EQ(keys(doc), (std::vector<std::string>{"schema_version", "tool", "measure", "context", "suite", "cases",
                                                 "table1", "table2", "scaling", "status", "wall_s"}));
  EXPECT_EQ(doc["measure"], "time") << "what the run measured: `tcsb compare` never mixes time and counts";
  EXPECT_EQ(doc["schema_version"], kNativeJsonSchemaVersion);
  EXPECT_EQ(doc["tool"], "tcsb");
  EXPECT_EQ(doc["status"], "ok");
  EXPECT_EQ(doc["wall_s"], 12.5);
  EXPECT_EQ(keys(doc["scaling"]), (std::vector<std::string>{"step_ms_vs_nodes", "op_ms_vs_nodes"}));
}

/// small_run() with an axis over the seed: configuration 1 holds the same cases, half as fast.
RunResult run_with_axes() {
  RunResult r = small_run();
  r.suite.axes = {{"seed", {7, 8}}};
  r.suite.configurations = {{{0}, "seed=7"}, {{1}, "seed=8"}};
  const std::size_t per_configuration = r.cases.size();
  for (std::size_t i = 0; i < per_configuration; ++i) {
    CaseResult c = r.cases[i];
    c.key.configuration = 1;
    for (RepetitionResult& rep : c.repetitions) rep.mean_step_ms *= (c.key.method == Method::kPlain ? 1.0 : 2.0);
    r.cases.push_back(c);
  }
  for (CaseResult& c : r.cases) c.label = case_label(r.suite, c.key);
  return r;
}

TEST(NativeJson, WithAxesTablesArePerConfigurationAndCasesCarryTheirs) {
  const ojson doc = testing::native_json_of(run_with_axes());
  EXPECT_EQ(keys(doc), (std::vector<std::string>{"schema_version", "tool", "measure", "context", "suite", "cases",
                                                 "table1", "table2", "scaling", "configurations", "status", "wall_s"}));
  EXPECT_EQ(doc["suite"]["axes"], (ojson{{"seed", {7, 8}}}));
  EXPECT_TRUE(doc["table1"].empty());
  EXPECT_TRUE(doc["table2"].empty());
  ASSERT_EQ(doc["cases"].size(), 8u);
  EXPECT_EQ(doc["cases"][5]["label"], "n0/tcsb@0.3[seed=8]");
  EXPECT_EQ(doc["cases"][5]["configuration"], (ojson{{"label", "seed=8"}, {"axes", {{"seed", 8}}}}));
  // Ratios pair within a configuration: the TC-SB case of seed=8 against the plain case of seed=8.
  EXPECT_DOUBLE_EQ(doc["cases"][1]["ratio_vs_plain"].get<double>(), 0.5);  // median of 0.6 / 1.0 and 0.48 / 1.2
  EXPECT_DOUBLE_EQ(doc["cases"][5]["ratio_vs_plain"].get<double>(), 1.0);
  ASSERT_EQ(doc["configurations"].size(), 2u);
  const ojson& second = doc["configurations"][1];
  EXPECT_EQ(keys(second), (std::vector<std::string>{"label", "axes", "cases", "table1", "table2", "scaling"}));
  EXPECT_EQ(second["label"], "seed=8");
  EXPECT_EQ(second["axes"], (ojson{{"seed", 8}}));
  EXPECT_EQ(second["cases"], 4);
  // Each configuration's Table 2 averages its own two nets only.
  ASSERT_EQ(second["table2"].size(), 2u);
  EXPECT_EQ(second["table2"][1]["nets"], 2);
  EXPECT_EQ(doc["configurations"][0]["table2"][1]["nets"], 2);
  // The configuration's tables are those of its cases run alone.
  RunResult alone = small_run();
  EXPECT_EQ(doc["configurations"][0]["table2"], testing::native_json_of(alone)["table2"]);
}

TEST(RunTables, OfARunWithoutAxesAreItsPaperTablesAndPairedRatios) {
  const RunResult r = small_run();
  const RunTables t = run_tables(r);
  EXPECT_TRUE(t.configurations.empty());
  EXPECT_EQ(t.whole.cases, (std::vector<std::size_t>{0, 1, 2, 3}));
  ASSERT_EQ(t.whole.table2.size(), table2(r).size());
  for (std::size_t i = 0; i < t.whole.table2.size(); ++i)
    EXPECT_EQ(t.whole.table2[i].total_ms, table2(r)[i].total_ms) << i;
  EXPECT_EQ(t.whole.table1.size(), table1(r).size());
  EXPECT_EQ(t.whole.step_fits.size(), step_ms_vs_nodes(r).size());
  EXPECT_EQ(t.whole.op_fits.size(), op_ms_vs_nodes(r).size());
  ASSERT_EQ(t.case_ratios.size(), r.cases.size());
  EXPECT_DOUBLE_EQ(*t.case_ratios[1].vs_plain, *paired_ratio(r, 1, 0));
  EXPECT_DOUBLE_EQ(*t.case_ratios[0].vs_plain, 1.0);  // plain against itself
  EXPECT_FALSE(t.case_ratios[1].has_equal_plain);     // the run has no plain_equal
  EXPECT_FALSE(t.fidelity.has_value());
}

TEST(RunTables, WithAxesOneSetPerConfigurationOverItsOwnCases) {
  const RunResult r = run_with_axes();
  const RunTables t = run_tables(r);
  EXPECT_TRUE(t.whole.table2.empty());
  EXPECT_TRUE(t.whole.cases.empty());
  ASSERT_EQ(t.configurations.size(), 2u);
  EXPECT_EQ(t.configurations[1].cases, (std::vector<std::size_t>{4, 5, 6, 7}));
  const std::vector<Table2Row> alone = table2(configuration_result(r, 1));
  ASSERT_EQ(t.configurations[1].table2.size(), alone.size());
  EXPECT_EQ(t.configurations[1].table2[1].total_ms, alone[1].total_ms);
  EXPECT_DOUBLE_EQ(*t.case_ratios[5].vs_plain, 1.0);  // paired within its configuration
}

TEST(NativeJson, RendersTheTablesItIsGivenAndComputesNone) {
  const RunResult r = small_run();
  RunTables t = run_tables(r);
  t.whole.table2.front().total_ms = 123.5;  // not what the run gives: a renderer that recomputed would not show it
  t.case_ratios[1].vs_plain = 0.125;
  const ojson doc = native_json(r, t);
  EXPECT_EQ(doc["table2"][0]["total_ms"], 123.5);
  EXPECT_EQ(doc["cases"][1]["ratio_vs_plain"], 0.125);
  std::ostringstream console;
  print_console_report(r, t, console);
  EXPECT_NE(console.str().find("123.5"), std::string::npos) << console.str();
  EXPECT_NE(console.str().find("0.125"), std::string::npos) << console.str();
}

TEST(NativeJson, WithoutAxesNoConfigurationKeys) {
  const ojson doc = testing::native_json_of(small_run());
  EXPECT_FALSE(doc.contains("configurations"));
  EXPECT_FALSE(doc["suite"].contains("axes"));
  for (const ojson& c : doc["cases"]) EXPECT_FALSE(c.contains("configuration"));
}

TEST(NativeJson, ContextCarriesTheSuiteHashAndSeed) {
  const ojson context = testing::native_json_of(small_run())["context"];
  for (const char* key : {"date_utc", "host", "cpu_model", "compiler", "bullet_version", "git_commit"}) {
    EXPECT_TRUE(context.contains(key)) << key;
  }
  const std::vector<std::string> k = keys(context);
  ASSERT_GE(k.size(), 3u);
  EXPECT_EQ(std::vector<std::string>(k.end() - 3, k.end()),
            (std::vector<std::string>{"suite_path", "suite_sha256", "seed"}));
  EXPECT_EQ(context["suite_sha256"], std::string(64, 'a'));
  EXPECT_EQ(context["seed"], 7);
}

TEST(NativeJson, SuiteBlock) {
  const ojson suite = testing::native_json_of(small_run())["suite"];
  EXPECT_EQ(keys(suite),
            (std::vector<std::string>{"name", "description", "path", "sha256", "steps", "warmup_steps", "repetitions",
                                      "interleave_steps", "interleave_across_nets", "dt", "gravity", "solver", "tcsb",
                                      "feedback", "nets", "methods", "compression"}));
  EXPECT_EQ(keys(suite["solver"]),
            (std::vector<std::string>{"piterations", "viterations", "diterations", "damping", "stiffness"}));
  EXPECT_EQ(keys(suite["tcsb"]),
            (std::vector<std::string>{"blend_steps", "placement", "restore_order", "restore_order_min_nodes"}));
  EXPECT_EQ(suite["feedback"]["policy"], "saliency");
  EXPECT_EQ(suite["methods"], (ojson{"plain", "tcsb"}));
}

TEST(NativeJson, TheCandidateChargesAreWrittenOnlyWhenSet) {
  // Absent at 0, so a suite without it writes what it wrote before the setting existed and its results still
  // compare with older baselines.
  RunResult run = small_run();
  EXPECT_FALSE(testing::native_json_of(run)["suite"]["feedback"].contains("popping_charge"));
  run.suite.feedback.popping_charge = 2.5;
  EXPECT_EQ(testing::native_json_of(run)["suite"]["feedback"]["popping_charge"], 2.5);
  EXPECT_FALSE(testing::native_json_of(run)["suite"]["feedback"].contains("interface_charge"));
  run.suite.feedback.interface_charge = 3;
  EXPECT_EQ(testing::native_json_of(run)["suite"]["feedback"]["interface_charge"], 3.0);
  EXPECT_FALSE(testing::native_json_of(run)["suite"]["feedback"].contains("interface_tension"));
  run.suite.feedback.interface_tension = 0.5;
  EXPECT_EQ(testing::native_json_of(run)["suite"]["feedback"]["interface_tension"], 0.5);
  EXPECT_FALSE(testing::native_json_of(run)["suite"]["feedback"].contains("pin_level_pull"));
  run.suite.feedback.pin_level_pull = 8;
  EXPECT_EQ(testing::native_json_of(run)["suite"]["feedback"]["pin_level_pull"], 8.0);
  EXPECT_FALSE(testing::native_json_of(run)["suite"]["tcsb"].contains("rebuild_dbvt"));
  run.suite.tcsb.rebuild_dbvt = false;
  EXPECT_EQ(testing::native_json_of(run)["suite"]["tcsb"]["rebuild_dbvt"], false);
}

TEST(NativeJson, TheMaterialsLinkPassesAreWrittenOnlyAboveOne) {
  // Absent at one pass a small step, so a compliant suite without the field writes what it wrote before it existed.
  RunResult run = small_run();
  run.suite.solver.model = MaterialModel::kCompliant;
  EXPECT_EQ(testing::native_json_of(run)["suite"]["material"]["substeps"], run.suite.solver.compliant.substeps);
  EXPECT_FALSE(testing::native_json_of(run)["suite"]["material"].contains("passes"));
  run.suite.solver.compliant.passes = 4;
  EXPECT_EQ(testing::native_json_of(run)["suite"]["material"]["passes"], 4);
}

TEST(NativeJson, TcsbCasesCarryTheirPairedRatioToTheGridOfTheirBudget) {
  RunResult r = small_run();
  EXPECT_FALSE(testing::native_json_of(r)["cases"][1].contains("ratio_vs_equal_plain"));  // no plain_equal in the run
  r.suite.methods.push_back(Method::kPlainEqual);
  r.cases.insert(r.cases.begin() + 2, make_case(r.suite, 0, Method::kPlainEqual, 0.3, 30, 55, 0, 0.5, {0.5, 0.4}));
  const ojson doc = testing::native_json_of(r);
  const ojson& tcsb = doc["cases"][1];
  const std::vector<std::string> k = keys(tcsb);
  const auto at = std::find(k.begin(), k.end(), "ratio_vs_equal_plain");
  ASSERT_NE(at, k.end());
  EXPECT_EQ(*(at - 1), "ratio_vs_plain");
  EXPECT_NEAR(tcsb["ratio_vs_equal_plain"].get<double>(), 1.2, 1e-12);  // 0.6 / 0.5 and 0.48 / 0.4, paired
  EXPECT_FALSE(doc["cases"][0].contains("ratio_vs_equal_plain"));       // plain
  EXPECT_FALSE(doc["cases"][2].contains("ratio_vs_equal_plain"));       // plain_equal itself
  EXPECT_FALSE(doc["cases"][4].contains("ratio_vs_equal_plain"));       // n1's TC-SB: no grid on that net
}

TEST(NativeJson, CaseAndRepetitionKeys) {
  const ojson doc = testing::native_json_of(small_run());
  ASSERT_EQ(doc["cases"].size(), 4u);
  const ojson& c = doc["cases"][1];
  EXPECT_EQ(keys(c), (std::vector<std::string>{"label", "net", "method", "compression", "target_nodes", "net_nodes",
                                               "net_links", "status", "mean_nodes", "mean_links", "mean_interpolations",
                                               "mean_feedback_ms", "mean_feedback_total_ms", "step_ms",
                                               "ratio_vs_plain", "step_breakdown_ms", "repetitions", "op_work"}));
  EXPECT_FALSE(doc["cases"][0].contains("op_work"));  // plain: no TreeCut operations
  EXPECT_EQ(keys(c["step_breakdown_ms"]), (std::vector<std::string>{"bullet", "feedback", "operations", "blending"}));
  EXPECT_EQ(c["label"], "n0/tcsb@0.3");
  EXPECT_EQ(c["compression"], 0.3);
  EXPECT_TRUE(doc["cases"][0]["compression"].is_null());
  EXPECT_EQ(keys(c["step_ms"]), (std::vector<std::string>{"count", "median", "mean", "stddev", "cv", "p95", "p99",
                                                          "min", "max", "unstable"}));
  EXPECT_NEAR(c["ratio_vs_plain"].get<double>(), 0.5, 1e-12);  // median of 0.6/1.0 and 0.48/1.2
  ASSERT_EQ(c["repetitions"].size(), 2u);
  EXPECT_EQ(keys(c["repetitions"][0]),
            (std::vector<std::string>{"repetition", "status", "diverged_step", "diverged_reason", "mean_step_ms",
                                      "median_step_ms", "mean_nodes", "mean_links", "mean_interpolations",
                                      "mean_feedback_ms", "mean_feedback_total_ms", "operations", "final_state_hash",
                                      "build_ms"}));
  EXPECT_TRUE(c["repetitions"][0]["diverged_step"].is_null());
}

TEST(NativeJson, OpWorkPerOperationAndCount) {
  RunResult r = small_run();
  OpSample a = op(OpKind::kCoarse, 1000, 500, 30, 60), b = a;
  a.work = {.nodes = 10, .links = 20, .tree_records = 60, .dbvt_leaves = 1, .dbvt_ancestors = 3, .interior = true};
  b.work = {.nodes = 8, .links = 15, .tree_records = 50, .dbvt_leaves = 1, .dbvt_ancestors = 0};
  r.cases[1].ops.samples = {a, b, op(OpKind::kRefine, 1000, 500, 30, 60)};
  const ojson work = testing::native_json_of(r)["cases"][1]["op_work"];
  EXPECT_EQ(keys(work), (std::vector<std::string>{"refine", "end-refine", "coarse", "end-coarse"}));
  EXPECT_EQ(keys(work["coarse"]),
            (std::vector<std::string>{"calls", "interior_calls", "nodes", "links", "tree_records", "dbvt_leaves",
                                      "relocation_nodes", "relocation_links", "dbvt_ancestors"}));
  EXPECT_EQ(keys(work["coarse"]["links"]), (std::vector<std::string>{"max", "mean", "interior_mean"}));
  EXPECT_EQ(work["coarse"]["calls"], 2);
  EXPECT_EQ(work["coarse"]["interior_calls"], 1);
  EXPECT_EQ(work["coarse"]["links"]["max"], 20);
  EXPECT_EQ(work["coarse"]["links"]["mean"], 17.5);
  EXPECT_EQ(work["coarse"]["links"]["interior_mean"], 20);          // a alone
  EXPECT_TRUE(work["refine"]["links"]["interior_mean"].is_null());  // called, but never in the interior
  EXPECT_EQ(work["coarse"]["dbvt_ancestors"]["mean"], 1.5);
  EXPECT_EQ(work["refine"]["calls"], 1);
  EXPECT_EQ(work["refine"]["nodes"]["max"], 0);
  EXPECT_EQ(work["end-refine"]["calls"], 0);  // never called: null, not a misleading 0
  EXPECT_TRUE(work["end-refine"]["nodes"]["max"].is_null());
  EXPECT_TRUE(work["end-refine"]["nodes"]["mean"].is_null());
}

TEST(NativeJson, TablesAndFits) {
  const ojson doc = testing::native_json_of(small_run());
  ASSERT_EQ(doc["table1"].size(), 4u);
  EXPECT_EQ(keys(doc["table1"][0]),
            (std::vector<std::string>{"operation", "N", "L", "node_ops_ms", "link_ops_ms", "complete_ms",
                                      "node_ops_pct", "link_ops_pct", "count", "p50_us", "p99_us"}));
  EXPECT_EQ(doc["table1"][0]["count"], 2);
  ASSERT_EQ(doc["table2"].size(), 2u);
  EXPECT_EQ(keys(doc["table2"][1]),
            (std::vector<std::string>{"method", "compression", "compression_label", "N", "L", "I", "total_ms",
                                      "time_ratio_vs_plain", "node_ratio", "nets", "status"}));
  EXPECT_EQ(doc["table2"][1]["compression_label"], "30%");
  const ojson& steps = doc["scaling"]["step_ms_vs_nodes"];
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(keys(steps[0]), (std::vector<std::string>{"method", "compression", "valid", "slope_ms_per_node",
                                                      "intercept_ms", "r2", "points"}));
  EXPECT_NEAR(steps[0]["slope_ms_per_node"].get<double>(), 2.0 / 300.0, 1e-12);
  const ojson& ops = doc["scaling"]["op_ms_vs_nodes"];
  ASSERT_EQ(ops.size(), 4u);
  EXPECT_EQ(keys(ops[0]), (std::vector<std::string>{"operation", "valid", "slope_ms_per_node", "intercept_ms", "r2",
                                                    "flatness", "points"}));
  EXPECT_TRUE(ops[1]["slope_ms_per_node"].is_null());  // end-refine never ran
}

TEST(NativeJson, NonFiniteBecomesNullNeverNaN) {
  RunResult r = small_run();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  r.cases[0].mean_links = nan;
  r.cases[0].mean_feedback_ms = inf;
  r.cases[0].repetitions[1].build_ms = -inf;
  r.wall_s = nan;
  r.context.mhz = nan;
  const ojson doc = testing::native_json_of(r);
  EXPECT_TRUE(doc["cases"][0]["mean_links"].is_null());
  EXPECT_TRUE(doc["cases"][0]["mean_feedback_ms"].is_null());
  EXPECT_TRUE(doc["cases"][0]["repetitions"][1]["build_ms"].is_null());
  EXPECT_TRUE(doc["wall_s"].is_null());
  const std::string text = testing::render_of(NativeJsonFormat(), r);
  for (const char* bad : {"NaN", "nan", "Infinity", "inf,", "inf\n"}) {
    EXPECT_EQ(text.find(bad), std::string::npos) << bad;
  }
  EXPECT_TRUE(ojson::accept(text));

  EXPECT_TRUE(json_number(nan).is_null());
  EXPECT_TRUE(json_number(std::optional<double>()).is_null());
  EXPECT_EQ(json_number(std::optional<double>(2.5)), 2.5);
}

TEST(NativeJson, DivergedRunIsReportedNotHidden) {
  RunResult r = small_run();
  diverge(r.cases[3], 42);
  const ojson doc = testing::native_json_of(r);
  EXPECT_EQ(doc["status"], "diverged");
  const ojson& c = doc["cases"][3];
  EXPECT_EQ(c["status"], "diverged");
  EXPECT_EQ(c["repetitions"].back()["diverged_step"], 42);
  EXPECT_TRUE(c["mean_nodes"].is_null());
  EXPECT_EQ(doc["table2"][1]["status"], "partial");
}

TEST(NativeJson, EmptyStepSummaryIsNull) {
  RunResult r = small_run();
  r.cases[2].step_ms = Summary{};
  const ojson s = testing::native_json_of(r)["cases"][2]["step_ms"];
  EXPECT_EQ(s["count"], 0);
  EXPECT_TRUE(s["median"].is_null());
  EXPECT_EQ(s["unstable"], false);
}

TEST(ReportFormat, RegistryKnowsJson) {
  const std::unique_ptr<ReportFormat> json = make_format("json");
  ASSERT_NE(json, nullptr);
  EXPECT_EQ(json->name(), "json");
  const std::string text = testing::render_of(*json, small_run());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(ojson::parse(text), testing::native_json_of(small_run()));
  EXPECT_EQ(make_format("nope"), nullptr);
  const std::vector<std::string> names = format_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "json"), names.end());
}

}  // namespace
}  // namespace tcsb
