// Case expansion order and the interleaved run plan.
#include "suite/case_plan.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace tcsb {
namespace {

Suite make_suite(std::vector<Method> methods, std::vector<double> compression, int nets, int repetitions) {
  Suite s;
  for (int i = 0; i < nets; ++i) {
    NetSpec n;
    n.name = "n";  // (built with += : GCC 12 warns falsely on "literal" + std::string&&)
    n.name += std::to_string(17 + 8 * i);
    n.width = n.height = 17 + 8 * i;
    s.nets.push_back(n);
  }
  s.methods = std::move(methods);
  s.compression = std::move(compression);
  s.repetitions = repetitions;
  return s;
}

TEST(CasePlan, ExpandsNetsThenMethodsThenTargetsInSuiteOrder) {
  const Suite s = make_suite({Method::kPlain, Method::kBulletPatch, Method::kTcsb}, {1.0, 0.75, 0.3}, 4, 9);
  const std::vector<CaseKey> cases = expand_cases(s);
  ASSERT_EQ(cases.size(), 4u * 5u);
  for (std::size_t net = 0; net < 4; ++net) {
    const CaseKey* c = &cases[net * 5];
    for (int k = 0; k < 5; ++k) EXPECT_EQ(c[k].net, net);
    EXPECT_EQ(c[0].method, Method::kPlain);
    EXPECT_FALSE(c[0].compression.has_value());
    EXPECT_EQ(c[1].method, Method::kBulletPatch);
    EXPECT_FALSE(c[1].compression.has_value());
    EXPECT_EQ(c[2].method, Method::kTcsb);
    EXPECT_EQ(c[2].compression, 1.0);
    EXPECT_EQ(c[3].compression, 0.75);
    EXPECT_EQ(c[4].compression, 0.3);
  }
}

TEST(CasePlan, MethodOrderFollowsTheSuite) {
  const Suite s = make_suite({Method::kTcsb, Method::kPlain}, {0.3, 1.0}, 1, 1);
  const std::vector<CaseKey> cases = expand_cases(s);
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_EQ(cases[0].compression, 0.3);
  EXPECT_EQ(cases[1].compression, 1.0);
  EXPECT_EQ(cases[2].method, Method::kPlain);
}

TEST(CasePlan, Labels) {
  const Suite s = make_suite({Method::kPlain, Method::kBulletPatch, Method::kTcsb}, {1.0, 0.75, 0.3}, 2, 1);
  const std::vector<CaseKey> cases = expand_cases(s);
  EXPECT_EQ(case_label(s, cases[0]), "n17/plain");
  EXPECT_EQ(case_label(s, cases[1]), "n17/bullet_patch");
  EXPECT_EQ(case_label(s, cases[2]), "n17/tcsb@1.0");
  EXPECT_EQ(case_label(s, cases[3]), "n17/tcsb@0.75");
  EXPECT_EQ(case_label(s, cases[4]), "n17/tcsb@0.3");
  EXPECT_EQ(case_label(s, cases[5]), "n25/plain");
}

TEST(CasePlan, PlainEqualRunsOneCasePerTargetBelowOne) {
  // At 1.0 a plain grid of the budget's nodes is the plain body itself: no case for it.
  const Suite s = make_suite({Method::kPlain, Method::kTcsb, Method::kPlainEqual}, {1.0, 0.75, 0.3}, 2, 1);
  const std::vector<CaseKey> cases = expand_cases(s);
  ASSERT_EQ(cases.size(), 2u * 6u);
  EXPECT_EQ(cases[4].method, Method::kPlainEqual);
  EXPECT_EQ(cases[4].compression, 0.75);
  EXPECT_EQ(cases[5].method, Method::kPlainEqual);
  EXPECT_EQ(cases[5].compression, 0.3);
  EXPECT_EQ(cases[6].method, Method::kPlain);
  EXPECT_EQ(cases[6].net, 1u);
  EXPECT_EQ(case_label(s, cases[4]), "n17/plain_equal@0.75");
  EXPECT_EQ(case_label(s, cases[5]), "n17/plain_equal@0.3");
}

void expect_valid_plan(const Suite& s) {
  const std::vector<CaseKey> cases = expand_cases(s);
  const std::vector<PlannedRun> plan = interleaved_plan(s, cases);
  ASSERT_EQ(plan.size(), cases.size() * static_cast<std::size_t>(s.repetitions));
  std::set<std::pair<std::size_t, int>> seen;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const PlannedRun& run = plan[i];
    ASSERT_LT(run.case_index, cases.size());
    // Repetition-major: every case once in repetition 0, then every case once in repetition 1, ...
    EXPECT_EQ(run.repetition, static_cast<int>(i / cases.size())) << "at run " << i;
    EXPECT_TRUE(seen.insert({run.case_index, run.repetition}).second) << "run planned twice";
    // A net's cases stay together within a repetition, in suite order, so its ratios pair runs close in time.
    if (i % cases.size() != 0 && cases[plan[i - 1].case_index].net == cases[run.case_index].net) {
      EXPECT_EQ(run.case_index, plan[i - 1].case_index + 1) << "at run " << i;
    }
    // Never the same case twice in a row, when the suite has more than one case.
    if (i > 0 && cases.size() >= 2) {
      EXPECT_NE(run.case_index, plan[i - 1].case_index) << "at run " << i;
    }
  }
  EXPECT_EQ(seen.size(), plan.size());
}

