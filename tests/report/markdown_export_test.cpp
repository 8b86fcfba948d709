// The "markdown" format (one run as a section of docs/results.md): the heading and Source: line from the context,
// the tables' key lines, the optional blocks skipped when absent, and claims rendered whatever fields they have.
#include "report/markdown_export.h"

#include <gtest/gtest.h>

#include "render_run.h"
#include "report/format_registry.h"
#include "report/json_report.h"
#include "synthetic_run.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

RunResult synthetic_run() {
  RunResult r;
  r.suite = testing::synthetic_suite(2);
  r.suite.compression = {0.5};
  r.suite.steps = 200;
  r.suite.repetitions = 1;
  r.cases = {testing::make_case(r.suite, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0),
             testing::make_case(r.suite, 0, Method::kTcsb, 0.5, 50, 100, 3, 0.5),
             testing::make_case(r.suite, 1, Method::kPlain, std::nullopt, 400, 800, 0, 3.0),
             testing::make_case(r.suite, 1, Method::kTcsb, 0.5, 200, 400, 3, 1.5)};
  r.cases[1].ops.samples = {testing::op(OpKind::kRefine, 1000, 500, 30, 60),
                            testing::op(OpKind::kRefine, 3000, 500, 30, 60)};
  r.context.date_utc = "2026-01-02T03:04:05Z";
  r.context.git_commit = "abcdef0123456789";
  r.context.cpu_model = "Test CPU 9000";
  r.context.cores = 2;
  r.context.load_average_1m = 0.25;
  r.wall_s = 12.3456;
  return r;
}

ojson synthetic_document() { return testing::native_json_of(synthetic_run()); }

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MarkdownNumber, FixedSignificantDigitsWithoutExponentsForOrdinaryValues) {
  EXPECT_EQ(markdown_number(ojson(1234.5678)), "1235");
  EXPECT_EQ(markdown_number(ojson(0.412652)), "0.4127");
  EXPECT_EQ(markdown_number(ojson(1.0)), "1.000");
  EXPECT_EQ(markdown_number(ojson(-0.10064)), "-0.1006");
  EXPECT_EQ(markdown_number(ojson(63.425), 3), "63.4");
  EXPECT_EQ(markdown_number(ojson(0.0)), "0");
  EXPECT_EQ(markdown_number(ojson(0.00022084)), "2.208e-04") << "below 0.001 an exponent keeps the digits";
  EXPECT_EQ(markdown_number(ojson(21975)), "21975") << "integers as they are";
  EXPECT_EQ(markdown_number(ojson(nullptr)), "");
  EXPECT_EQ(markdown_number(ojson("1.5")), "") << "a string is not a number";
}

TEST(MarkdownExport, IsARegisteredFormat) {
  const std::unique_ptr<ReportFormat> format = make_format("markdown");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(format->name(), "markdown");
  EXPECT_EQ(testing::render_of(*format, synthetic_run()), markdown_report(synthetic_document()));
}

TEST(MarkdownExport, HeadingAndSourceLineComeFromTheDocument) {
  const std::string md = markdown_report(synthetic_document());
  EXPECT_EQ(md.substr(0, md.find('\n')), "## Run: suite `synthetic`, 2026-01-02, abcdef0");
  EXPECT_TRUE(has_line(md, "Source: suite `synthetic` (2 nets, 1 repetitions of 200 steps) · 2026-01-02 03:04:05 UTC · "
                           "commit abcdef0 · Test CPU 9000, 2 cores · load 0.250 at the start · 12.3 s wall."))
      << md;
  EXPECT_EQ(md.back(), '\n');
  EXPECT_NE(md.substr(md.size() - 2), "\n\n") << "no blank line at the end: the script joins sections";
}

TEST(MarkdownExport, ADirtyBuildSaysSo) {
  RunResult run = synthetic_run();
  run.context.git_commit = "abcdef0123456789-dirty";
  const std::string md = markdown_report(testing::native_json_of(run));
  EXPECT_EQ(md.substr(0, md.find('\n')), "## Run: suite `synthetic`, 2026-01-02, abcdef0-dirty");
  EXPECT_TRUE(contains(md, " · commit abcdef0-dirty · ")) << md;
}

