// The comparison's input contract: different suites are refused, every deterministic difference is listed, and
// the timing samples are the same-run ratios and the absolute step times.
#include "gate/result_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>

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

TEST(ResultComparison, ACaseOfOneLabelMustAgreeOnEveryFieldThatPlacesIt) {
  for (const char* field : {"net", "method", "compression"}) {
    SCOPED_TRACE(field);
    ojson next = result_doc();
    next["cases"][3][field] = std::string(field) == "compression" ? ojson(0.25) : ojson("other");
    EXPECT_NE(mismatch(result_doc(), next).find(std::string("new.json: cases[3].") + field), std::string::npos)
        << mismatch(result_doc(), next);
  }
  ojson next = result_doc();
  next["cases"][3]["configuration"] = {{"label", "x=1"}};
  EXPECT_NE(mismatch(result_doc(), next)
                .find("cases[3].configuration.label: \"x=1\", but base.json's case "
                      "n17/tcsb@0.5 has \"\""),
            std::string::npos)
      << mismatch(result_doc(), next);
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

/// The change of `metric` in case `label` (repetition `rep`, or the case itself), or nullptr.
const BehaviourChange* find_change(const ResultComparison& c, const std::string& label, const std::string& metric,
                                   std::optional<int> rep = std::nullopt) {
  for (const BehaviourChange& b : c.changes) {
    if (b.case_label == label && b.metric == metric && b.repetition == rep) return &b;
  }
  return nullptr;
}

/// Expects exactly one presence change for `label` (and `rep`), with these occurrences.
void expect_presence(const ResultComparison& c, const std::string& label, std::optional<int> rep,
                     const std::string& base, const std::string& next) {
  const BehaviourChange* b = find_change(c, label, kPresenceMetric, rep);
  ASSERT_NE(b, nullptr) << label << (rep ? " rep " + std::to_string(*rep) : std::string());
  EXPECT_EQ(b->base, base) << label;
  EXPECT_EQ(b->next, next) << label;
}

// One to one by label: a missing case is named wherever it was, the first or a later one.
TEST(ResultComparison, EveryMissingCaseIsNamed) {
  for (std::size_t gone = 0; gone < 4; ++gone) {
    ojson next = result_doc();
    const std::string label = next["cases"][gone]["label"];
    next["cases"].erase(gone);
    const ResultComparison c = compare(result_doc(), next);
    ASSERT_EQ(c.changes.size(), 1u) << label;
    expect_presence(c, label, std::nullopt, "present", "absent");
    EXPECT_EQ(c.cases, 3u);
    EXPECT_EQ(c.repetitions, 27u);
    // The other way round: the case is extra in the new run.
    const ResultComparison reverse = compare(next, result_doc());
    ASSERT_EQ(reverse.changes.size(), 1u) << label;
    expect_presence(reverse, label, std::nullopt, "absent", "present");
  }
}

TEST(ResultComparison, AnExtraCaseIsNamed) {
  ojson next = result_doc();
  next["cases"].push_back(testing::case_doc("n25", "plain", 625, testing::around(3.0)));
  const ResultComparison c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 1u);
  expect_presence(c, "n25/plain", std::nullopt, "absent", "present");
  EXPECT_EQ(c.cases, 4u);
  EXPECT_EQ(c.step_ms.size(), 4u) << "an unmatched case has no timings";
}

TEST(ResultComparison, ADuplicatedLabelCannotBeMatched) {
  // An exact copy of a case, so no value differs: only the matching can tell.
  ojson next = result_doc();
  next["cases"].push_back(next["cases"][1]);
  ResultComparison c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 1u);
  expect_presence(c, "n9/tcsb@0.5", std::nullopt, "present", "2 entries");
  EXPECT_EQ(c.cases, 3u) << "neither copy is compared";
  EXPECT_EQ(c.ratios.size(), 1u) << "nor timed";

  // Duplicated on both sides is no better: two entries cannot be paired one to one either.
  c = compare(next, next);
  ASSERT_EQ(c.changes.size(), 1u);
  expect_presence(c, "n9/tcsb@0.5", std::nullopt, "2 entries", "2 entries");

  // A case renamed to another's label: one label gone, one doubled.
  next = result_doc();
  next["cases"][2]["label"] = "n9/plain";
  c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 2u);
  expect_presence(c, "n9/plain", std::nullopt, "present", "2 entries");
  expect_presence(c, "n17/plain", std::nullopt, "present", "absent");
}

