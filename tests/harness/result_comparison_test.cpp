// The comparison's input contract: different suites are refused, every deterministic difference is listed, and
// the timing samples are the same-run ratios and the absolute step times.
#include "harness/result_comparison.h"

#include <gtest/gtest.h>

#include "result_documents.h"

namespace tcsb {
namespace {

using testing::ojson;
using testing::result_doc;

ResultComparison compare(const ojson& base, const ojson& next) {
  return compare_results(read_result(base, "base.json"), read_result(next, "new.json"));
}

std::string mismatch(const ojson& base, const ojson& next) {
  try {
    compare(base, next);
  } catch (const SuiteMismatch& e) {
    return e.what();
  }
  return "";
}

TEST(ResultComparison, IdenticalRunsHaveNoChanges) {
  const ResultComparison c = compare(result_doc(), result_doc());
  EXPECT_TRUE(c.changes.empty());
  EXPECT_TRUE(c.deterministic);
  EXPECT_EQ(c.suite_name, "tiny");
  EXPECT_EQ(c.cases, 4u);
  EXPECT_EQ(c.repetitions, 36u);
  ASSERT_EQ(c.ratios.size(), 2u) << "one per TC-SB case";
  EXPECT_EQ(c.ratios[0].case_label, "n9/tcsb@0.5");
  EXPECT_EQ(c.ratios[0].metric, std::string(kRatioMetric));
  EXPECT_EQ(c.ratios[0].samples.base.size(), 9u);
  EXPECT_DOUBLE_EQ(c.ratios[0].samples.next[4], 0.5);
  ASSERT_EQ(c.step_ms.size(), 4u) << "one per case";
  EXPECT_EQ(c.step_ms[2].case_label, "n17/plain");
  EXPECT_TRUE(c.machine_differences.empty());
}

TEST(ResultComparison, DifferentSuitesAreRefusedNamingTheField) {
  ojson other = result_doc();
  other["suite"]["sha256"] = std::string(64, 'b');
  EXPECT_NE(mismatch(result_doc(), other).find("suite.sha256"), std::string::npos) << mismatch(result_doc(), other);

  // Same file, narrowed on the command line (e.g. --compression): still a different run.
  other = result_doc();
  other["suite"]["methods"] = {"plain"};
  const std::string m = mismatch(result_doc(), other);
  EXPECT_NE(m.find("suite.methods"), std::string::npos) << m;
  EXPECT_NE(m.find("base.json"), std::string::npos) << m;
  EXPECT_NE(m.find("new.json"), std::string::npos) << m;

  other = result_doc();
  other["suite"]["feedback"]["max_step_ms"] = 2.0;
  EXPECT_NE(mismatch(result_doc(), other).find("suite.feedback.max_step_ms"), std::string::npos);

  other = result_doc();
  other["context"]["seed"] = 2;
  EXPECT_NE(mismatch(result_doc(), other).find("context.seed"), std::string::npos);
}

TEST(ResultComparison, ThePathOfTheSuiteFileDoesNotMatter) {
  ojson other = result_doc();
  other["suite"]["path"] = "/elsewhere/tiny.json";
  EXPECT_TRUE(compare(result_doc(), other).changes.empty());
}

TEST(ResultComparison, EveryDeterministicDifferenceIsListed) {
  ojson next = result_doc();
  next["cases"][1]["mean_nodes"] = 41.0;
  next["cases"][1]["repetitions"][4]["mean_nodes"] = 41.0;
  next["cases"][2]["repetitions"][0]["final_state_hash"] = "other";
  next["cases"][3]["repetitions"][8]["mean_interpolations"] = 2.0;
  next["cases"][3]["repetitions"][7]["operations"] = 8;
  next["cases"][0]["repetitions"][1]["status"] = "diverged";
  next["cases"][0]["repetitions"][1]["diverged_step"] = 12;
  const ResultComparison c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 6u);
  const auto has = [&](const char* label, const char* metric, std::optional<int> rep, const char* base,
                       const char* now) {
    for (const BehaviourChange& b : c.changes) {
      if (b.case_label == label && b.metric == metric && b.repetition == rep) {
        EXPECT_EQ(b.base, base);
        EXPECT_EQ(b.next, now);
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(has("n9/tcsb@0.5", "N", std::nullopt, "40", "41"));
  EXPECT_TRUE(has("n9/tcsb@0.5", "N", 4, "40", "41"));
  EXPECT_TRUE(has("n17/plain", "final_state_hash", 0, "h0", "other"));
  EXPECT_TRUE(has("n17/tcsb@0.5", "I", 8, "1.5", "2"));
  EXPECT_TRUE(has("n17/tcsb@0.5", "operations", 7, "7", "8"));
  EXPECT_TRUE(has("n9/plain", "status", 1, "ok", "diverged at step 12"));
}

TEST(ResultComparison, MissingCasesAndRepetitionsAreChanges) {
  ojson next = result_doc();
  next["cases"].erase(3);
  next["cases"][0]["repetitions"].erase(8);
  const ResultComparison c = compare(result_doc(), next);
  ASSERT_GE(c.changes.size(), 2u);
  EXPECT_EQ(c.changes[0].metric, "cases");
  EXPECT_EQ(c.changes[1].metric, "repetitions");
  EXPECT_EQ(c.changes[1].base, "9");
  EXPECT_EQ(c.changes[1].next, "8");
  EXPECT_EQ(c.cases, 3u);
}

TEST(ResultComparison, RatiosFollowTheSameRunNotTheMachine) {
  // Everything twice as slow (a slower machine): the ratios do not move, the absolute times do.
  ojson next = result_doc();
  for (std::size_t i = 0; i < 4; ++i) testing::scale_case(next, i, 2.0);
  const ResultComparison c = compare(result_doc(), next);
  EXPECT_DOUBLE_EQ(c.ratios[1].samples.next[3], c.ratios[1].samples.base[3]);
  EXPECT_DOUBLE_EQ(c.step_ms[1].samples.next[3], 2.0 * c.step_ms[1].samples.base[3]);
}

TEST(ResultComparison, ATimeBudgetMakesNodeCountsMachineDependent) {
  ojson base = result_doc(), next = result_doc();
  base["suite"]["feedback"]["max_step_ms"] = 0.5;
  next["suite"]["feedback"]["max_step_ms"] = 0.5;
  next["cases"][1]["mean_nodes"] = 39.0;
  const ResultComparison c = compare(base, next);
  EXPECT_FALSE(c.deterministic);
  EXPECT_TRUE(c.changes.empty());
}

TEST(ResultComparison, MachineDifferencesAreListed) {
  ojson next = result_doc();
  next["context"]["cpu_model"] = "Other CPU";
  next["context"]["build_type"] = "Debug";
  next["context"]["host"] = "elsewhere";  // any two runs differ in host: not worth a warning
  const ResultComparison c = compare(result_doc(), next);
  ASSERT_EQ(c.machine_differences.size(), 2u);
  EXPECT_EQ(c.machine_differences[0], "cpu_model: \"Test CPU\" vs \"Other CPU\"");
  EXPECT_EQ(c.machine_differences[1], "build_type: \"Release\" vs \"Debug\"");
}

TEST(ResultComparison, HugePageSettingsCountAsMachineDifferences) {
  ojson base = result_doc();
  base["context"]["transparent_hugepages"] = "madvise";
  base["context"]["glibc_tunables"] = "";  // unset
  ojson next = base;
  next["context"]["glibc_tunables"] = "glibc.malloc.hugetlb=1";
  const ResultComparison c = compare(base, next);
  ASSERT_EQ(c.machine_differences.size(), 1u);
  EXPECT_EQ(c.machine_differences[0], "glibc_tunables: \"\" vs \"glibc.malloc.hugetlb=1\"");
}

}  // namespace
}  // namespace tcsb