TEST(MarkdownExport, ARecordedCommandLeadsTheSourceLine) {
  ojson doc = synthetic_document();
  doc["context"]["command"] = ojson::array({"tcsb", "run", "ci", "--out", "x|y.json"});
  const std::string md = markdown_report(doc);
  EXPECT_TRUE(contains(md, "Source: `tcsb run ci --out x|y.json` · 2026-01-02 03:04:05 UTC")) << md;
  EXPECT_TRUE(contains(md, "12.3 s wall · suite `synthetic` (2 nets")) << md;
}

TEST(MarkdownExport, Table2Rows) {
  const std::string md = markdown_report(synthetic_document());
  EXPECT_TRUE(has_line(md, "| method | compression | N | L | I | ms | ratio | node ratio | nets | status |")) << md;
  // Means over the two nets: N (100 + 400) / 2, ms (1 + 3) / 2; TC-SB's ratio pairs each net with its plain case.
  EXPECT_TRUE(has_line(md, "| plain | - | 250.0 | 500.0 | 0 | 2.000 | 1.000 | 1.000 | 2 | ok |")) << md;
  EXPECT_TRUE(has_line(md, "| tcsb | 50% | 125.0 | 250.0 | 3.000 | 1.000 | 0.5000 | 0.5000 | 2 | ok |")) << md;
  EXPECT_FALSE(contains(md, "paper")) << "no reproduction block: nothing to put beside";
}

TEST(MarkdownExport, Table2ShowsTheRatioToEqualPlainWhenTheRunHasIt) {
  RunResult r = synthetic_run();
  r.suite.methods.push_back(Method::kPlainEqual);
  r.cases.insert(r.cases.begin() + 2, testing::make_case(r.suite, 0, Method::kPlainEqual, 0.5, 49, 84, 0, 0.4));
  r.cases.push_back(testing::make_case(r.suite, 1, Method::kPlainEqual, 0.5, 196, 364, 0, 1.6));
  const std::string md = markdown_report(testing::native_json_of(r));
  EXPECT_TRUE(has_line(
      md, "| method | compression | N | L | I | ms | ratio | node ratio | ratio to equal plain | nets | status |"))
      << md;
  // (0.5 + 1.5) / (0.4 + 1.6)
  EXPECT_TRUE(has_line(md, "| tcsb | 50% | 125.0 | 250.0 | 3.000 | 1.000 | 0.5000 | 0.5000 | 1.000 | 2 | ok |")) << md;
  EXPECT_TRUE(contains(md, "Ratio to equal plain")) << md;
  // And per net, each TC-SB case paired with its net's grid: 0.5 / 0.4 and 1.5 / 1.6.
  EXPECT_TRUE(contains(md, "### TC-SB against a static grid of its size, per net")) << md;
  EXPECT_TRUE(has_line(md, "| case | N | L | ms | ratio to equal plain |")) << md;
  EXPECT_TRUE(has_line(md, "| n0/tcsb@0.5 | 50.00 | 100.0 | 0.5000 | 1.250 |")) << md;
  EXPECT_TRUE(has_line(md, "| n1/tcsb@0.5 | 200.0 | 400.0 | 1.500 | 0.9375 |")) << md;
}

TEST(MarkdownExport, NoPerNetTaxWithoutPlainEqual) {
  EXPECT_FALSE(contains(markdown_report(synthetic_document()), "static grid of its size")) << "no plain_equal cases";
}

TEST(MarkdownExport, Table1Rows) {
  const std::string md = markdown_report(synthetic_document());
  EXPECT_TRUE(has_line(md, "| operation | N | µs | p50 µs | p99 µs | node % | count |")) << md;
  // Two refines of 1.5 and 3.5 µs (node part 1 and 3 µs): mean 2.5 µs, 80 % of it on nodes.
  EXPECT_TRUE(contains(md, "\n| refine | 30.00 | 2.500 | ")) << md;
  EXPECT_TRUE(contains(md, " | 80.0 | 2 |\n")) << md;
}