std::size_t first_net_of_repetition(const Suite& s, int rep) {
  const std::vector<CaseKey> cases = expand_cases(s);
  return cases[interleaved_plan(s, cases)[static_cast<std::size_t>(rep) * cases.size()].case_index].net;
}

TEST(CasePlan, EveryNetInEveryRepetitionWithTheFirstNetRotating) {
  const Suite s = make_suite({Method::kPlain, Method::kBulletPatch, Method::kTcsb}, {1.0, 0.75, 0.3}, 4, 9);
  expect_valid_plan(s);
  const std::vector<CaseKey> cases = expand_cases(s);
  const std::vector<PlannedRun> plan = interleaved_plan(s, cases);
  // Repetition 1 starts with the second net: its five cases A..E in order, then the third net's, and so on.
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const PlannedRun& run = plan[cases.size() + k];
    EXPECT_EQ(run.repetition, 1);
    EXPECT_EQ(run.case_index, (5 + k) % cases.size());
  }
  // Over 8 repetitions each of the 4 nets starts twice.
  std::vector<int> starts(4, 0);
  for (int rep = 0; rep < 8; ++rep) ++starts[first_net_of_repetition(s, rep)];
  EXPECT_EQ(starts, std::vector<int>(4, 2));
}

TEST(CasePlan, TwoMethodsAlternate) {
  const Suite s = make_suite({Method::kPlain, Method::kTcsb}, {0.5}, 3, 5);
  expect_valid_plan(s);
  const std::vector<CaseKey> cases = expand_cases(s);
  const std::vector<PlannedRun> plan = interleaved_plan(s, cases);
  for (std::size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ(cases[plan[i].case_index].method, i % 2 == 0 ? Method::kPlain : Method::kTcsb);
  }
}

TEST(CasePlan, SingleCasePerNetIsStillComplete) {
  expect_valid_plan(make_suite({Method::kPlain}, {}, 3, 4));
  expect_valid_plan(make_suite({Method::kPlain}, {}, 1, 3));
}

TEST(CasePlan, TwoNetsOfOneCaseKeepAlternating) {
  // Rotating would run the second net twice in a row at each repetition's start, so the order stays n17, n25.
  const Suite s = make_suite({Method::kPlain}, {}, 2, 4);
  expect_valid_plan(s);
  for (int rep = 0; rep < 4; ++rep) EXPECT_EQ(first_net_of_repetition(s, rep), 0u);
}

}  // namespace
}  // namespace tcsb
