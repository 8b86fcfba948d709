// Bootstrap resampling of a run's repetitions, and the claim intervals computed from it.
#include "paper/claim_intervals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "analysis/statistics.h"
#include "run/case_summary.h"

namespace tcsb {
namespace {

constexpr int kReps = 5;

/// The step time that names a repetition: 100 * net + 10 * case-within-net + repetition.
double code(std::size_t net, int c, int rep) { return 100.0 * static_cast<double>(net) + 10.0 * c + rep; }

/// Two nets x (plain, TC-SB at 0.5), five repetitions each. Every TC-SB repetition records rep + 1 operations whose
/// node_ns is the repetition's code, so the tests can see which samples travelled with which repetition.
RunResult two_nets() {
  RunResult r;
  r.suite.seed = 11;
  for (std::size_t net = 0; net < 2; ++net) {
    for (int c = 0; c < 2; ++c) {
      CaseResult& k = r.cases.emplace_back();
      k.key = CaseKey{net, c == 0 ? Method::kPlain : Method::kTcsb, c == 0 ? std::nullopt : std::optional(0.5)};
      k.label = k.net_name = std::string("n").append(std::to_string(net));  // not "n" + ...: GCC 12 -Wrestrict
      for (int rep = 0; rep < kReps; ++rep) {
        RepetitionResult& x = k.repetitions.emplace_back();
        x.repetition = rep;
        x.mean_step_ms = x.median_step_ms = code(net, c, rep);
        x.mean_nodes = 1000.0 * static_cast<double>(net + 1);
        x.series.step_ms.assign(3, x.mean_step_ms);
        if (c == 1) {
          x.operations = rep + 1;
          for (int i = 0; i <= rep; ++i)
            k.ops.samples.push_back({OpKind::kRefine, static_cast<std::int32_t>(code(net, c, rep)), 0, 10, 20});
        }
      }
      summarize_case(k);
    }
  }
  return r;
}

int rep_of(double step_ms) { return static_cast<int>(std::lround(step_ms)) % 10; }

TEST(ClaimIntervals, ResampleDrawsOneSetOfRepetitionsPerNetAndCarriesTheirOperations) {
  const RunResult run = two_nets();
  std::mt19937_64 rng(5);
  bool some_repeat = false;
  for (int trial = 0; trial < 20; ++trial) {
    const RunResult s = resample_repetitions(run, rng);
    ASSERT_EQ(s.cases.size(), run.cases.size());
    for (std::size_t net = 0; net < 2; ++net) {
      const CaseResult& plain = s.cases[2 * net];
      const CaseResult& tcsb = s.cases[2 * net + 1];
      ASSERT_EQ(plain.repetitions.size(), static_cast<std::size_t>(kReps));
      std::vector<double> means;
      std::vector<OpSample> expected_ops;
      std::set<int> drawn;
      for (int i = 0; i < kReps; ++i) {
        const RepetitionResult& p = plain.repetitions[static_cast<std::size_t>(i)];
        const RepetitionResult& t = tcsb.repetitions[static_cast<std::size_t>(i)];
        const int rep = rep_of(p.mean_step_ms);
        drawn.insert(rep);
        EXPECT_EQ(p.mean_step_ms, code(net, 0, rep));  // a plain repetition of this net ...
        EXPECT_EQ(t.mean_step_ms, code(net, 1, rep));  // ... paired with the TC-SB one measured beside it
        EXPECT_EQ(p.repetition, i);                    // renumbered, so pairing by index still works
        EXPECT_EQ(t.repetition, i);
        EXPECT_TRUE(p.series.step_ms.empty());  // series are not carried
        EXPECT_EQ(t.operations, rep + 1);
        means.push_back(t.mean_step_ms);
        for (int k = 0; k <= rep; ++k)
          expected_ops.push_back({OpKind::kRefine, static_cast<std::int32_t>(code(net, 1, rep)), 0, 10, 20});
      }
      some_repeat = some_repeat || drawn.size() < static_cast<std::size_t>(kReps);
      ASSERT_EQ(tcsb.ops.samples.size(), expected_ops.size());
      for (std::size_t k = 0; k < expected_ops.size(); ++k)
        EXPECT_EQ(tcsb.ops.samples[k].node_ns, expected_ops[k].node_ns) << "sample " << k;
      EXPECT_EQ(tcsb.step_ms.median, median(means));  // the summary is recomputed
      EXPECT_EQ(tcsb.mean_nodes, 1000.0 * static_cast<double>(net + 1));
    }
  }
  EXPECT_TRUE(some_repeat);  // drawn with replacement
}

/// Over 20 resamples: whether both nets drew the same repetitions every time.
bool nets_always_draw_alike(const RunResult& run) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const RunResult s = resample_repetitions(run, rng);
    for (std::size_t i = 0; i < static_cast<std::size_t>(kReps); ++i)
      if (rep_of(s.cases[0].repetitions[i].mean_step_ms) != rep_of(s.cases[2].repetitions[i].mean_step_ms))
        return false;
  }
  return true;
}

