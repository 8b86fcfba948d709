// The tax judged on finished runs: which cases are judged, how runs pool, when the verdict is undecided, and what
// is refused. Hand-made documents: a TC-SB case and its plain_equal case per net, the times chosen so the outcome
// is obvious.
#include "gate/adaptivity_tax.h"

#include <gtest/gtest.h>

#include "gate/result_comparison.h"
#include "result_documents.h"

namespace tcsb {
namespace {

using testing::case_doc;
using testing::ojson;
using testing::result_doc;

/// A case of `method` at compression 0.3 on a net of `net_nodes` nodes whose repetitions take `ms[r]`.
ojson budget_case(const std::string& net, const std::string& method, std::int64_t net_nodes,
                  const std::vector<double>& ms) {
  ojson c = case_doc(net, method, 100, ms);
  c["label"] = net + "/" + method + "@0.3";
  c["method"] = method;
  c["compression"] = 0.3;
  c["net_nodes"] = net_nodes;
  return c;
}

/// A run with, per net, TC-SB at 0.3 taking `ratio` x plain_equal's 1 ms in every repetition (times spread a
/// little, so repetitions differ).
ojson run_doc(const std::vector<std::pair<std::string, std::int64_t>>& nets, double ratio, int repetitions = 6) {
  ojson doc = result_doc(repetitions);
  doc["cases"] = ojson::array();
  for (const auto& [net, nodes] : nets) {
    std::vector<double> equal, tcsb;
    for (int r = 0; r < repetitions; ++r) {
      equal.push_back(1.0 + 0.01 * r);
      tcsb.push_back(ratio * (1.0 + 0.01 * r) * (1.0 + 0.002 * (r % 3)));
    }
    doc["cases"].push_back(budget_case(net, "tcsb", nodes, tcsb));
    doc["cases"].push_back(budget_case(net, "plain_equal", nodes, equal));
  }
  return doc;
}

std::vector<NetTax> judge(const std::vector<ojson>& docs, const TaxTarget& target = {}) {
  std::vector<ResultView> views;
  for (std::size_t i = 0; i < docs.size(); ++i) views.push_back(read_result(docs[i], "run" + std::to_string(i)));
  return judge_tax(views, target);
}

TEST(AdaptivityTax, OnlyTheBudgetsCasesOnNetsFromTheMinimumSizeAreJudged) {
  const std::vector<NetTax> nets = judge({run_doc({{"small", 1089}, {"n257", 66049}, {"n513", 263169}}, 1.05)});
  ASSERT_EQ(nets.size(), 2u);
  EXPECT_EQ(nets[0].net, "n257");
  EXPECT_EQ(nets[1].net, "n513");
  EXPECT_EQ(nets[0].claim.id, "tax_n257");
  TaxTarget elsewhere;
  elsewhere.compression = 0.75;  // no case at that budget
  EXPECT_TRUE(judge({run_doc({{"n257", 66049}}, 1.05)}, elsewhere).empty());
}

TEST(AdaptivityTax, ClearlyBelowTheBoundPassesClearlyAboveFails) {
  const std::vector<NetTax> below = judge({run_doc({{"n257", 66049}}, 1.02)});
  ASSERT_EQ(below.size(), 1u);
  ASSERT_TRUE(below[0].claim.interval);
  EXPECT_NEAR(*below[0].claim.measured, 1.02, 0.01);
  EXPECT_EQ(verdict(below[0].claim), Verdict::kPass);
  EXPECT_EQ(tax_verdict(below), Verdict::kPass);
  const std::vector<NetTax> above = judge({run_doc({{"n257", 66049}}, 1.30)});
  EXPECT_EQ(verdict(above[0].claim), Verdict::kFail);
  EXPECT_EQ(above[0].ratios, 6u);
  EXPECT_EQ(above[0].runs, 1u);
}

TEST(AdaptivityTax, TooFewRatiosAreUndecidedNotPassed) {
  const std::vector<NetTax> nets = judge({run_doc({{"n257", 66049}}, 1.02, 3)});
  ASSERT_EQ(nets.size(), 1u);
  EXPECT_FALSE(nets[0].claim.interval);
  EXPECT_EQ(verdict(nets[0].claim), Verdict::kUndecided);
  EXPECT_NE(nets[0].note.find("fewer than 5"), std::string::npos);
}

TEST(AdaptivityTax, RunsPoolAndTheirDisagreementWidensTheInterval) {
  // Two runs of three repetitions each are too few alone; pooled they are six ratios over two runs.
  const ojson low = run_doc({{"n257", 66049}}, 1.00, 3), high = run_doc({{"n257", 66049}}, 1.20, 3);
  const std::vector<NetTax> pooled = judge({low, high});
  ASSERT_EQ(pooled.size(), 1u);
  EXPECT_EQ(pooled[0].runs, 2u);
  EXPECT_EQ(pooled[0].ratios, 6u);
  ASSERT_EQ(pooled[0].run_medians.size(), 2u);
  EXPECT_NEAR(pooled[0].run_medians[0], 1.00, 0.01);
  EXPECT_NEAR(pooled[0].run_medians[1], 1.20, 0.01);
  ASSERT_TRUE(pooled[0].claim.interval);
  // Resampling the runs first: some resamples hold only the 1.00 run, some only the 1.20 run, so the interval
  // spans both and straddles 1.15 — undecided, where six agreeing ratios of one run at 1.10 would pass.
  EXPECT_LT(pooled[0].claim.interval->low, 1.02);
  EXPECT_GT(pooled[0].claim.interval->high, 1.18);
  EXPECT_EQ(verdict(pooled[0].claim), Verdict::kUndecided);
  EXPECT_EQ(verdict(judge({run_doc({{"n257", 66049}}, 1.10)})[0].claim), Verdict::kPass);
}

/// One merged run of 60 repetitions whose three shards (shard p measured repetitions p-1, p+2, ...) measured TC-SB at
/// different ratios to plain_equal (0.95, 1.05, 1.00), a shard's repetitions alike within half a percent.
ojson merged_doc() {
  const double ratio_of_process[] = {0.95, 1.05, 1.00};
  ojson doc = run_doc({{"n257", 66049}}, 1.0, 60);
  for (ojson& c : doc["cases"]) {
    for (ojson& r : c["repetitions"]) {
      const int rep = r["repetition"].get<int>(), process = rep % 3;
      r["process"] = process + 1;
      const double equal = 1.0 + 0.001 * rep;
      const double tcsb = equal * ratio_of_process[process] * (1.0 + 0.001 * (rep % 5));
      r["mean_step_ms"] = c["method"] == "plain_equal" ? equal : tcsb;
    }
  }
  return doc;
}

TEST(AdaptivityTax, AMergedRunsShardsAreResampledBeforeTheirRepetitions) {
  // The same sixty ratios, as one process measured them and as the shards of a merged run did. Pooled, the median
  // of a resample stays among the middle shard's ratios; drawn shard by shard, a resample may hold one shard's only,
  // so the shards' disagreement widens the interval. The row says how many processes it pooled.
  const ojson merged = merged_doc();
  ojson one = merged;
  for (ojson& c : one["cases"])
    for (ojson& r : c["repetitions"]) r.erase("process");
  const std::vector<NetTax> by_process = judge({merged}), pooled = judge({one});
  ASSERT_EQ(by_process.size(), 1u);
  ASSERT_TRUE(by_process[0].claim.interval && pooled[0].claim.interval);
  EXPECT_EQ(by_process[0].processes, 3u);
  EXPECT_EQ(pooled[0].processes, 1u);
  EXPECT_EQ(by_process[0].runs, 1u);
  EXPECT_EQ(*by_process[0].claim.measured, *pooled[0].claim.measured);  // the same data, the same median
  const Interval a = *by_process[0].claim.interval, b = *pooled[0].claim.interval;
  EXPECT_LE(a.low, b.low);
  EXPECT_GE(a.high, b.high);
  EXPECT_GT(a.high - a.low, 2 * (b.high - b.low));
}

TEST(AdaptivityTax, TheSameFilesGiveTheSameInterval) {
  const ojson a = run_doc({{"n257", 66049}}, 1.00, 3), b = run_doc({{"n257", 66049}}, 1.20, 3);
  const NetTax first = judge({a, b})[0], second = judge({a, b})[0];
  EXPECT_EQ(first.claim.interval->low, second.claim.interval->low);
  EXPECT_EQ(first.claim.interval->high, second.claim.interval->high);
}

TEST(AdaptivityTax, ADivergedRepetitionFailsTheNet) {
  ojson doc = run_doc({{"n257", 66049}}, 1.02);
  ojson& rep = doc["cases"][1]["repetitions"][2];  // plain_equal's
  rep["status"] = "diverged";
  rep["diverged_step"] = 17;
  rep["mean_step_ms"] = nullptr;
  const std::vector<NetTax> nets = judge({doc});
  ASSERT_EQ(nets.size(), 1u);
  EXPECT_FALSE(nets[0].claim.measured);
  EXPECT_EQ(verdict(nets[0].claim), Verdict::kFail);
  EXPECT_NE(nets[0].note.find("plain_equal diverged at step 17 in run0, repetition 2"), std::string::npos);
}

TEST(AdaptivityTax, RunsOfOtherSettingsOrBuildsAreNotPooledButOtherRepetitionCountsAre) {
  const ojson base = run_doc({{"n257", 66049}}, 1.02);
  EXPECT_NO_THROW(judge({base, run_doc({{"n257", 66049}}, 1.02, 9)}));
  ojson steps = base;
  steps["suite"]["steps"] = 40;
  EXPECT_THROW(judge({base, steps}), SuiteMismatch);
  ojson build = base;
  build["context"]["git_commit"] = "def";
  try {
    judge({base, build});
    FAIL() << "runs of two builds were pooled";
  } catch (const SuiteMismatch& e) {
    EXPECT_NE(std::string(e.what()).find("context.git_commit"), std::string::npos) << e.what();
  }
  ojson seed = base;
  seed["context"]["seed"] = 2;
  EXPECT_THROW(judge({base, seed}), SuiteMismatch);
}

TEST(AdaptivityTax, OverTheNetsIsTable2sRatioOfTheNetsMeanSteps) {
  // Two nets: the small one at 2x plain_equal, the large one at 1.0x, plain_equal's steps 1 ms and 9 ms: the ratio
  // of the nets' mean steps is (2 + 9) / (1 + 9) = 1.1, not the mean of the nets' ratios, 1.5.
  ojson doc = run_doc({{"a", 100}, {"b", 400}}, 1.0);
  testing::scale_case(doc, 0, 2.0);  // a/tcsb
  testing::scale_case(doc, 2, 9.0);  // b/tcsb
  testing::scale_case(doc, 3, 9.0);  // b/plain_equal
  TaxTarget together;
  together.over_nets = true;
  together.min_net_nodes = 1;
  const std::vector<NetTax> one = judge({doc}, together);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].net, "a+b");
  EXPECT_EQ(one[0].net_nodes, 100);
  EXPECT_EQ(one[0].claim.id, "tax_over_nets");
  EXPECT_EQ(one[0].ratios, 12u);  // six repetitions of each net
  EXPECT_NEAR(*one[0].claim.measured, 1.1, 0.01);
  ASSERT_TRUE(one[0].claim.interval);
  EXPECT_EQ(verdict(one[0].claim), Verdict::kPass);  // the repetitions agree: 1.15 lies well outside
  ASSERT_EQ(one[0].run_medians.size(), 1u);
  EXPECT_NEAR(one[0].run_medians[0], 1.1, 0.01);
  together.min_net_nodes = 200;  // the small net out of scope: the large one alone
  EXPECT_NEAR(*judge({doc}, together)[0].claim.measured, 1.0, 0.01);
}

