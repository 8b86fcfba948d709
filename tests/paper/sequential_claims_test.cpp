// Claims judged in looks, with a fake runner and a fake clock: which cases get extra repetitions, when the looks
// stop (decided, out of budget, out of looks), and that a claim keeps the verdict of the look that decided it.
#include "paper/sequential_claims.h"

#include <gtest/gtest.h>

#include <deque>

#include "run/case_summary.h"

namespace tcsb {
namespace {

/// One net with plain, TC-SB at 0.5 and TC-SB at 0.9; every step costs `ms` and a repetition 1000 steps, so one
/// repetition of a case costs ms seconds by repetition_cost_s.
struct Fixture {
  RunResult run;
  double clock_s = 0;               ///< the fake clock
  std::deque<double> next_tcsb_ms;  ///< step times of the extra TC-SB@0.5 repetitions, in order (then 0.9)
  std::vector<std::vector<std::size_t>> runs_of;  ///< the cases of each run_more call
  std::vector<int> extras;

  Fixture(const std::vector<double>& tcsb_ms) {
    run.suite.seed = 3;
    run.suite.steps = 1000;
    run.suite.warmup_steps = 0;
    const std::optional<double> targets[] = {std::nullopt, 0.5, 0.9};
    for (int c = 0; c < 3; ++c) {
      CaseResult& k = run.cases.emplace_back();
      k.key = CaseKey{0, c == 0 ? Method::kPlain : Method::kTcsb, targets[c]};
      k.label = c == 0 ? "n/plain" : c == 1 ? "n/tcsb@0.5" : "n/tcsb@0.9";
      for (std::size_t r = 0; r < tcsb_ms.size(); ++r) add(k, c == 1 ? tcsb_ms[r] : 1.0);
    }
  }

  static void add(CaseResult& k, double ms) {
    RepetitionResult& x = k.repetitions.emplace_back();
    x.repetition = static_cast<int>(k.repetitions.size()) - 1;
    x.mean_step_ms = x.median_step_ms = ms;
    summarize_case(k);
  }

