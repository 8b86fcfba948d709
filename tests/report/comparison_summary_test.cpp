// The Markdown summary of `tcsb compare`: verdict first, one row per metric with the required columns, changed
// behaviour marked, long lists cut.
#include "report/comparison_summary.h"

#include <gtest/gtest.h>

#include <utility>

#include "../gate/result_documents.h"

namespace tcsb {
namespace {

using testing::ojson;
using testing::result_doc;

struct Compared {
  ResultView base, next;
  GateOutcome outcome;
};

Compared compare(const ojson& base_doc, const ojson& next_doc, bool absolute = false) {
  Compared c{read_result(base_doc, "base.json"), read_result(next_doc, "new.json"), {}};
  c.outcome = decide_gate(compare_results(c.base, c.next), {}, absolute);
  return c;
}

std::string summary(const Compared& c) { return comparison_summary_markdown(c.outcome, c.base, c.next); }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ComparisonSummary, PassHasATableRowPerMetric) {
  const std::string s = summary(compare(result_doc(), result_doc()));
  EXPECT_TRUE(s.starts_with("## tcsb compare: PASS\n")) << s;
  EXPECT_NE(s.find("| case | metric | base median | new median | change % | p-value | verdict |"), std::string::npos);
  EXPECT_EQ(count(s, "| ratio vs plain |"), 2u);
  EXPECT_EQ(count(s, "| step ms |"), 4u);
  // The change with its interval: the ratios are the same in every repetition, so the interval is a point.
  EXPECT_NE(s.find("| n9/tcsb@0.5 | ratio vs plain | 0.5 | 0.5 | +0.0 [+0.0, +0.0] | 1 | ok |"), std::string::npos)
      << s;
  EXPECT_NE(s.find("Deterministic metrics: identical in 4 cases and 36 repetitions."), std::string::npos) << s;
  EXPECT_NE(s.find("`base.json` (commit abc"), std::string::npos) << s;
}

TEST(ComparisonSummary, AMergedResultsIntervalsNameTheirProcesses) {
  ojson merged = result_doc();
  for (ojson& c : merged["cases"]) {
    int r = 0;
    for (ojson& rep : c["repetitions"]) rep["process"] = 1 + r++ % 3;  // three shards measured it
  }
  const Compared c = compare(result_doc(), merged);
  EXPECT_EQ(c.outcome.processes(), (std::pair<std::size_t, std::size_t>{1, 3}));
  const std::string s = summary(c);
  EXPECT_NE(s.find("| n9/tcsb@0.5 | ratio vs plain | 0.5 | 0.5 | +0.0 [+0.0, +0.0] (1/3 processes) | 1 | ok |"),
            std::string::npos)
      << s;
}

TEST(ComparisonSummary, RegressionAndChangedBehaviourAreMarked) {
  ojson next = result_doc();
  testing::scale_case(next, 1, 2.0);
  next["cases"][2]["repetitions"][5]["mean_nodes"] = 82.0;
  const Compared c = compare(result_doc(), next);
  const std::string s = summary(c);
  EXPECT_TRUE(s.starts_with("## tcsb compare: FAIL\n")) << s;
  EXPECT_NE(s.find("**1 regression, 1 behaviour change, 1 warning.**"), std::string::npos) << s;
  EXPECT_NE(s.find("| n9/tcsb@0.5 | ratio vs plain | 0.5 | 1 | +100.0 [+100.0, +100.0] |"), std::string::npos) << s;
  EXPECT_NE(s.find("| **REGRESSED** |"), std::string::npos) << s;
  EXPECT_NE(s.find("| n9/tcsb@0.5 | step ms |"), std::string::npos);
  EXPECT_NE(s.find("slower (warning only)"), std::string::npos) << s;
  EXPECT_NE(s.find("| n17/plain | N (rep 5) | 81 | 82 | +1.23 | – | **changed behaviour** |"), std::string::npos) << s;
  EXPECT_EQ(comparison_verdict_line(c.outcome).rfind("FAIL: 1 regression, 1 behaviour change", 0), 0u)
      << comparison_verdict_line(c.outcome);
}

TEST(ComparisonSummary, AbsoluteGatingSaysSo) {
  ojson next = result_doc();
  for (std::size_t i = 0; i < 4; ++i) testing::scale_case(next, i, 2.0);
  const std::string s = summary(compare(result_doc(), next, true));
  EXPECT_EQ(count(s, "**REGRESSED**"), 4u) << s;
  EXPECT_NE(s.find("and absolute `step ms`."), std::string::npos) << s;
}

TEST(ComparisonSummary, UnreliableMetricsAndMachineDifferencesAreExplained) {
  ojson next = result_doc(5);
  next["context"]["cpu_model"] = "Other CPU";
  const std::string s = summary(compare(result_doc(5), next));
  EXPECT_NE(s.find("unreliable (n < 9)"), std::string::npos) << s;
  EXPECT_NE(s.find("- cpu_model: \"Test CPU\" vs \"Other CPU\""), std::string::npos) << s;
}

TEST(ComparisonSummary, UnmatchedCasesAndRepetitionsAreRowsWithTheirLabel) {
  ojson next = result_doc();
  next["cases"].erase(3);
  next["cases"][0]["repetitions"].erase(3);
  const Compared c = compare(result_doc(), next);
  const std::string s = summary(c);
  EXPECT_TRUE(s.starts_with("## tcsb compare: FAIL\n")) << s;
  EXPECT_NE(s.find("| n17/tcsb@0.5 | presence | present | absent | – | – | **changed behaviour** |"), std::string::npos)
      << s;
  EXPECT_NE(s.find("| n9/plain | presence (rep 3) | present | absent | – | – | **changed behaviour** |"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("3 cases, 26 repetitions compared"), std::string::npos) << s;
  EXPECT_EQ(comparison_verdict_line(c.outcome).rfind("FAIL: 0 regressions, 2 behaviour changes", 0), 0u)
      << comparison_verdict_line(c.outcome);
}

TEST(ComparisonSummary, UndecidedTimingsAreSaidWithTheReason) {
  const Compared few = compare(result_doc(5), result_doc(5));
  EXPECT_EQ(undecided_reason(few.outcome),
            "none of the 2 gated timing metrics is reliable (each needs 9 ok repetitions on both sides; the most any "
            "has is 5): rerun with suite.repetitions >= 9");
  const std::string line = comparison_verdict_line(few.outcome);
  EXPECT_EQ(line.rfind("FAIL: 0 regressions, 0 behaviour changes (0 timing metrics gated", 0), 0u) << line;
  EXPECT_NE(line.find("; 2 unreliable, not gated; timings undecided: none of the 2"), std::string::npos) << line;
  EXPECT_TRUE(summary(few).starts_with("## tcsb compare: FAIL\n"));

  ojson plain_only = result_doc();
  plain_only["cases"].erase(3);
  plain_only["cases"].erase(1);
  EXPECT_EQ(undecided_reason(compare(plain_only, plain_only).outcome),
            "no timing metric to gate: no TC-SB case has a plain case on its net for `ratio vs plain` (--absolute "
            "gates the step times too)");
}

TEST(ComparisonSummary, LongChangeListsAreCut) {
  ojson next = result_doc();
  for (std::size_t i = 0; i < 4; ++i) {
    for (ojson& r : next["cases"][i]["repetitions"]) r["final_state_hash"] = "x";  // 36 changes
  }
  for (ojson& r : next["cases"][1]["repetitions"]) r["mean_interpolations"] = 2.0;  // 9 more
  const std::string s = summary(compare(result_doc(), next));
  EXPECT_EQ(count(s, "**changed behaviour**"), kMaxChangeRows);
  EXPECT_NE(s.find("…and 5 more behaviour changes not shown."), std::string::npos) << s;
  EXPECT_NE(s.find("**0 regressions, 45 behaviour changes.**"), std::string::npos) << s;
}

}  // namespace
}  // namespace tcsb