TEST(AdaptivityTax, OverTheNetsTheRunsDisagreementWidensTheInterval) {
  TaxTarget together;
  together.over_nets = true;
  const std::vector<NetTax> pooled = judge({run_doc({{"n257", 66049}, {"n513", 263169}}, 1.00, 3),
                                            run_doc({{"n257", 66049}, {"n513", 263169}}, 1.20, 3)},
                                           together);
  ASSERT_EQ(pooled.size(), 1u);
  EXPECT_EQ(pooled[0].runs, 2u);
  ASSERT_TRUE(pooled[0].claim.interval);
  EXPECT_LT(pooled[0].claim.interval->low, 1.02);
  EXPECT_GT(pooled[0].claim.interval->high, 1.18);
  EXPECT_EQ(verdict(pooled[0].claim), Verdict::kUndecided);
  const std::vector<NetTax> few = judge({run_doc({{"n257", 66049}}, 1.0, 4)}, together);
  EXPECT_EQ(verdict(few[0].claim), Verdict::kUndecided);
  EXPECT_NE(few[0].note.find("fewer than 5"), std::string::npos);
}

TEST(AdaptivityTax, ARunWithoutTheNetIsIgnoredForItNotCountedAsARatioOfZero) {
  // Two shards of one suite: each holds one net. A net failing clearly (2.5x against 1.15) must fail: the shard
  // without it has no ratio to give, and resampling it as an empty run once pulled the interval down to 0.
  const std::vector<NetTax> nets = judge({run_doc({{"n257", 66049}}, 2.5), run_doc({{"n513", 263169}}, 2.5)});
  ASSERT_EQ(nets.size(), 2u);
  for (const NetTax& n : nets) {
    SCOPED_TRACE(n.net);
    EXPECT_EQ(n.runs, 1u);
    ASSERT_TRUE(n.claim.interval);
    EXPECT_GT(n.claim.interval->low, 2.0);
    EXPECT_EQ(verdict(n.claim), Verdict::kFail);
  }
}

TEST(AdaptivityTax, RunsOfOtherCompilersFlagsBuildTypesOrPrecisionsAreNotPooled) {
  const ojson base = run_doc({{"n257", 66049}}, 1.02);
  for (const char* key : {"build_type", "compiler", "cxx_flags", "sanitized", "bullet_precision"}) {
    SCOPED_TRACE(key);
    ojson other = run_doc({{"n257", 66049}}, 1.03);
    other["context"][key] = "something else";
    try {
      judge({base, other});
      FAIL() << "runs of two builds were pooled";
    } catch (const SuiteMismatch& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("context.") + key), std::string::npos) << e.what();
    }
  }
}

TEST(AdaptivityTax, AJudgedCaseWithoutItsNetSizeIsRefusedNamingTheField) {
  ojson doc = run_doc({{"n257", 66049}}, 1.02);
  doc["cases"][0].erase("net_nodes");
  try {
    judge({doc});
    FAIL() << "judged without knowing the net's size";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run0: cases[0].net_nodes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tcsb
