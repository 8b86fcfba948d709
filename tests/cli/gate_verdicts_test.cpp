// `tcsb compare`'s verdicts as scripts see them: an undecided timing exits 4 and says how many repetitions would
// decide, --summary-json carries the verdict and its counts, and results of `tcsb run --measure instructions` gate
// on their counts (a time result against a count result is refused). The counts are set in the JSON here; the one
// test that counts for real runs only where valgrind is installed, on a net small enough for callgrind.
#include <nlohmann/json.hpp>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace tcsb::cli_test;
using ojson = nlohmann::ordered_json;

class GateVerdicts : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    write_file(dir_ / "gate.json", nine_by_nine_suite("gate", 9));
    const Outcome o = tcsb("run gate.json --quiet --out base.json");
    ASSERT_EQ(o.exit_code, 0) << o.err;
    base_ = ojson::parse(read_file(dir_ / "base.json"));
    // Fixed times (plain 1 ms, TC-SB 0.5 ms, +1 % per repetition), as compare_test.cpp sets them.
    for (ojson& c : base_["cases"]) {
      const double ms = c["method"] == "plain" ? 1.0 : 0.5;
      for (ojson& r : c["repetitions"]) r["mean_step_ms"] = ms * (1.0 + 0.01 * r["repetition"].get<int>());
    }
    write_file(dir_ / "base.json", base_.dump(2));
  }

  /// `doc` measured in instructions: every case `bullet` + `own` (TC-SB cases only) instructions.
  static ojson counted(ojson doc, std::int64_t own) {
    doc["measure"] = "instructions";
    for (ojson& c : doc["cases"]) {
      const std::int64_t o = c["method"] == "tcsb" ? own : 0, bullet = 1000000;
      c["instructions"] = {{"own", o},
                           {"bullet", bullet},
                           {"total", o + bullet},
                           {"functions",
                            ojson::array({{{"name", "btSoftBody::PSolve_Links"}, {"instructions", bullet}},
                                          {{"name", "TcSoftBody::advance_blends"}, {"instructions", o}}})}};
    }
    return doc;
  }

  Outcome compare(const ojson& base, const ojson& next, const std::string& flags = "") {
    write_file(dir_ / "a.json", base.dump(2));
    write_file(dir_ / "b.json", next.dump(2));
    return tcsb("compare a.json b.json --summary summary.md --summary-json summary.json " + flags);
  }

  ojson summary_json() const { return ojson::parse(read_file(dir_ / "summary.json")); }

  ojson base_;
};

TEST_F(GateVerdicts, AWideIntervalAcrossTheThresholdIsUndecidedAndExits4) {
  // TC-SB's ratio 10 % higher at the median, spread from -30 % to +50 %: its interval holds changes on both sides of
  // the 5 % margin.
  ojson next = base_;
  const double factors[] = {0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5};
  for (ojson& c : next["cases"]) {
    if (c["method"] != "tcsb") continue;
    for (ojson& r : c["repetitions"])
      r["mean_step_ms"] = r["mean_step_ms"].get<double>() * factors[r["repetition"].get<int>()];
  }
  const Outcome o = compare(base_, next);
  EXPECT_EQ(o.exit_code, 4) << o.err;
  EXPECT_NE(o.err.find("tcsb compare: UNDECIDED: 0 regressions, 0 behaviour changes, "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find(" per run would likely decide)"), std::string::npos) << o.err;
  const ojson s = summary_json();
  EXPECT_EQ(s["verdict"], "undecided");
  EXPECT_EQ(s["exit_code"], 4);
  EXPECT_GE(s["undecided"].get<int>(), 1);
  EXPECT_GE(s["more_repetitions"].get<int>(), 1);
  EXPECT_NE(read_file(dir_ / "summary.md").find("**undecided**"), std::string::npos);
}

TEST_F(GateVerdicts, TheJsonSummarySaysWhetherBehaviourChanged) {
  ojson next = base_;
  next["cases"][0]["repetitions"][0]["final_state_hash"] = "0000000000000000";
  const Outcome o = compare(base_, next);
  EXPECT_EQ(o.exit_code, 1) << o.err;
  const ojson s = summary_json();
  EXPECT_EQ(s["verdict"], "fail");
  EXPECT_EQ(s["behaviour_changes"], 1);
  EXPECT_EQ(s["regressions"], 0);
  EXPECT_EQ(s["measure"], "time");
  EXPECT_EQ(compare(base_, base_).exit_code, 0);
  EXPECT_EQ(summary_json()["verdict"], "pass");
}

TEST_F(GateVerdicts, CountsMissingOrImpossibleAreRefusedLikeMissingTimings) {
  // Issue 60: a hand-edited result with one case's counts removed, or zero, passed the instruction gate (exit 0).
  ojson next = counted(base_, 20000);
  next["cases"][1].erase("instructions");
  Outcome o = compare(counted(base_, 20000), next);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("b.json: cases[1].instructions"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "summary.json"));
  next = counted(base_, 20000);
  next["cases"][1]["instructions"] = {{"own", 0}, {"bullet", 0}, {"total", 0}, {"functions", ojson::array()}};
  o = compare(counted(base_, 20000), next);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("b.json: cases[1].instructions.total"), std::string::npos) << o.err;
}