TEST(ResultComparison, CasesAndRepetitionsMatchByKeyNotByPosition) {
  ojson next = result_doc();
  std::reverse(next["cases"].begin(), next["cases"].end());
  ojson& reps = next["cases"][3]["repetitions"];  // n9/plain, now last
  std::reverse(reps.begin(), reps.end());
  ResultComparison c = compare(result_doc(), next);
  EXPECT_TRUE(c.changes.empty());
  EXPECT_EQ(c.cases, 4u);
  EXPECT_EQ(c.repetitions, 36u);
  ASSERT_EQ(c.ratios.size(), 2u);
  EXPECT_EQ(c.ratios[0].case_label, "n9/tcsb@0.5");
  EXPECT_EQ(c.ratios[0].samples.next.size(), 9u);

  // A change in a reordered repetition is found on that repetition.
  reps[6]["final_state_hash"] = "other";  // repetition 2
  c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 1u);
  EXPECT_NE(find_change(c, "n9/plain", "final_state_hash", 2), nullptr);
}

TEST(ResultComparison, EveryUnmatchedRepetitionIsNamed) {
  // One missing: named by its number, not only counted.
  ojson next = result_doc();
  next["cases"][0]["repetitions"].erase(3);
  ResultComparison c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 1u);
  expect_presence(c, "n9/plain", 3, "present", "absent");
  EXPECT_EQ(c.repetitions, 35u);

  // Renumbered with every hash changed: the same count, and not one pair to compare.
  next = result_doc();
  for (ojson& r : next["cases"][1]["repetitions"]) {
    r["repetition"] = r["repetition"].get<int>() + 9;
    r["final_state_hash"] = "changed";
  }
  c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 18u);
  for (int r = 0; r < 9; ++r) {
    expect_presence(c, "n9/tcsb@0.5", r, "present", "absent");
    expect_presence(c, "n9/tcsb@0.5", r + 9, "absent", "present");
  }
  EXPECT_EQ(c.repetitions, 27u);

  // A copy of repetition 8 in place of repetition 7: the count and every value still agree.
  next = result_doc();
  next["cases"][2]["repetitions"][7] = next["cases"][2]["repetitions"][8];
  c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 2u);
  expect_presence(c, "n17/plain", 7, "present", "absent");
  expect_presence(c, "n17/plain", 8, "present", "2 entries");
  EXPECT_EQ(c.repetitions, 34u);

  // An extra repetition.
  next = result_doc();
  next["cases"][3]["repetitions"].push_back(testing::repetition_doc(9, 0.5, 40));
  c = compare(result_doc(), next);
  ASSERT_EQ(c.changes.size(), 1u);
  expect_presence(c, "n17/tcsb@0.5", 9, "absent", "present");
}

TEST(ResultComparison, MatchingDoesNotDependOnDeterminism) {
  // With a time budget the values may differ, but which cases and repetitions ran may not.
  ojson base = result_doc();
  base["suite"]["feedback"]["max_step_ms"] = 0.5;
  ojson next = base;
  next["cases"].erase(3);
  next["cases"][0]["repetitions"].erase(8);
  const ResultComparison c = compare(base, next);
  ASSERT_EQ(c.changes.size(), 2u);
  expect_presence(c, "n17/tcsb@0.5", std::nullopt, "present", "absent");
  expect_presence(c, "n9/plain", 8, "present", "absent");
  EXPECT_EQ(c.repetitions, 26u);
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