  SequentialHooks hooks(bool with_target = false) {
    SequentialHooks h;
    h.claims_of = [with_target](const RunResult& r) {
      JudgedClaims judged;
      judged.claims = {check_claim("tcsb_at_most_1", "", Comparison::kAtMost, 1.0, 0.0,
                                   r.cases.size() > 1 ? std::optional(r.cases[1].step_ms.median) : std::nullopt,
                                   Evidence::kRepeated),
                       check_claim("exact", "", Comparison::kAtMost, 1.0, 0.0, 0.5)};
      if (with_target)  // undecided at 0.9: 1.0 +- nothing, straddling forever
        judged.targets.push_back(check_claim(
            "target_09", "", Comparison::kAtMost, 1.0, 0.0,
            r.cases.size() > 2 ? std::optional(r.cases[2].step_ms.median) : std::nullopt, Evidence::kRepeated));
      return judged;
    };
    h.scope_of = [](std::string_view id) -> std::optional<ClaimScope> {
      if (id == "tcsb_at_most_1") return ClaimScope{.plain = true, .tcsb_targets = {0.5}};
      if (id == "target_09") return ClaimScope{.plain = true, .tcsb_targets = {0.9}};
      return std::nullopt;
    };
    h.run_more = [this](RunResult& r, const std::vector<std::size_t>& cases, int extra) {
      clock_s += repetition_cost_s(r, cases) * extra;  // exactly what the loop predicts, before its margin
      runs_of.push_back(cases);
      extras.push_back(extra);
      for (int e = 0; e < extra; ++e) {
        for (const std::size_t c : cases) {
          double ms = 1.0;
          if (c == 1) {
            ms = next_tcsb_ms.empty() ? 0.9 : next_tcsb_ms.front();
            if (!next_tcsb_ms.empty()) next_tcsb_ms.pop_front();
          }
          add(r.cases[c], ms);
        }
      }
    };
    h.now_s = [this] { return clock_s; };
    return h;
  }
};

/// Five repetitions around the threshold: 0.8 and 1.2 alternate, so look 1 cannot decide.
const std::vector<double> kStraddling{0.8, 1.2, 0.8, 1.2, 0.9};

TEST(SequentialClaims, AClaimDecidedByItsRepetitionsTakesOneLook) {
  Fixture f({0.5, 0.6, 0.55, 0.5, 0.6});
  SequentialSettings s;
  s.budget_s = 100;
  const SequentialOutcome o = judge_sequentially(f.run, s, f.hooks());
  EXPECT_EQ(o.ended, LooksEnded::kDecided);
  ASSERT_EQ(o.looks.size(), 1u);
  EXPECT_TRUE(f.runs_of.empty());
  EXPECT_EQ(verdict(o.claims[0].claim), Verdict::kPass);
  EXPECT_EQ(o.claims[0].look, 1);
  EXPECT_EQ(o.claims[0].repetitions, 5);
  EXPECT_DOUBLE_EQ(o.claims[0].confidence, 0.95);
  EXPECT_EQ(o.claims[1].look, 0);  // deterministic: not judged in looks
  EXPECT_EQ(verdict(o.claims[1].claim), Verdict::kPass);
}

TEST(SequentialClaims, MoreRepetitionsOfJustItsCasesDecideAnUndecidedClaim) {
  Fixture f(kStraddling);  // extra TC-SB repetitions at 0.9 (the fixture's default): a true pass
  SequentialSettings s;
  s.budget_s = 1000;
  const SequentialOutcome o = judge_sequentially(f.run, s, f.hooks());
  EXPECT_EQ(o.ended, LooksEnded::kDecided);
  ASSERT_GE(o.looks.size(), 2u);
  EXPECT_EQ(o.looks[0].undecided, 1);
  EXPECT_EQ(verdict(o.claims[0].claim), Verdict::kPass);
  EXPECT_EQ(o.claims[0].look, static_cast<int>(o.looks.size()));
  EXPECT_GT(o.claims[0].repetitions, 5);
  EXPECT_LT(o.claims[0].confidence, 1.0);
  EXPECT_GT(o.claims[0].confidence, 0.95);  // judged at a stricter level than the first look
  // Only TC-SB at 0.5 and its plain baseline ran more, side by side; TC-SB at 0.9 kept its five.
  for (const std::vector<std::size_t>& cases : f.runs_of) EXPECT_EQ(cases, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(f.run.cases[0].repetitions.size(), f.run.cases[1].repetitions.size());
  EXPECT_EQ(f.run.cases[2].repetitions.size(), 5u);
  EXPECT_EQ(f.extras.front(), 5);  // the first extra look doubles the repetitions
}

TEST(SequentialClaims, StopsWithinTheBudgetWhenTheClaimStaysUndecided) {
  Fixture f(kStraddling);
  for (int i = 0; i < 1000; ++i) f.next_tcsb_ms.push_back(i % 2 == 0 ? 0.8 : 1.2);  // forever at the threshold
  SequentialSettings s;
  s.budget_s = 40;  // a repetition of the two cases costs ~2 s (x 1.25 margin)
  const SequentialOutcome o = judge_sequentially(f.run, s, f.hooks());
  EXPECT_EQ(o.ended, LooksEnded::kBudget);
  EXPECT_EQ(verdict(o.claims[0].claim), Verdict::kUndecided);
  EXPECT_LE(f.clock_s, s.budget_s);
  EXPECT_GE(o.looks.size(), 2u);  // it did try
  EXPECT_EQ(o.claims[0].look, static_cast<int>(o.looks.size()));
}

TEST(SequentialClaims, ABudgetOfZeroTakesOnlyTheFirstLook) {
  Fixture f(kStraddling);
  const SequentialOutcome o = judge_sequentially(f.run, SequentialSettings{}, f.hooks());
  EXPECT_EQ(o.ended, LooksEnded::kBudget);
  EXPECT_EQ(o.looks.size(), 1u);
  EXPECT_TRUE(f.runs_of.empty());
  EXPECT_EQ(verdict(o.claims[0].claim), Verdict::kUndecided);
}

TEST(SequentialClaims, StopsAfterTheLastLookAllowed) {
  Fixture f(kStraddling);
  for (int i = 0; i < 100000; ++i) f.next_tcsb_ms.push_back(i % 2 == 0 ? 0.8 : 1.2);
  SequentialSettings s;
  s.budget_s = 1e9;
  s.max_looks = 3;
  const SequentialOutcome o = judge_sequentially(f.run, s, f.hooks());
  EXPECT_EQ(o.ended, LooksEnded::kMaxLooks);
  EXPECT_EQ(o.looks.size(), 3u);
  EXPECT_EQ(o.claims[0].repetitions, 20);  // 5, doubled twice
}

TEST(SequentialClaims, AnUndecidedTargetAloneAddsNoRepetitionsAndIsNotJudgedOnCasesThatDidNotRun) {
  Fixture f({0.5, 0.6, 0.55, 0.5, 0.6});
  // TC-SB at 0.9 straddles its target, but targets do not gate: no extra repetitions for it.
  for (CaseResult& c : f.run.cases) c.repetitions.clear();
  for (double ms : kStraddling) {
    Fixture::add(f.run.cases[0], 1.0);
    Fixture::add(f.run.cases[1], 0.5);
    Fixture::add(f.run.cases[2], ms);
  }
  SequentialSettings s;
  s.budget_s = 100;
  const SequentialOutcome o = judge_sequentially(f.run, s, f.hooks(true));
  EXPECT_EQ(o.ended, LooksEnded::kDecided);
  EXPECT_TRUE(f.runs_of.empty());
  ASSERT_EQ(o.targets.size(), 1u);
  EXPECT_EQ(verdict(o.targets[0].claim), Verdict::kUndecided);
  EXPECT_EQ(o.targets[0].look, 1);
}

TEST(SequentialClaims, RepetitionCostIsBuildPlusStepsAtTheCasesMeanStepTime) {
  Fixture f({2.0, 2.0});
  f.run.cases[1].repetitions[0].build_ms = 100;  // mean build 50 ms
  EXPECT_DOUBLE_EQ(repetition_cost_s(f.run, {1}), 2.05);
  EXPECT_DOUBLE_EQ(repetition_cost_s(f.run, {0, 1}), 3.05);
}

}  // namespace
}  // namespace tcsb
