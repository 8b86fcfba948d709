// The fidelity sections of the reports: present only with a fidelity pass, null (never NaN) for what was not
// measured, and the same numbers in JSON and on the console.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "render_run.h"
#include "report/console_report.h"
#include "report/fidelity_console.h"
#include "report/json_report.h"
#include "synthetic_run.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

FidelityCase fidelity_case(std::string_view method, double compression, double rms) {
  FidelityCase c;
  c.net_name = std::string("n0");  // moved in: GCC 12 -Wrestrict false positive on literal assignment
  c.subject = fidelity_subject(method, compression);
  c.target_nodes = static_cast<int>(100 * compression);
  c.mean_nodes = 100 * compression;
  c.rms_pct = {400, rms, 2 * rms, 3 * rms};
  c.max_pct = {400, 4 * rms, 5 * rms, 6 * rms};
  c.weighted_rms_pct = {400, rms, rms, rms};
  c.popping_pct = {520, 0.01, 0.02, 0.3};
  c.energy_drift_pct = {400, 1, 2, 3};
  c.step_ms = compression;
  c.reference_step_ms = 1.0;
  return c;
}

RunResult run_with_fidelity() {
  RunResult r;
  r.suite = testing::synthetic_suite(1);
  r.suite.compression = {1.0, 0.5};
  r.suite.fidelity.enabled = true;
  r.suite.fidelity.rms_threshold_pct = 1.0;
  r.cases = {testing::make_case(r.suite, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0),
             testing::make_case(r.suite, 0, Method::kTcsb, 1.0, 100, 200, 0, 1.0),
             testing::make_case(r.suite, 0, Method::kTcsb, 0.5, 50, 100, 3, 0.5)};
  FidelityResult f;
  f.cases = {fidelity_case("tcsb", 0.5, 2.0), fidelity_case("tcsb", 1.0, 0.0), fidelity_case("uniform_grid", 0.5, 5.0),
             fidelity_case("switch_body", 0.5, 6.0)};
  f.cases[3].switch_ms = 1.5;
  f.cases[3].switch_step = 12;
  f.cases[2].step_ms = std::numeric_limits<double>::quiet_NaN();  // must come out as null
  FidelityFloors floors;
  floors.net_name = std::string("n0");
  floors.noise_rms_pct = {400, 0.0042, 0.005, 0.006};
  floors.interpolation = {{0.5, "7x7", {400, 0.25, 0.3, 0.4}}, {1.0, "10x10", {400, 0.0, 0.0, 0.0}}};
  f.floors = {floors};
  r.fidelity = f;
  return r;
}

bool has_nan_or_inf(const ojson& j) {
  if (j.is_number_float()) return !std::isfinite(j.get<double>());
  if (!j.is_structured()) return false;  // items() of a primitive would yield the primitive itself
  for (const auto& item : j.items())
    if (has_nan_or_inf(item.value())) return true;
  return false;
}

TEST(FidelityJson, CalibratedTcsbHasItsOwnSweepOnlyWhenItRan) {
  RunResult r = run_with_fidelity();
  EXPECT_FALSE(testing::native_json_of(r).contains("pareto_calibrated"));
  EXPECT_FALSE(testing::native_json_of(r).contains("max_compression_calibrated"));
  r.fidelity->cases.push_back(fidelity_case("tcsb_calibrated", 0.5, 0.8));
  r.fidelity->cases.push_back(fidelity_case("tcsb_calibrated", 0.3, 1.2));
  const ojson doc = testing::native_json_of(r);
  ASSERT_EQ(doc["pareto_calibrated"].size(), 2u);
  EXPECT_EQ(doc["pareto_calibrated"][0]["compression"], 0.3);
  EXPECT_EQ(doc["pareto_calibrated"][1]["rms_pct"], 0.8);
  // 0.3 errs 1.2 % (over the 1 % threshold), 0.5 errs 0.8 %: the calibrated body compresses to half the nodes.
  EXPECT_EQ(doc["max_compression_calibrated"]["compression"], 0.5);
  EXPECT_EQ(doc["max_compression"]["compression"], 1.0) << "TC-SB's own sweep is unchanged";
  EXPECT_EQ(doc["pareto"].size(), 2u);
  std::ostringstream console;
  testing::print_fidelity_report_of(r, console);
  EXPECT_NE(console.str().find("Calibrated TC-SB time versus error"), std::string::npos) << console.str();
}

TEST(FidelityJson, AbsentWithoutAFidelityPass) {
  RunResult r = run_with_fidelity();
  r.fidelity.reset();
  const ojson doc = testing::native_json_of(r);
  EXPECT_FALSE(doc.contains("fidelity"));
  EXPECT_FALSE(doc.contains("pareto"));
  EXPECT_FALSE(doc.contains("max_compression"));
}