TEST(ClaimIntervals, NetsSideBySideAcrossNetsDrawTheirRepetitionsTogether) {
  RunResult run = two_nets();
  EXPECT_FALSE(nets_always_draw_alike(run));  // each net's own draw
  run.suite.interleave_steps = 8;
  run.suite.interleave_across_nets = true;  // repetition r of both nets ran together: one draw for both
  EXPECT_TRUE(nets_always_draw_alike(run));
  // Merged from shards that measured the nets' repetitions in different processes: each net draws its own again.
  for (RepetitionResult& r : run.cases[2].repetitions) r.process = 1;
  for (RepetitionResult& r : run.cases[3].repetitions) r.process = 1;
  EXPECT_FALSE(nets_always_draw_alike(run));
}

TEST(ClaimIntervals, ResampleRejectsOperationCountsThatDoNotAddUp) {
  RunResult run = two_nets();
  run.cases[1].ops.samples.pop_back();
  std::mt19937_64 rng(1);
  EXPECT_THROW(resample_repetitions(run, rng), std::logic_error);
  run = two_nets();
  run.cases[3].repetitions.pop_back();
  run.cases[3].ops.samples.resize(run.cases[3].ops.samples.size() - kReps);
  EXPECT_THROW(resample_repetitions(run, rng), std::logic_error);  // a net's cases differ in repetitions
}

/// Claims on the median step time of case `index`, and one never measured.
std::vector<Claim> claims_on(const RunResult& r, std::size_t index) {
  return {check_claim("median", "", Comparison::kAtMost, 3.0, 0.0, r.cases[index].step_ms.median, Evidence::kRepeated),
          check_claim("never", "", Comparison::kAtMost, 3.0, 0.0, std::nullopt, Evidence::kRepeated)};
}

TEST(ClaimIntervals, IntervalsSpanTheRepetitionsAndRepeatForASeed) {
  const RunResult run = two_nets();
  const auto of_case1 = [](const RunResult& r) { return claims_on(r, 1); };
  const ClaimReplicates replicates = bootstrap_claims(run, of_case1, 200, 9);
  ASSERT_EQ(replicates.at("median").size(), 200u);
  std::vector<Claim> claims = claims_on(run, 1);
  attach_intervals(claims, replicates, 0.95);
  ASSERT_TRUE(claims[0].interval.has_value());
  // Case 1's repetitions take 10..14 ms: the median of a resample lies among them, and varies.
  EXPECT_GE(claims[0].interval->low, 10.0);
  EXPECT_LE(claims[0].interval->high, 14.0);
  EXPECT_LT(claims[0].interval->low, claims[0].interval->high);
  EXPECT_TRUE(claims[0].interval->contains(*claims[0].measured));
  EXPECT_FALSE(claims[1].interval.has_value());   // undefined on every resample
  EXPECT_EQ(verdict(claims[0]), Verdict::kFail);  // 10..14 > 3: a decided FAIL
  EXPECT_EQ(verdict(claims[1]), Verdict::kFail);  // never measured

  const ClaimReplicates again = bootstrap_claims(run, of_case1, 200, 9);
  EXPECT_EQ(again.at("median"), replicates.at("median"));
}

TEST(ClaimIntervals, IdenticalRepetitionsGiveAPointInterval) {
  RunResult run = two_nets();
  for (RepetitionResult& x : run.cases[0].repetitions) x.mean_step_ms = 2.5;
  summarize_case(run.cases[0]);
  std::vector<Claim> claims = claims_on(run, 0);
  attach_intervals(claims,
                   bootstrap_claims(
                       run, [](const RunResult& r) { return claims_on(r, 0); }, 100, 3),
                   0.95);
  ASSERT_TRUE(claims[0].interval.has_value());
  EXPECT_EQ(claims[0].interval->low, 2.5);
  EXPECT_EQ(claims[0].interval->high, 2.5);
  EXPECT_EQ(verdict(claims[0]), Verdict::kPass);
}

TEST(ClaimIntervals, TooFewRepetitionsGiveNoIntervals) {
  // One repetition resampled is always itself: a point "interval" would claim a decided verdict. None instead.
  RunResult run = two_nets();
  for (CaseResult& c : run.cases) {
    c.repetitions.resize(kMinRepetitionsForIntervals - 1);
    std::size_t ops = 0;
    for (const RepetitionResult& r : c.repetitions) ops += static_cast<std::size_t>(r.operations);
    c.ops.samples.resize(ops);
  }
  const auto of_case1 = [](const RunResult& r) { return claims_on(r, 1); };
  EXPECT_TRUE(bootstrap_claims(run, of_case1, 100, 3).empty());
  std::vector<Claim> claims = claims_on(run, 1);
  attach_intervals(claims, bootstrap_claims(run, of_case1, 100, 3), 0.95);
  EXPECT_FALSE(claims[0].interval.has_value());
  EXPECT_EQ(verdict(claims[0]), Verdict::kUndecided);  // no interval: the run cannot know its noise
}

