// The reproduction is judged and its tables computed once (paper/reproduction.h); the report renders what it is
// given and computes nothing: the tables it shows are the Reproduction's, of the run after its last look.
#include "report/reproduction_report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "synthetic_run.h"

namespace tcsb {
namespace {

using testing::make_case;
using testing::synthetic_suite;

/// Two nets, plain and TC-SB at 50 %, six repetitions each (enough for intervals), no operations.
RunResult two_nets_six_repetitions() {
  RunResult run;
  run.suite = synthetic_suite(2);
  run.suite.compression = {0.5};
  for (std::size_t net = 0; net < 2; ++net) {
    run.cases.push_back(
        make_case(run.suite, net, Method::kPlain, std::nullopt, 100, 300, 0, 2.0, {2.0, 2.1, 1.9, 2.0, 2.05, 1.95}));
    run.cases.push_back(
        make_case(run.suite, net, Method::kTcsb, 0.5, 50, 150, 1, 1.0, {1.0, 1.05, 0.95, 1.0, 1.02, 0.98}));
  }
  return run;
}

PaperReference paper() {
  return load_paper_reference(std::filesystem::path(TCSB_SOURCE_DIR) / "results" / "paper.json");
}

TEST(Reproduction, TablesAreThoseOfTheRunAfterItsLastLook) {
  RunResult run = two_nets_six_repetitions();
  ReproductionOptions options;
  options.budget_s = 0;  // the first look only: the run's own repetitions
  const Reproduction r = check_reproduction(run, paper(), options);
  const std::vector<Table2Row> rows = table2(run);
  ASSERT_EQ(r.tables.run.whole.table2.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(r.tables.run.whole.table2[i].method, rows[i].method);
    EXPECT_EQ(r.tables.run.whole.table2[i].total_ms, rows[i].total_ms);
    EXPECT_EQ(r.tables.run.whole.table2[i].time_ratio_vs_plain, rows[i].time_ratio_vs_plain);
  }
  EXPECT_EQ(r.tables.run.whole.table1.size(), table1(run).size());
  EXPECT_EQ(r.tables.tcsb_fit.points.size(), step_fit_of_method(run, Method::kTcsb).points.size());
  EXPECT_FALSE(r.tables.run.fidelity.has_value());
  for (const TrackedClaim& t : r.targets) EXPECT_EQ(t.claim.id.rfind("fidelity_", 0), std::string::npos) << t.claim.id;
}

TEST(Reproduction, TheRenderersShowTheTablesTheyAreGiven) {
  RunResult run = two_nets_six_repetitions();
  Reproduction r = check_reproduction(run, paper());
  ASSERT_FALSE(r.tables.run.whole.table2.empty());
  r.tables.run.whole.table2.front().total_ms =
      123.5;  // not what the run gives: a renderer that recomputed would not show it
  const nlohmann::ordered_json doc = reproduction_json(r);
  EXPECT_EQ(doc["table2"][0]["ours"]["total_ms"], 123.5);
  std::ostringstream console;
  print_reproduction(r, false, console);
  EXPECT_NE(console.str().find("123.5"), std::string::npos) << console.str();
}

}  // namespace
}  // namespace tcsb
