// The instruction-count gate: counts are the same in every run of a build, so identical counts pass, a total that
// grows beyond the threshold regresses and names the functions that grew, and a time result is never compared with a
// count result.
#include "gate/instruction_gate.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "gate/gate_outcome.h"
#include "gate/run_consistency.h"
#include "result_documents.h"

namespace tcsb {
namespace {

using testing::ojson;
using testing::result_doc;

InstructionsView counts(std::int64_t own, std::int64_t bullet, std::int64_t step_fn = 100) {
  return {own, bullet, own + bullet, {{"btSoftBody::PSolve_Links", bullet}, {"TcSoftBody::advance_blends", step_fn}}};
}

/// result_doc() measured in instructions: each case's counts, TC-SB's own work `own` (plain: none).
ojson counted_doc(std::int64_t own = 1000) {
  ojson doc = result_doc(1);
  doc["measure"] = "instructions";
  for (ojson& c : doc["cases"]) {
    const bool tcsb = c["method"] == "tcsb";
    const std::int64_t o = tcsb ? own : 0, bullet = 100000;
    c["instructions"] = {{"own", o},
                         {"bullet", bullet},
                         {"total", o + bullet},
                         {"functions", ojson::array({{{"name", "btSoftBody::PSolve_Links"}, {"instructions", bullet}},
                                                     {{"name", "TcSoftBody::advance_blends"}, {"instructions", o}}})}};
  }
  return doc;
}

GateOutcome instruction_gate(const ojson& base, const ojson& next, double threshold = 0.005) {
  GateSettings settings;
  settings.threshold = threshold;
  return decide_gate(compare_results(read_result(base, "base.json"), read_result(next, "new.json")), settings, false);
}

TEST(InstructionGate, IdenticalCountsPass) {
  const InstructionDecision d = decide_instructions("n9/tcsb", counts(10, 1000), counts(10, 1000), 0.005);
  EXPECT_FALSE(d.regressed);
  EXPECT_FALSE(d.improved);
  ASSERT_TRUE(d.change.has_value());
  EXPECT_EQ(*d.change, 0.0);
  EXPECT_TRUE(d.shifts.empty());
}

TEST(InstructionGate, OnePercentMoreRegressesAndNamesTheFunction) {
  // 1 % more instructions in TC-SB's own work: above a 0.5 % threshold, a decided regression.
  const InstructionDecision d = decide_instructions("n9/tcsb", counts(100, 9900), counts(200, 9900, 200), 0.005);
  EXPECT_TRUE(d.regressed);
  EXPECT_NEAR(*d.change, 0.01, 1e-12);
  ASSERT_EQ(d.shifts.size(), 1u);
  EXPECT_EQ(d.shifts[0].name, "TcSoftBody::advance_blends");
  EXPECT_EQ(d.shifts[0].base, 100);
  EXPECT_EQ(d.shifts[0].next, 200);
  EXPECT_FALSE(decide_instructions("n9/tcsb", counts(100, 9900), counts(200, 9900), 0.02).regressed)
      << "within a 2 % threshold";
}

TEST(InstructionGate, FewerInstructionsAreReportedNotFailed) {
  const InstructionDecision d = decide_instructions("n9/tcsb", counts(200, 9900), counts(100, 9900), 0.005);
  EXPECT_FALSE(d.regressed);
  EXPECT_TRUE(d.improved);
}

TEST(InstructionGate, WorkWhereTheBaseCountedNoneRegresses) {
  const InstructionDecision d = decide_instructions("n9/tcsb", counts(0, 0), counts(1, 0), 0.005);
  EXPECT_FALSE(d.change.has_value());
  EXPECT_TRUE(d.regressed);
  EXPECT_THROW(decide_instructions("x", counts(0, 1), counts(0, 1), -0.1), std::invalid_argument);
}

TEST(InstructionGate, CountResultsGateOnCountsAlone) {
  // One repetition: the timings could never be decided, the counts are.
  const GateOutcome same = instruction_gate(counted_doc(), counted_doc());
  EXPECT_TRUE(same.counts);
  EXPECT_TRUE(same.pass());
  EXPECT_EQ(same.gated_metrics, 4u);
  const GateOutcome more = instruction_gate(counted_doc(), counted_doc(2000));  // +1000 of 101000: +0.99 %
  EXPECT_FALSE(more.pass());
  EXPECT_EQ(more.regressions, 2u);
  EXPECT_EQ(more.verdict(), Verdict::kFail);
  EXPECT_TRUE(instruction_gate(counted_doc(), counted_doc(2000), 0.01).pass());
}

TEST(InstructionGate, ATimeResultIsNeverComparedWithACountResult) {
  EXPECT_THROW(compare_results(read_result(result_doc(1), "time.json"), read_result(counted_doc(), "counts.json")),
               SuiteMismatch);
}

TEST(InstructionGate, FailsClosedOnMissingOrImpossibleCounts) {
  // Issue 60: a case's counts removed, or set to zero, passed the gate: it compared only the cases both had counted.
  const auto refused = [](const ojson& next, const std::string& field) {
    try {
      compare_results(read_result(counted_doc(), "base.json"), read_result(next, "new.json"));
      ADD_FAILURE() << "accepted: " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("new.json: " + field), std::string::npos) << e.what();
    }
  };
  ojson doc = counted_doc();
  doc["cases"][1].erase("instructions");
  refused(doc, "cases[1].instructions");
  doc = counted_doc();
  doc["cases"][2]["instructions"] = {{"own", 0}, {"bullet", 0}, {"total", 0}, {"functions", ojson::array()}};
  refused(doc, "cases[2].instructions.total");
  doc = counted_doc();  // fewer than one instruction per node and step: 81 nodes x the suite's steps
  doc["cases"][0]["instructions"] = {{"own", 0}, {"bullet", 80}, {"total", 80}, {"functions", ojson::array()}};
  refused(doc, "cases[0].instructions.total");
  doc = counted_doc();  // counts for a case none of whose repetitions is ok
  doc["cases"][0]["repetitions"][0]["status"] = "diverged";
  doc["cases"][0]["repetitions"][0]["diverged_step"] = 3;
  doc["cases"][0]["repetitions"][0]["mean_step_ms"] = nullptr;
  refused(doc, "cases[0].instructions.total");
  // The base is checked as strictly as the new run.
  EXPECT_THROW(compare_results(read_result(doc, "base.json"), read_result(counted_doc(), "new.json")), InputError);
  EXPECT_NO_THROW(compare_results(read_result(counted_doc(), "base.json"), read_result(counted_doc(), "new.json")));
}

TEST(InstructionGate, TheCiBaselinesCountsAreOnesARunWrites) {
  // What the checks above refuse must never be what a real run writes: the CI instruction gate compares against this.
  std::ifstream in(std::filesystem::path(TCSB_SOURCE_DIR) / "results/baselines/ci-instructions.json");
  ASSERT_TRUE(in.good());
  const ojson baseline = ojson::parse(in);
  const ResultView view = read_result(baseline, "ci-instructions.json");
  ASSERT_EQ(view.measure, "instructions");
  EXPECT_NO_THROW(check_instruction_counts(view));
  EXPECT_NO_THROW(compare_results(view, view));
}

TEST(InstructionGate, TheReaderChecksTheCounts) {
  ojson doc = counted_doc();
  doc["cases"][1]["instructions"]["total"] = 5;
  EXPECT_THROW(read_result(doc, "bad.json"), InputError);
  doc = counted_doc();
  doc["measure"] = "cycles";
  EXPECT_THROW(read_result(doc, "bad.json"), InputError);
  EXPECT_EQ(read_result(result_doc(), "old.json").measure, "time") << "a file without `measure` measured time";
}

}  // namespace
}  // namespace tcsb