TEST(MarkdownExport, ScalingFitsListEveryMethod) {
  const std::string md = markdown_report(synthetic_document());
  EXPECT_TRUE(contains(md, "### Scaling")) << md;
  // Two points per line: (100, 1) and (400, 3) for plain: slope 2/300 ms per node.
  EXPECT_TRUE(contains(md, "| plain | - | 6.667 | 0.3333 | 1.000 | 2 |")) << md;
}

TEST(MarkdownExport, MissingOptionalBlocksAreSkipped) {
  ojson doc = synthetic_document();
  ASSERT_FALSE(doc.contains("fidelity"));
  doc.erase("table1");
  doc.erase("scaling");
  const std::string md = markdown_report(doc);
  EXPECT_TRUE(contains(md, "### Table 2"));
  for (const char* absent : {"### Table 1", "### Scaling", "### Fidelity", "### Claims", "Status:", "Warnings"}) {
    EXPECT_FALSE(contains(md, absent)) << absent << "\n" << md;
  }
}

TEST(MarkdownExport, AnEmptyOrOddDocumentRendersWithoutThrowing) {
  EXPECT_EQ(markdown_report(ojson::object()), "## Run: suite `unnamed`\n\nSource: suite `unnamed`.\n");
  ojson odd = synthetic_document();
  odd["context"]["date_utc"] = 42;
  odd["table2"][0]["N"] = "many";
  odd["table2"][1] = "not a row";
  odd["scaling"] = ojson::array();
  const std::string md = markdown_report(odd);
  EXPECT_TRUE(has_line(md, "| plain | - | many | 500.0 | 0 | 2.000 | 1.000 | 1.000 | 2 | ok |")) << md;
  EXPECT_TRUE(has_line(md, "| | | | | | | | | | |")) << md;
}

TEST(MarkdownExport, ADivergedRunSaysSo) {
  ojson doc = synthetic_document();
  doc["status"] = "diverged";
  EXPECT_TRUE(contains(markdown_report(doc), "Status: **diverged**"));
}

ojson reproduction_block() {
  return {{"paper_hardware", "Old PC"},
          {"table1", ojson::array()},
          {"table2",
           {{{"method", "plain"},
             {"compression", "-"},
             {"paper", {{"N", 4266}, {"L", 8413}, {"I", 0.0}, {"total_ms", 11.09}, {"time_ratio_vs_plain", 1.0}}},
             {"ours", {{"fidelity", nullptr}}}},
            {{"method", "tcsb"},
             {"compression", "50%"},
             {"paper", nullptr},
             {"ours", {{"fidelity", {{"rms_pct", 8.842}, {"max_pct", 47.57}, {"popping_pct", 3.232}}}}}}}},
          {"claims",
           {{{"id", "speed"},
             {"description", "long prose"},
             {"comparison", "at_most"},
             {"expected", 0.4328},
             {"measured", 0.2296},
             {"interval", {{"low", 0.2188}, {"high", 0.8841}}},
             {"pass", true},
             {"decided", false}},
            {{"id", "new|shape"},
             {"verdict", "undecided"},
             {"margin", 0.5},
             {"interval", {{"low", 0.25}, {"high", 0.75}, {"confidence", 0.975}}}},
            {{"id", "bare"}, {"pass", false}}}},
          {"targets", ojson::array()},
          {"pass", true},
          {"bootstrap_s", 1.25},
          {"wall_s", 77.94}};
}