TEST(ClaimIntervals, ASubsetKeepsTheChosenCasesWithoutSeriesAndOperationsUnlessAsked) {
  const RunResult run = two_nets();
  const RunResult light = subset_for_bootstrap(run, {1, 3}, false);
  ASSERT_EQ(light.cases.size(), 2u);
  EXPECT_EQ(light.cases[0].label, run.cases[1].label);
  EXPECT_TRUE(light.cases[0].ops.samples.empty());
  for (const RepetitionResult& r : light.cases[1].repetitions) {
    EXPECT_EQ(r.operations, 0);
    EXPECT_TRUE(r.series.step_ms.empty());
  }
  const RunResult with_ops = subset_for_bootstrap(run, {1}, true);
  EXPECT_EQ(with_ops.cases[0].ops.samples.size(), run.cases[1].ops.samples.size());
  std::mt19937_64 rng(1);
  EXPECT_NO_THROW(resample_repetitions(light, rng));  // still consistent: counts add up
  EXPECT_NO_THROW(resample_repetitions(with_ops, rng));
}

/// One net, plain and TC-SB side by side, 12 repetitions measured by `processes` processes in turn (process p runs
/// repetitions p-1, p-1+processes, ...). TC-SB's ratio to plain is the same within a process and moves between them
/// (0.95, 1.05, 1.00, ...), as a net's ratio moves between processes on a shared machine; plain's step is 10 ms
/// everywhere, with a little spread within a process.
RunResult run_over_processes(int processes) {
  const std::vector<double> ratio_of_process{0.95, 1.05, 1.00, 0.98, 1.03, 0.97, 1.02};
  RunResult r;
  for (int c = 0; c < 2; ++c) {
    CaseResult& k = r.cases.emplace_back();
    k.key = CaseKey{0, c == 0 ? Method::kPlain : Method::kTcsb, c == 0 ? std::nullopt : std::optional(1.0)};
    k.label = k.net_name = "n0";
    for (int rep = 0; rep < 12; ++rep) {
      RepetitionResult& x = k.repetitions.emplace_back();
      x.repetition = rep;
      const int process = rep % processes;
      x.process = processes == 1 ? 0 : process + 1;
      const double plain = 10.0 + 0.01 * rep;
      x.mean_step_ms = x.median_step_ms = c == 0 ? plain : plain * ratio_of_process[static_cast<std::size_t>(process)];
    }
    summarize_case(k);
  }
  return r;
}

/// TC-SB's median step over plain's.
std::vector<Claim> ratio_claim(const RunResult& r) {
  return {check_claim("ratio", "", Comparison::kAtMost, 1.03, 0.0,
                      r.cases[1].step_ms.median / r.cases[0].step_ms.median, Evidence::kRepeated)};
}

Interval ratio_interval(const RunResult& run) {
  std::vector<Claim> claims = ratio_claim(run);
  attach_intervals(claims, bootstrap_claims(run, ratio_claim, 2000, 7), 0.95);
  return claims.front().interval.value();
}

TEST(ClaimIntervals, AMergedResultsIntervalIsAtLeastAsWideAsOneProcesssOnTheSameData) {
  // The same twelve repetitions, first as if one process had measured them all, then marked with the two (three)
  // processes that did: resampling the processes first carries their spread into the interval.
  for (const int processes : {2, 3}) {
    RunResult merged = run_over_processes(processes);
    RunResult one = merged;
    for (CaseResult& c : one.cases)
      for (RepetitionResult& x : c.repetitions) x.process = 0;
    const Interval pooled = ratio_interval(one), by_process = ratio_interval(merged);
    EXPECT_LE(by_process.low, pooled.low) << processes;
    EXPECT_GE(by_process.high, pooled.high) << processes;
    EXPECT_GT(by_process.high - by_process.low, pooled.high - pooled.low) << processes;
  }
}

TEST(ClaimIntervals, ProcessesAreDrawnWholeAndTheNetsCasesStayPaired) {
  const RunResult merged = run_over_processes(2);
  std::mt19937_64 rng(3);
  int one_process_only = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const RunResult s = resample_repetitions(merged, rng);
    ASSERT_EQ(s.cases[0].repetitions.size(), s.cases[1].repetitions.size());
    std::set<int> seen;
    for (std::size_t i = 0; i < s.cases[0].repetitions.size(); ++i) {
      EXPECT_EQ(s.cases[0].repetitions[i].process, s.cases[1].repetitions[i].process);  // paired
      seen.insert(s.cases[0].repetitions[i].process);
    }
    one_process_only += seen.size() == 1;
  }
  EXPECT_GT(one_process_only, 60);  // about half the resamples draw one process twice
  EXPECT_LT(one_process_only, 140);
}

TEST(ClaimIntervals, OneProcessResamplesAsBeforeWhateverItsLabel) {
  // A run's own process (0) and a merged net that one shard measured whole (k) give the very same draws.
  RunResult shard = two_nets();
  for (CaseResult& c : shard.cases)
    for (RepetitionResult& x : c.repetitions) x.process = 2;
  const auto of_case1 = [](const RunResult& r) { return claims_on(r, 1); };
  EXPECT_EQ(bootstrap_claims(two_nets(), of_case1, 100, 4).at("median"),
            bootstrap_claims(shard, of_case1, 100, 4).at("median"));
}

}  // namespace
}  // namespace tcsb
