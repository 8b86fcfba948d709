// Extra repetitions of chosen cases (run_more_repetitions): numbered after the existing ones, only the chosen
// cases, each with the case's own seed — so an added repetition does exactly the work of the first ones.
#include "run/runner.h"

#include <gtest/gtest.h>

#include <climits>

namespace tcsb {
namespace {

Suite two_nets() {
  Suite s;
  s.name = std::string("two");  // moved in: GCC 12 -Wrestrict false positive on literal assignment
  NetSpec a, b;
  a.width = a.height = 9;
  a.name = std::string("a");
  b.width = b.height = 11;
  b.name = std::string("b");
  s.nets = {a, b};
  s.methods = {Method::kPlain, Method::kTcsb};
  s.compression = {1.0, 0.5};
  s.steps = 10;
  s.warmup_steps = 5;
  s.repetitions = 2;
  s.feedback.max_ops_per_step = 16;
  s.fidelity.enabled = false;
  return s;
}

TEST(Runner, MoreRepetitionsOfChosenCasesContinueTheirNumberingAndRepeatTheirWork) {
  RunResult run = run_suite(two_nets(), Context{});
  ASSERT_EQ(run.cases.size(), 6u);  // per net: plain, tcsb@1.0, tcsb@0.5
  const double wall_before = run.wall_s;
  const std::vector<std::size_t> chosen{0, 2, 3, 5};  // plain and TC-SB at 0.5 on both nets
  run_more_repetitions(run, chosen, 3);
  for (std::size_t i = 0; i < run.cases.size(); ++i) {
    const CaseResult& c = run.cases[i];
    const bool more = i == 0 || i == 2 || i == 3 || i == 5;
    ASSERT_EQ(c.repetitions.size(), more ? 5u : 2u) << c.label;
    for (std::size_t r = 0; r < c.repetitions.size(); ++r) {
      EXPECT_EQ(c.repetitions[r].repetition, static_cast<int>(r)) << c.label;
      // Same seed, same work: the final state and the node counts are those of the first repetition.
      EXPECT_EQ(c.repetitions[r].final_state_hash, c.repetitions[0].final_state_hash) << c.label << " " << r;
      EXPECT_EQ(c.repetitions[r].mean_nodes, c.repetitions[0].mean_nodes) << c.label << " " << r;
      EXPECT_EQ(c.repetitions[r].operations, c.repetitions[0].operations) << c.label << " " << r;
    }
    std::size_t ops = 0;
    for (const RepetitionResult& r : c.repetitions) ops += static_cast<std::size_t>(r.operations);
    EXPECT_EQ(c.ops.samples.size(), ops) << c.label;              // samples still add up per repetition
    EXPECT_EQ(c.step_ms.count, c.repetitions.size()) << c.label;  // the summary covers the new repetitions
  }
  EXPECT_GE(run.wall_s, wall_before);
  run_more_repetitions(run, {0}, 0);  // nothing asked: nothing runs
  EXPECT_EQ(run.cases[0].repetitions.size(), 5u);
}

TEST(Runner, StepsPerRepetitionCountTheUntimedStepOpeningEachBlock) {
  Suite s = two_nets();
  EXPECT_EQ(steps_per_repetition(s), 15);
  s.interleave_steps = 4;  // 10 timed steps: blocks of 4, 4 and 2
  EXPECT_EQ(steps_per_repetition(s), 18);
  s.interleave_steps = 10;
  EXPECT_EQ(steps_per_repetition(s), 16);
  s.interleave_steps = INT_MAX;  // one block, and no overflow on the way (the sanitizer build would report it)
  EXPECT_EQ(steps_per_repetition(s), 16);
  s.steps = s.warmup_steps = INT_MAX;
  EXPECT_EQ(steps_per_repetition(s), 2LL * INT_MAX + 1);
}

/// Runs `side` (interleave_steps set) and checks every case steps as it would alone, extra repetitions included.
void expect_steps_as_alone(const Suite& side) {
  RunResult run = run_suite(side, Context{});
  run_more_repetitions(run, {0, 2}, 1);  // side by side too: plain and TC-SB at 0.5 of net a
  // Alone, with as many steps in all: the same final states, so stepping beside other bodies changes nothing.
  Suite alone = two_nets();
  alone.steps = static_cast<int>(steps_per_repetition(side)) - alone.warmup_steps;
  const RunResult reference = run_suite(alone, Context{});
  ASSERT_EQ(run.cases.size(), reference.cases.size());
  for (std::size_t i = 0; i < run.cases.size(); ++i) {
    const CaseResult& c = run.cases[i];
    ASSERT_EQ(c.repetitions.size(), i == 0 || i == 2 ? 3u : 2u) << c.label;
    std::size_t ops = 0;
    for (const RepetitionResult& r : c.repetitions) {
      EXPECT_EQ(r.status, "ok") << c.label;
      EXPECT_EQ(r.final_state_hash, reference.cases[i].repetitions[0].final_state_hash) << c.label;
      EXPECT_EQ(r.series.step_ms.size(), 10u) << c.label;  // every timed step once, the blocks' openers not
      ops += static_cast<std::size_t>(r.operations);
    }
    EXPECT_EQ(c.ops.samples.size(), ops) << c.label;
  }
}

TEST(Runner, SideBySideStepsEachCaseAsItWouldStepAlone) {
  Suite side = two_nets();
  side.interleave_steps = 4;
  expect_steps_as_alone(side);
}

TEST(Runner, SideBySideAcrossNetsStepsEachCaseAsItWouldStepAlone) {
  Suite side = two_nets();
  side.interleave_steps = 4;
  side.interleave_across_nets = true;  // both nets' cases of a repetition take turns together
  expect_steps_as_alone(side);
}

TEST(Runner, PlainEqualIsAStaticGridOfTheBudgetsNodeCount) {
  Suite s = two_nets();
  s.methods.push_back(Method::kPlainEqual);
  const RunResult run = run_suite(s, Context{});
  ASSERT_EQ(run.cases.size(), 8u);  // per net: plain, tcsb@1.0, tcsb@0.5, plain_equal@0.5
  const CaseResult& equal = run.cases[3];
  EXPECT_EQ(equal.label, "a/plain_equal@0.5");
  EXPECT_EQ(equal.target_nodes, 41);  // round(0.5 x 81)
  // The fidelity pass's uniform grid for 41 nodes of a 9 x 9 net: 6 x 7 (coarse_grid_for), no operations.
  EXPECT_EQ(equal.mean_nodes, 42.0);
  EXPECT_EQ(equal.mean_interpolations, 0.0);
  EXPECT_EQ(equal.repetitions[0].operations, 0);
  EXPECT_EQ(equal.repetitions[0].final_state_hash, equal.repetitions[1].final_state_hash);
  // Bit-identical: adding plain_equal leaves every other case's state as it was.
  const RunResult before = run_suite(two_nets(), Context{});
  for (const std::size_t i : {0u, 1u, 2u}) {
    EXPECT_EQ(run.cases[i].repetitions[0].final_state_hash, before.cases[i].repetitions[0].final_state_hash) << i;
    EXPECT_EQ(run.cases[i + 4].repetitions[0].final_state_hash, before.cases[i + 3].repetitions[0].final_state_hash)
        << i;
  }
}

TEST(Runner, StepBreakdownAccountsForTheOperationsAndForStockSteps) {
  const RunResult run = run_suite(two_nets(), Context{});
  for (const CaseResult& c : run.cases) {
    for (const RepetitionResult& r : c.repetitions) {
      const StepBreakdown& b = r.breakdown;
      if (c.key.method == Method::kPlain) {
        // A stock body's step is all Bullet's: the runner's own step times, nothing else.
        EXPECT_DOUBLE_EQ(b.bullet_ms, r.mean_step_ms) << c.label;
        EXPECT_EQ(b.feedback_ms + b.operations_ms + b.blending_ms, 0.0) << c.label;
        continue;
      }
      EXPECT_GT(b.bullet_ms, 0.0) << c.label;
      // The parts lie within the step (the rest is the clock reads between them).
      EXPECT_LE(b.bullet_ms + b.feedback_ms + b.operations_ms + b.blending_ms, r.mean_step_ms * (1 + 1e-9)) << c.label;
    }
    // The case's breakdown: each part's median over the repetitions (a stock case's Bullet part is its step).
    if (c.key.method == Method::kPlain) {
      EXPECT_DOUBLE_EQ(c.breakdown.bullet_ms, c.step_ms.median) << c.label;
    }
    // Operations: exactly their own samples' time, per timed step (the samples are the timed steps' only).
    double ops_ms = 0;
    for (const OpSample& s : c.ops.samples) ops_ms += (static_cast<double>(s.node_ns) + s.link_ns) / 1e6;
    double breakdown_ops_ms = 0;
    for (const RepetitionResult& r : c.repetitions) breakdown_ops_ms += r.breakdown.operations_ms * run.suite.steps;
    EXPECT_NEAR(breakdown_ops_ms, ops_ms, 1e-9 * (1 + ops_ms)) << c.label;
    if (c.key.compression == 0.5) {
      EXPECT_GT(ops_ms, 0.0) << c.label << ": the test must see operations";
    }
  }
}

TEST(Runner, ASelectionOfNetsRunsOnlyTheirCasesAndEachAsInTheWholeRun) {
  const Suite suite = two_nets();
  const RunResult whole = run_suite(suite, Context{});
  Suite second_net_only = suite;
  second_net_only.run_units = {false, true};
  const RunResult part = run_suite(second_net_only, Context{});
  ASSERT_EQ(part.cases.size(), 3u);  // net b: plain, tcsb@1.0, tcsb@0.5
  for (std::size_t i = 0; i < part.cases.size(); ++i) {
    const CaseResult& c = part.cases[i];
    const CaseResult& w = whole.cases[3 + i];
    EXPECT_EQ(c.label, w.label);
    EXPECT_EQ(c.key.net, 1u);  // the suite-wide net index, so seeds and labels are the whole suite's
    ASSERT_EQ(c.repetitions.size(), w.repetitions.size());
    for (std::size_t r = 0; r < c.repetitions.size(); ++r) {
      EXPECT_EQ(c.repetitions[r].final_state_hash, w.repetitions[r].final_state_hash) << c.label;
      EXPECT_EQ(c.repetitions[r].mean_nodes, w.repetitions[r].mean_nodes) << c.label;
      EXPECT_EQ(c.repetitions[r].operations, w.repetitions[r].operations) << c.label;
    }
    EXPECT_EQ(c.ops.samples.size(), w.ops.samples.size()) << c.label;
  }
  Suite none = suite;
  none.run_units = {false, false};
  EXPECT_TRUE(run_suite(none, Context{}).cases.empty());  // an empty shard: nothing runs, nothing fails
}

}  // namespace
}  // namespace tcsb
