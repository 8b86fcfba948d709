#include "paper/op_work_claims.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "softbody/op_work_bounds.h"

namespace tcsb {
namespace {

OpSample sample(OpKind kind, OpWork work) {
  OpSample s;
  s.kind = kind;
  s.work = work;
  return s;
}

/// Work well inside every bound, scaled by `f` (1 keeps it unchanged), of an interior call. No relocation: refine and
/// coarse remove nothing, so their bound on it is 0.
OpWork typical(int f = 1) {
  return {
      .nodes = 5 * f, .links = 10 * f, .tree_records = 30 * f, .dbvt_leaves = 1, .dbvt_ancestors = 2, .interior = true};
}

/// A TC-SB case on `net` whose every operation did `work` and `other` (so maxima and means are both exercised).
CaseResult tcsb_case(const std::string& net, OpWork work, OpWork other) {
  CaseResult c;
  c.key.method = Method::kTcsb;
  c.net_name = net;
  for (int k = 0; k < kOpKindCount; ++k) {
    c.ops.samples.push_back(sample(static_cast<OpKind>(k), work));
    c.ops.samples.push_back(sample(static_cast<OpKind>(k), other));
  }
  return c;
}

RunResult flat_run() {
  RunResult r;
  for (const char* net : {"n45", "n55", "n81"}) {
    CaseResult plain;
    plain.net_name = net;
    plain.ops.samples.push_back(sample(OpKind::kRefine, typical(100)));  // plain never counts: ignored
    r.cases.push_back(plain);
    r.cases.push_back(tcsb_case(net, typical(), typical(2)));
    r.cases.push_back(tcsb_case(net, typical(2), typical()));  // a second budget, pooled with the first
  }
  return r;
}

const Claim& op_claim(const std::vector<Claim>& claims, const std::string& id) {
  for (const Claim& c : claims)
    if (c.id == id) return c;
  throw std::runtime_error("no claim " + id);
}

TEST(OpWorkClaims, OneClaimPerOperationNamedAfterIt) {
  const std::vector<Claim> claims = op_work_claims(flat_run());
  ASSERT_EQ(claims.size(), 4u);
  EXPECT_EQ(claims[0].id, "op_work_refine");
  EXPECT_EQ(claims[1].id, "op_work_end-refine");
  EXPECT_EQ(claims[2].id, "op_work_coarse");
  EXPECT_EQ(claims[3].id, "op_work_end-coarse");
}

TEST(OpWorkClaims, TheSameWorkOnEveryNetPasses) {
  for (const Claim& c : op_work_claims(flat_run())) {
    EXPECT_TRUE(passed(c)) << c.id;
    ASSERT_TRUE(c.measured) << c.id;
    // Nothing spreads, so measured is the largest max / bound: 2 * 30 tree records against refine's bound, etc.
    EXPECT_GT(*c.measured, 0) << c.id;
    EXPECT_LE(*c.measured, 1) << c.id;
  }
}

TEST(OpWorkClaims, AnInteriorMeanGrowingWithTheNetFailsThoughTheMaximumIsFlat) {
  RunResult r = flat_run();
  // On the largest net the smaller of each case's two end-coarse calls touches two links more: per-net interior
  // mean 16 against 15, the maximum 20 everywhere.
  for (std::size_t i : {7u, 8u})
    for (OpSample& s : r.cases[i].ops.samples)
      if (s.kind == OpKind::kEndCoarse && s.work.links == 10) s.work.links += 2;
  const std::vector<Claim> claims = op_work_claims(r);
  EXPECT_FALSE(passed(op_claim(claims, "op_work_end-coarse")));
  EXPECT_TRUE(passed(op_claim(claims, "op_work_coarse")));
  EXPECT_NEAR(*op_claim(claims, "op_work_end-coarse").measured, (1.0 / 16) / 0.05, 1e-12);
}

TEST(OpWorkClaims, BorderCallsThatDifferWhileInteriorCallsAgreePass) {
  RunResult r = flat_run();
  // Only n45 has border calls, and they do less (fewer neighbours): its mean over all calls drops well beyond 5 %,
  // its maximum and interior mean are those of every other net.
  OpWork border = typical();
  border.interior = false;
  border.links = 4;
  border.tree_records = 12;
  for (int k = 0; k < kOpKindCount; ++k)
    for (int i = 0; i < 4; ++i) r.cases[1].ops.samples.push_back(sample(static_cast<OpKind>(k), border));
  const std::vector<NetOpWork> nets = op_work_by_net(r);
  const OpWorkSummary n45 = nets[0].tally.summary(OpKind::kCoarse), n55 = nets[1].tally.summary(OpKind::kCoarse);
  EXPECT_EQ(n45.interior_calls, 4);
  EXPECT_DOUBLE_EQ(n45[OpWorkCount::kLinks].mean, 9.5);  // (10 + 20 + 20 + 10 + 4 * 4) / 8, against 15
  EXPECT_DOUBLE_EQ(n45[OpWorkCount::kLinks].interior_mean, n55[OpWorkCount::kLinks].interior_mean);
  for (const Claim& c : op_work_claims(r)) EXPECT_TRUE(passed(c)) << c.id;
  // The same border calls on an interior block would be judged: the interior mean then drops as well.
  for (OpSample& s : r.cases[1].ops.samples) s.work.interior = s.work.interior || s.work.links == 4;
  for (const Claim& c : op_work_claims(r)) EXPECT_FALSE(passed(c)) << c.id;
}

TEST(OpWorkClaims, RelocationWorkIsBoundedButNotCompared) {
  RunResult r = flat_run();
  // Whatever is last in Bullet's arrays: end-coarse relocates 0 links on n45, 60 on n81 (bound 68). Passes.
  for (std::size_t i : {7u, 8u})
    for (OpSample& s : r.cases[i].ops.samples)
      if (s.kind == OpKind::kEndCoarse) {
        s.work.relocation_nodes = op_work_bounds::kEndCoarse.relocation_nodes;
        s.work.relocation_links = 60;
      }
  EXPECT_TRUE(passed(op_claim(op_work_claims(r), "op_work_end-coarse")));
  // One call more than the bound fails, on any net.
  r.cases[4].ops.samples[6].work.relocation_links = op_work_bounds::kEndCoarse.relocation_links + 1;
  EXPECT_FALSE(passed(op_claim(op_work_claims(r), "op_work_end-coarse")));
  // Refine removes nothing: its relocation bound is 0, so any relocation fails.
  r.cases[4].ops.samples[0].work.relocation_nodes = 1;
  EXPECT_FALSE(passed(op_claim(op_work_claims(r), "op_work_refine")));
}

TEST(OpWorkClaims, WithoutInteriorCallsOnSomeNetTheClaimIsUnmeasured) {
  RunResult r = flat_run();
  for (CaseResult& c : r.cases)
    if (c.net_name == "n55")
      for (OpSample& s : c.ops.samples) s.work.interior = false;
  for (const Claim& c : op_work_claims(r)) {
    EXPECT_FALSE(passed(c)) << c.id;
    EXPECT_FALSE(c.measured.has_value()) << c.id;
  }
}

TEST(OpWorkClaims, ACountGrowingWithTheNetFails) {
  RunResult r = flat_run();
  // On the largest net every end-coarse call touches two links more: per-net mean 17 against 15, max 22 against 20.
  for (std::size_t i : {7u, 8u})
    for (OpSample& s : r.cases[i].ops.samples)
      if (s.kind == OpKind::kEndCoarse) s.work.links += 2;
  const std::vector<Claim> claims = op_work_claims(r);
  EXPECT_FALSE(passed(op_claim(claims, "op_work_end-coarse")));
  EXPECT_TRUE(passed(op_claim(claims, "op_work_refine")));
  EXPECT_TRUE(passed(op_claim(claims, "op_work_end-refine")));
  EXPECT_TRUE(passed(op_claim(claims, "op_work_coarse")));
  // The worst spread is the mean's: (17 - 15) / 17 = 11.8 %, 2.35 x the 5 % allowed (the max's is 9.1 %).
  EXPECT_NEAR(*op_claim(claims, "op_work_end-coarse").measured, (2.0 / 17) / 0.05, 1e-12);
}

TEST(OpWorkClaims, AMeanWithinFivePercentStillPasses) {
  RunResult r = flat_run();
  // One of the four refines on n45 touches 29 tree records instead of 30: mean 45 -> 44.75 (0.56 %), max unchanged.
  OpWork less = typical();
  less.tree_records -= 1;
  r.cases[1].ops.samples[0] = sample(OpKind::kRefine, less);
  EXPECT_TRUE(passed(op_claim(op_work_claims(r), "op_work_refine")));
}

TEST(OpWorkClaims, AMaximumOverItsBoundFailsEvenWhenEveryNetAgrees) {
  RunResult r = flat_run();
  OpWork over = typical(2);
  over.dbvt_leaves = op_work_bounds::kCoarse.dbvt_leaves + 1;  // a coarse adds one node, so one leaf
  for (CaseResult& c : r.cases)
    if (c.key.method == Method::kTcsb) c.ops.samples[4] = sample(OpKind::kCoarse, over);
  const std::vector<Claim> claims = op_work_claims(r);
  const Claim& coarse = op_claim(claims, "op_work_coarse");
  EXPECT_FALSE(passed(coarse));
  EXPECT_DOUBLE_EQ(*coarse.measured, 2.0);  // 2 leaves against a bound of 1
}

TEST(OpWorkClaims, TheDbvtAncestorWalkIsReportedButNotJudged) {
  RunResult r = flat_run();
  OpWork deep = typical();  // replaces a typical() call: only the ancestor walk differs
  deep.dbvt_ancestors = 40;
  r.cases[7].ops.samples[0] = sample(OpKind::kRefine, deep);
  EXPECT_TRUE(passed(op_claim(op_work_claims(r), "op_work_refine")));
}

TEST(OpWorkClaims, WithoutCallsOnSomeNetTheClaimIsUnmeasuredAndFails) {
  RunResult r = flat_run();
  for (CaseResult& c : r.cases)
    if (c.net_name == "n55")
      std::erase_if(c.ops.samples, [](const OpSample& s) { return s.kind == OpKind::kEndRefine; });
  const std::vector<Claim> claims = op_work_claims(r);
  EXPECT_FALSE(passed(op_claim(claims, "op_work_end-refine")));
  EXPECT_FALSE(op_claim(claims, "op_work_end-refine").measured.has_value());
  EXPECT_TRUE(passed(op_claim(claims, "op_work_refine")));
}

TEST(OpWorkClaims, OneNetCannotShowFlatnessSoItIsUnmeasured) {
  RunResult r = flat_run();
  r.cases.resize(3);
  for (const Claim& c : op_work_claims(r)) {
    EXPECT_FALSE(passed(c)) << c.id;
    EXPECT_FALSE(c.measured.has_value()) << c.id;
  }
  EXPECT_FALSE(passed(op_work_claims(RunResult{})[0]));
}

TEST(OpWorkByNet, PoolsTheTcsbCasesOfEachNetInOrder) {
  const std::vector<NetOpWork> nets = op_work_by_net(flat_run());
  ASSERT_EQ(nets.size(), 3u);
  EXPECT_EQ(nets[0].net, "n45");
  EXPECT_EQ(nets[2].net, "n81");
  const OpWorkSummary s = nets[1].tally.summary(OpKind::kCoarse);
  EXPECT_EQ(s.calls, 4);  // two budgets x two calls; the plain case's sample is not among them
  EXPECT_EQ(s[OpWorkCount::kLinks].max, 20);
  EXPECT_DOUBLE_EQ(s[OpWorkCount::kLinks].mean, 15.0);
  EXPECT_EQ(s.interior_calls, 4);
  EXPECT_DOUBLE_EQ(s[OpWorkCount::kLinks].interior_mean, 15.0);
}

TEST(RelativeSpread, IsTheRangeOverTheLargest) {
  EXPECT_DOUBLE_EQ(relative_spread({}), 0);
  EXPECT_DOUBLE_EQ(relative_spread({0, 0}), 0);
  EXPECT_DOUBLE_EQ(relative_spread({10, 9.5, 10}), 0.05);
}

}  // namespace
}  // namespace tcsb