TEST_F(GateVerdicts, CountsGateAtHalfAPercentWithTheFunctionsThatGrew) {
  const Outcome same = compare(counted(base_, 20000), counted(base_, 20000));
  EXPECT_EQ(same.exit_code, 0) << same.err;
  EXPECT_NE(same.err.find("tcsb compare: PASS: 0 regressions, 0 behaviour changes (3 cases' instruction counts gated "
                          "at threshold 0.5 %)"),
            std::string::npos)
      << same.err;
  // +1 % of TC-SB's step (1 020 000 -> 1 030 200): a decided regression, and the summary names the function.
  const Outcome more = compare(counted(base_, 20000), counted(base_, 30200));
  EXPECT_EQ(more.exit_code, 1) << more.err;
  const std::string md = read_file(dir_ / "summary.md");
  EXPECT_NE(md.find("**REGRESSED**"), std::string::npos) << md;
  EXPECT_NE(md.find("| TcSoftBody::advance_blends | 20000 | 30200 | +10200 |"), std::string::npos) << md;
  EXPECT_EQ(summary_json()["measure"], "instructions");
  EXPECT_EQ(summary_json()["regressions"], 2);
  EXPECT_EQ(compare(counted(base_, 20000), counted(base_, 30200), "--threshold 0.02").exit_code, 0);
}

TEST_F(GateVerdicts, ATimeResultAgainstACountResultIsRefused) {
  const Outcome o = compare(base_, counted(base_, 100));
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("a.json measured time and b.json measured instructions"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "summary.json"));
}

TEST_F(GateVerdicts, MeasuringInstructionsNeedsDeterministicWork) {
  std::string suite = nine_by_nine_suite("parallel", 1);
  suite.replace(suite.find("\"solver\""), 0, R"("feedback": {"parallel": true}, )");
  write_file(dir_ / "parallel.json", suite);
  const Outcome o = tcsb("run parallel.json --measure instructions --quiet --out p.json");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("feedback.parallel: --measure instructions: needs false"), std::string::npos) << o.err;
  EXPECT_EQ(tcsb("run gate.json --measure cycles --quiet").exit_code, 2);
  EXPECT_EQ(tcsb("run gate.json --measure instructions --format md --quiet").exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "p.json"));
}

TEST_F(GateVerdicts, TwoInstructionCountsOfOneBuildAgreeBeyondBulletsAddressOrder) {
  if (kAddressSanitized) GTEST_SKIP() << "valgrind does not run AddressSanitizer builds";
  if (shell("command -v valgrind").exit_code != 0) GTEST_SKIP() << "valgrind is not installed";
  write_file(dir_ / "tiny.json", nine_by_nine_suite("tiny", 1));
  const Outcome a = tcsb("run tiny.json --measure instructions --quiet --out a.json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const Outcome b = tcsb("run tiny.json --measure instructions --quiet --out b.json");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const ojson ra = ojson::parse(read_file(dir_ / "a.json")), rb = ojson::parse(read_file(dir_ / "b.json"));
  EXPECT_EQ(ra["measure"], "instructions");
  ASSERT_EQ(ra["cases"].size(), 3u);
  // Equal up to Bullet's DBVT rotations: btDbvt::optimizeIncremental, which every soft body's predictMotion calls,
  // rotates the tree where a parent's address is above its child's (btDbvt.cpp, sort: `if (p > n)`), so where the
  // allocator happened to put the nodes can move a run's count by a few hundred instructions in a million (seen: 37
  // in 1.08 M in about one run in twenty; 2026-12-01, 220 in 747 k of Bullet's and 264 in 614 k of TC-SB's own, whose
  // operations insert their nodes' leaves into the same, differently rotated tree). Allowed: 1e-3 of a count, five
  // times below the gate's 0.5 % threshold, so a change the gate would catch still fails here.
  for (std::size_t i = 0; i < ra["cases"].size(); ++i) {
    const ojson& ca = ra["cases"][i]["instructions"];
    const ojson& cb = rb["cases"][i]["instructions"];
    EXPECT_GT(ca["bullet"].get<std::int64_t>(), 0) << ra["cases"][i]["label"];
    for (const char* part : {"own", "bullet", "total"}) {
      const auto a_count = static_cast<double>(ca[part].get<std::int64_t>());
      const auto b_count = static_cast<double>(cb[part].get<std::int64_t>());
      EXPECT_LE(std::abs(a_count - b_count), 1e-3 * std::max(a_count, 1.0)) << ra["cases"][i]["label"] << " " << part;
    }
  }
  EXPECT_GT(ra["cases"][2]["instructions"]["own"].get<std::int64_t>(), 0) << "TC-SB at 50 % does its own work";
  const Outcome c = tcsb("compare a.json b.json");
  EXPECT_EQ(c.exit_code, 0) << c.err;
}

}  // namespace
