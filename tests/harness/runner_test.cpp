// Extra repetitions of chosen cases (run_more_repetitions): numbered after the existing ones, only the chosen
// cases, each with the case's own seed — so an added repetition does exactly the work of the first ones.
#include "harness/runner.h"

#include <gtest/gtest.h>

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

TEST(Runner, ASelectionOfNetsRunsOnlyTheirCasesAndEachAsInTheWholeRun) {
  const Suite suite = two_nets();
  const RunResult whole = run_suite(suite, Context{});
  Suite second_net_only = suite;
  second_net_only.run_nets = {false, true};
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
  none.run_nets = {false, false};
  EXPECT_TRUE(run_suite(none, Context{}).cases.empty());  // an empty shard: nothing runs, nothing fails
}

}  // namespace
}  // namespace tcsb