TEST(MarkdownExport, AReproductionPutsThePaperBesideOurs) {
  ojson doc = synthetic_document();
  doc["reproduction"] = reproduction_block();
  const std::string md = markdown_report(doc);
  EXPECT_EQ(md.substr(0, md.find('\n')), "## Reproduction: suite `synthetic`, 2026-01-02, abcdef0");
  EXPECT_TRUE(contains(md, " · 77.9 s wall (claims' intervals 1.25 s).")) << md;
  EXPECT_TRUE(has_line(md, "| method | compression | paper N | ours N | paper L | ours L | paper I | ours I | "
                           "paper ms | ours ms | paper ratio | ours ratio | node ratio | nets | status | RMS % | "
                           "max % | pop max % |"))
      << md;
  EXPECT_TRUE(has_line(md, "| plain | - | 4266 | 250.0 | 8413 | 500.0 | 0 | 0 | 11.09 | 2.000 | 1.000 | 1.000 | "
                           "1.000 | 2 | ok | | | |"))
      << md;
  EXPECT_TRUE(has_line(md, "| tcsb | 50% | | 125.0 | | 250.0 | | 3.000 | | 1.000 | | 0.5000 | 0.5000 | 2 | ok | "
                           "8.842 | 47.57 | 3.232 |"))
      << md;
  EXPECT_TRUE(contains(md, "Paper (Old PC) beside ours.")) << md;
}

TEST(MarkdownExport, ClaimsRenderWhateverFieldsTheyHaveInAStableOrder) {
  ojson doc = synthetic_document();
  doc["reproduction"] = reproduction_block();
  const std::string md = markdown_report(doc);
  // Known fields in a fixed order, the verdict, then unknown fields (margin); description is left out.
  EXPECT_TRUE(has_line(md, "| id | check | expected | measured | interval | verdict | decided | margin |")) << md;
  EXPECT_TRUE(has_line(md, "| speed | at_most | 0.4328 | 0.2296 | 0.2188 – 0.8841 | pass | no | |")) << md;
  EXPECT_TRUE(has_line(md, "| new\\|shape | | | | 0.2500 – 0.7500 (confidence: 0.9750) | undecided | | 0.5000 |"))
      << md;
  EXPECT_TRUE(has_line(md, "| bare | | | | | FAIL | | |")) << md;
  EXPECT_FALSE(contains(md, "long prose"));
  EXPECT_TRUE(contains(md, "Every claim of the paper passed.")) << md;
  EXPECT_FALSE(contains(md, "Targets of this project")) << "an empty list is skipped";
}

TEST(MarkdownExport, FidelitySummary) {
  ojson doc = synthetic_document();
  const ojson metric = {{"mean", 1.5}, {"p95", 2.5}, {"max", 4.0}};
  doc["fidelity"] = {{"rows",
                      {{{"method", "tcsb"},
                        {"compression", 0.3},
                        {"N", 1279.0},
                        {"rms_pct", metric},
                        {"max_pct", metric},
                        {"weighted_rms_pct", metric},
                        {"popping_pct", metric},
                        {"energy_drift_pct", {{"mean", nullptr}, {"p95", nullptr}, {"max", nullptr}}},
                        {"time_ratio_vs_plain", 0.25},
                        {"switch_ms", nullptr},
                        {"worst_net_rms_pct", 3.0},
                        {"grid", nullptr},
                        {"nets", 5},
                        {"status", "ok"}}}},
                     {"targets", {{{"id", "fidelity_rms_30"}, {"comparison", "at_most"}, {"pass", false}}}},
                     {"wall_s", 13.5}};
  doc["pareto"] = {{{"compression", 0.3},
                    {"N", 1279.0},
                    {"time_ratio_vs_plain", 0.25},
                    {"rms_pct", 1.5},
                    {"worst_net_rms_pct", 3.0},
                    {"on_front", true}}};
  doc["max_compression"] = {{"threshold_pct", 2.0}, {"compression", nullptr}};
  doc["pareto_calibrated"] = {{{"compression", 0.3},
                               {"N", 1270.0},
                               {"time_ratio_vs_plain", 0.26},
                               {"rms_pct", 0.9},
                               {"worst_net_rms_pct", 1.1},
                               {"on_front", true}}};
  doc["max_compression_calibrated"] = {
      {"threshold_pct", 2.0}, {"compression", 0.3}, {"worst_net_rms_pct", 1.1}, {"time_ratio_vs_plain", 0.26}};
  const std::string md = markdown_report(doc);
  EXPECT_TRUE(has_line(md, "| tcsb | 30% | 1279 | 1.500 | 2.500 | 4.000 | 1.500 | 4.000 | | 0.2500 | | 3.000 | 5 | "
                           "ok |"))
      << md;
  EXPECT_FALSE(contains(md, "| grid |")) << "no row has a grid";
  EXPECT_TRUE(has_line(md, "| 30% | 1279 | 0.2500 | 1.500 | 3.000 | yes |")) << md;
  EXPECT_TRUE(contains(md, "Maximum compression: none keeps the worst net's RMS error within 2.00 % of its extent."))
      << md;
  EXPECT_TRUE(contains(md, "Pareto sweep (calibrated TC-SB budgets;")) << md;
  EXPECT_TRUE(has_line(md, "| 30% | 1270 | 0.2600 | 0.9000 | 1.100 | yes |")) << md;
  EXPECT_TRUE(contains(md, "Maximum compression of calibrated TC-SB: 30% of the nodes keeps the worst net's RMS error "
                           "within 2.00 % of its extent (worst net 1.100 %, time ratio 0.2600)."))
      << md;
  EXPECT_TRUE(has_line(md, "| fidelity_rms_30 | at_most | FAIL |")) << md;
  EXPECT_TRUE(contains(md, " · 12.3 s wall (fidelity pass 13.5 s).")) << md;
}

