// The gate's verdict from two documents: ratios gate by default, absolute times only with --absolute, and a
// deterministic difference fails whatever the timings say.
#include "gate/gate_outcome.h"

#include <gtest/gtest.h>

#include "result_documents.h"

namespace tcsb {
namespace {

using testing::ojson;
using testing::result_doc;
using testing::scale_case;

GateOutcome gate(const ojson& base, const ojson& next, bool absolute = false) {
  return decide_gate(compare_results(read_result(base, "base.json"), read_result(next, "new.json")), {}, absolute);
}

TEST(GateOutcome, UnchangedRunPasses) {
  const GateOutcome o = gate(result_doc(), result_doc());
  EXPECT_TRUE(o.pass());
  EXPECT_EQ(o.regressions, 0u);
  EXPECT_EQ(o.gated_metrics, 2u);
  ASSERT_EQ(o.ratio_decisions.size(), 2u);
  ASSERT_EQ(o.step_decisions.size(), 4u);
}

TEST(GateOutcome, SlowerTcsbFailsOnTheRatio) {
  ojson next = result_doc();
  scale_case(next, 3, 1.5);  // n17/tcsb@0.5 half again as slow, plain unchanged
  const GateOutcome o = gate(result_doc(), next);
  EXPECT_FALSE(o.pass());
  EXPECT_EQ(o.regressions, 1u);
  EXPECT_EQ(o.ratio_decisions[1].verdict, TimingVerdict::kRegressed);
  EXPECT_EQ(o.ratio_decisions[0].verdict, TimingVerdict::kUnchanged);
  EXPECT_EQ(o.warnings, 1u) << "its absolute time is slower too, reported only";
}

TEST(GateOutcome, ASlowerMachineOnlyWarnsUnlessAbsoluteIsAsked) {
  ojson next = result_doc();
  for (std::size_t i = 0; i < 4; ++i) scale_case(next, i, 1.5);
  const GateOutcome shared = gate(result_doc(), next);
  EXPECT_TRUE(shared.pass());
  EXPECT_EQ(shared.warnings, 4u);
  const GateOutcome dedicated = gate(result_doc(), next, true);
  EXPECT_FALSE(dedicated.pass());
  EXPECT_EQ(dedicated.regressions, 4u);
  EXPECT_EQ(dedicated.gated_metrics, 6u) << "one Holm family: 2 ratios + 4 step times";
}

TEST(GateOutcome, ChangedBehaviourFailsEvenWithIdenticalTimes) {
  ojson next = result_doc();
  next["cases"][1]["repetitions"][0]["final_state_hash"] = "different";
  const GateOutcome o = gate(result_doc(), next);
  EXPECT_EQ(o.regressions, 0u);
  EXPECT_TRUE(o.behaviour_changed());
  EXPECT_FALSE(o.pass());
}

TEST(GateOutcome, TooFewRepetitionsNeverRegressButCannotPass) {
  ojson base = result_doc(5), next = result_doc(5);
  scale_case(next, 1, 3.0);
  const GateOutcome o = gate(base, next);
  EXPECT_EQ(o.ratio_decisions[0].verdict, TimingVerdict::kUnreliable);
  EXPECT_EQ(o.regressions, 0u);
  EXPECT_EQ(o.gated_metrics, 0u);
  EXPECT_EQ(o.unreliable_metrics(), 2u);
  EXPECT_FALSE(o.timings_decided());
  EXPECT_FALSE(o.pass()) << "nothing was measured: a gate that fails closed does not pass";
  EXPECT_FALSE(gate(base, base).pass()) << "not even the same file";
}

TEST(GateOutcome, NoRatioMetricCannotPass) {
  // Plain cases only: nothing for the default family; --absolute gates the step times instead.
  ojson plain_only = result_doc();
  plain_only["cases"].erase(3);
  plain_only["cases"].erase(1);
  const GateOutcome o = gate(plain_only, plain_only);
  EXPECT_TRUE(o.ratio_decisions.empty());
  EXPECT_FALSE(o.timings_decided());
  EXPECT_FALSE(o.pass());
  const GateOutcome absolute = gate(plain_only, plain_only, true);
  EXPECT_EQ(absolute.gated_metrics, 2u);
  EXPECT_TRUE(absolute.pass());
}

TEST(GateOutcome, SomeUnreliableMetricsAreCountedNotHidden) {
  ojson base = result_doc(), next = result_doc();
  for (ojson* doc : {&base, &next}) {
    auto& reps = (*doc)["cases"][3]["repetitions"];  // n17/tcsb@0.5: only five repetitions ok
    for (int r = 0; r < 4; ++r) {
      reps[r]["status"] = "diverged";
      reps[r]["diverged_step"] = 3;
      reps[r]["mean_step_ms"] = nullptr;
    }
  }
  const GateOutcome o = gate(base, next);
  EXPECT_EQ(o.gated_metrics, 1u);
  EXPECT_EQ(o.unreliable_metrics(), 1u);
  EXPECT_TRUE(o.pass()) << "the other ratio decides";
}

}  // namespace
}  // namespace tcsb