TEST(FidelityJson, RowsParetoAndMaxCompression) {
  const ojson doc = testing::native_json_of(run_with_fidelity());
  ASSERT_TRUE(doc.contains("fidelity"));
  const ojson& f = doc["fidelity"];
  ASSERT_EQ(f["rows"].size(), 4u);
  const ojson& row = f["rows"][0];
  for (const char* key : {"method", "compression", "N", "rms_pct", "max_pct", "weighted_rms_pct", "popping_pct",
                          "energy_drift_pct", "time_ratio_vs_plain", "switch_ms"})
    EXPECT_TRUE(row.contains(key)) << key;
  EXPECT_EQ(row["method"], "tcsb");
  EXPECT_EQ(row["rms_pct"]["mean"], 2.0);
  EXPECT_EQ(row["time_ratio_vs_plain"], 0.5);
  EXPECT_EQ(f["rows"][3]["switch_ms"], 1.5);
  EXPECT_EQ(f["cases"][3]["switch_step"], 12);
  EXPECT_TRUE(f["cases"][2]["step_ms"].is_null());
  EXPECT_TRUE(f["rows"][2]["time_ratio_vs_plain"].is_null());
  EXPECT_FALSE(has_nan_or_inf(doc));
  ASSERT_EQ(doc["pareto"].size(), 2u);
  EXPECT_EQ(doc["pareto"][0]["compression"], 0.5);
  EXPECT_EQ(doc["pareto"][0]["on_front"], true);
  // 0.5 fails the 1% threshold (worst net RMS 2%), 1.0 passes: no compression is the most that qualifies.
  EXPECT_EQ(doc["max_compression"]["compression"], 1.0);
  EXPECT_EQ(doc["max_compression"]["threshold_pct"], 1.0);
  ASSERT_TRUE(doc["max_compression"].contains("mean_compression"));  // the mean over the nets, beside the worst net
  bool weighted_target = false;
  for (const ojson& t : f["targets"]) weighted_target |= t["id"] == "fidelity_weighted_vs_uniform_50";
  EXPECT_TRUE(weighted_target);
}

TEST(FidelityJson, FloorsPerNetAndBesideEveryRow) {
  const ojson doc = testing::native_json_of(run_with_fidelity());
  const ojson& f = doc["fidelity"];
  ASSERT_EQ(f["floors"].size(), 1u);
  EXPECT_EQ(f["floors"][0]["net"], "n0");
  EXPECT_EQ(f["floors"][0]["noise_floor_pct"], 0.0042);
  ASSERT_EQ(f["floors"][0]["interpolation_floor_pct"].size(), 2u);
  EXPECT_EQ(f["floors"][0]["interpolation_floor_pct"][0]["grid"], "7x7");
  EXPECT_EQ(f["floors"][0]["interpolation_floor_pct"][0]["rms_pct"], 0.25);
  EXPECT_EQ(f["rows"][0]["noise_floor_pct"], 0.0042);        // tcsb@0.5
  EXPECT_EQ(f["rows"][0]["interpolation_floor_pct"], 0.25);  // its budget's grid
  EXPECT_EQ(f["rows"][1]["interpolation_floor_pct"], 0.0);   // tcsb@1: the full grid
  RunResult unmeasured = run_with_fidelity();
  unmeasured.fidelity->floors[0].noise_rms_pct = {};  // the perturbed reference diverged
  const ojson u = testing::native_json_of(unmeasured);
  EXPECT_TRUE(u["fidelity"]["floors"][0]["noise_floor_pct"].is_null());
  EXPECT_TRUE(u["fidelity"]["rows"][0]["noise_floor_pct"].is_null());
  EXPECT_FALSE(has_nan_or_inf(u));
}

TEST(FidelityJson, UnmeasuredMetricsAreNull) {
  RunResult r = run_with_fidelity();
  r.fidelity->cases[0].status = "diverged";
  r.fidelity->cases[0].rms_pct = {};
  const ojson doc = testing::native_json_of(r);
  EXPECT_TRUE(doc["fidelity"]["cases"][0]["rms_pct"]["mean"].is_null());
  EXPECT_TRUE(doc["fidelity"]["rows"][0]["rms_pct"]["mean"].is_null());
  EXPECT_EQ(doc["fidelity"]["rows"][0]["status"], "diverged");
  EXPECT_FALSE(has_nan_or_inf(doc));
}

TEST(FidelityConsole, PrintsRowsSweepAndTargets) {
  std::ostringstream out;
  testing::print_console_report_of(run_with_fidelity(), out);
  const std::string text = out.str();
  for (const char* expected :
       {"Fidelity against full-resolution", "uniform_grid", "switch_body", "Pareto sweep", "Maximal compression",
        "fidelity_rms_75", "FAIL", "Floors", "noise floor %", "interp floor 50% %", "0.0042", "0.250"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  std::ostringstream none;
  RunResult r = run_with_fidelity();
  r.fidelity.reset();
  testing::print_fidelity_report_of(r, none);
  EXPECT_TRUE(none.str().empty());
}

}  // namespace
}  // namespace tcsb