TEST(MarkdownExport, AWorldPassHasItsMethodsInOneTable) {
  EXPECT_EQ(markdown_report(synthetic_document()).find("### Many bodies"), std::string::npos) << "no world, no table";
  ojson doc = synthetic_document();
  doc["world"] = {{"bodies", 16},
                  {"scene_nodes", 17424},
                  {"wall_s", 1.0},
                  {"methods",
                   {{{"method", "full_resolution"},
                     {"budget", 1.0},
                     {"status", "ok"},
                     {"mean_nodes", 17424},
                     {"step_ms", 5.4},
                     {"step_ratio", 1.0},
                     {"p95_px", 0.0},
                     {"popping_px", 0.0},
                     {"resolution_changes", 0}},
                    {{"method", "tcsb_world"},
                     {"budget", 0.3},
                     {"status", "ok"},
                     {"mean_nodes", 5374.4},
                     {"step_ms", 2.4},
                     {"step_ratio", 0.452},
                     {"p95_px", 3.92},
                     {"popping_px", 0.35},
                     {"resolution_changes", 5130}}}}};
  const std::string md = markdown_report(doc);
  ASSERT_NE(md.find("### Many bodies"), std::string::npos) << md;
  EXPECT_NE(md.find("16 bodies, 17424 nodes"), std::string::npos) << md;
  EXPECT_NE(md.find("| tcsb_world | 30% | 5374 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.4520 | 3.920 | 0.3500 | 5130 | ok |"), std::string::npos) << md;
}

}  // namespace
}  // namespace tcsb

namespace tcsb {
namespace {

TEST(MarkdownExport, ARunWithAxesHasEachConfigurationsTables) {
  RunResult r = synthetic_run();
  r.suite.axes = {{"solver.piterations", {2, 8}}};
  r.suite.configurations = {{{0}, "piterations=2"}, {{1}, "piterations=8"}};
  for (std::size_t i = 0, n = r.cases.size(); i < n; ++i) {
    r.cases.push_back(r.cases[i]);
    r.cases.back().key.configuration = 1;
  }
  for (CaseResult& c : r.cases) c.label = case_label(r.suite, c.key);
  const std::string md = markdown_report(testing::native_json_of(r));
  const std::size_t first = md.find("### Configuration piterations=2");
  const std::size_t second = md.find("### Configuration piterations=8");
  ASSERT_NE(first, std::string::npos) << md;
  ASSERT_NE(second, std::string::npos) << md;
  // One Table 2 per configuration, none run-wide (the run-wide tables are empty with axes).
  EXPECT_LT(first, md.find("### Table 2"));
  EXPECT_NE(md.find("### Table 2", first), std::string::npos);
  EXPECT_NE(md.find("### Table 2", second), std::string::npos);
  EXPECT_EQ(md.find("### Table 2", md.find("### Table 2", first) + 1), md.find("### Table 2", second));
}

}  // namespace
}  // namespace tcsb
