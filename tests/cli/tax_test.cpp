// `tcsb tax`, on a real run of a tiny suite with plain_equal whose timings are then set in the JSON (so no verdict
// depends on the machine): exit 0 / 1 / 4 for pass / fail / undecided with the JSON verdict on stdout and the table
// on stderr, 2 with one line for anything it cannot judge.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace tcsb::cli_test;
using ojson = nlohmann::ordered_json;

/// The flags that put the tiny net in scope: its 81 nodes and its only budget.
const std::string kScope = " --min-nodes 1 --compression 0.5";

class Tax : public Cli {
 protected:
  /// Runs the 9 x 9 suite with plain_equal and `repetitions` into run.json, with TC-SB at `ratio` x plain_equal's
  /// time in every repetition.
  void make_run(int repetitions, double ratio, const std::string& file = "run.json") {
    std::string suite = nine_by_nine_suite("taxed", repetitions);
    const std::string methods = R"("methods": ["plain", "tcsb"])";
    suite.replace(suite.find(methods), methods.size(), R"("methods": ["plain", "tcsb", "plain_equal"])");
    write_file(dir_ / "taxed.json", suite);
    const Outcome o = tcsb("run taxed.json --quiet --out " + file);
    ASSERT_EQ(o.exit_code, 0) << o.err;
    set_times(file, ratio);
  }

  /// Sets every repetition's time in `file`: TC-SB at `ratio` x the others'. Each file's times differ a little from
  /// every other's, as two processes' do (tax counts files of identical times as one process).
  void set_times(const std::string& file, double ratio) {
    ojson doc = ojson::parse(read_file(dir_ / file));
    const double process = 1.0 + 0.001 * ++files_timed_;
    for (ojson& c : doc["cases"]) {
      const double ms = c["method"] == "tcsb" ? ratio : 1.0;
      for (ojson& r : c["repetitions"]) r["mean_step_ms"] = process * ms * (1.0 + 0.01 * r["repetition"].get<int>());
    }
    write_file(dir_ / file, doc.dump(2));
  }

  /// Runs a suite of two 9 x 9 nets with plain_equal and six repetitions as two shards, shard-1.json and
  /// shard-2.json (split by `split`: "nets" or "repetitions"), each net's TC-SB at `ratio` x plain_equal's time.
  void make_shards(double ratio, const std::string& split = "nets") {
    std::string suite = nine_by_nine_suite("sharded", 6);
    const std::string methods = R"("methods": ["plain", "tcsb"])";
    suite.replace(suite.find(methods), methods.size(), R"("methods": ["plain", "tcsb", "plain_equal"])");
    const std::string net = R"({"name": "n9", "width": 9, "height": 9, "size": [2.0, 2.0], "elevation": 2.0,)"
                            R"( "mass": {"total": 1.0}, "pinned": "corners"})";
    const std::size_t at = suite.find(R"({"name": "n9")");
    const std::size_t end = suite.find("}]", at);
    suite.replace(at, end + 1 - at, net + ", " + std::string(net).replace(net.find("n9"), 2, "m9"));
    write_file(dir_ / "sharded.json", suite);
    for (const char* k : {"1", "2"}) {
      const std::string file = std::string("shard-") + k + ".json";
      const Outcome o = tcsb("run sharded.json --quiet --split " + split + " --shard " + k + "/2 --out " + file);
      ASSERT_EQ(o.exit_code, 0) << o.err;
      set_times(file, ratio);
    }
  }

  /// Edits `file` in place.
  void edit(const std::string& file, const std::function<void(ojson&)>& change) {
    ojson doc = ojson::parse(read_file(dir_ / file));
    change(doc);
    write_file(dir_ / file, doc.dump(2));
  }

  int files_timed_ = 0;

  static void expect_bad_input(const Outcome& o, const std::string& expected) {
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_EQ(count_lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find(expected), std::string::npos) << o.err;
    EXPECT_TRUE(o.out.empty()) << o.out;
  }
};

TEST_F(Tax, BelowTheBoundPassesWithTheVerdictOnStdoutAndTheTableOnStderr) {
  make_run(6, 1.02);
  const Outcome o = tcsb("tax run.json" + kScope);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const ojson verdict = ojson::parse(o.out);
  EXPECT_EQ(verdict["tax"]["verdict"], "pass");
  ASSERT_EQ(verdict["tax"]["nets"].size(), 1u);
  EXPECT_EQ(verdict["tax"]["nets"][0]["net"], "n9");
  EXPECT_EQ(verdict["tax"]["nets"][0]["ratios"], 6);
  EXPECT_NEAR(verdict["tax"]["nets"][0]["ratio"].get<double>(), 1.02, 1e-9);
  EXPECT_NE(o.err.find("tcsb tax: pass"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("one run"), std::string::npos) << "a single run is warned of: " << o.err;
}

TEST_F(Tax, AboveTheBoundFails) {
  make_run(6, 1.30);
  EXPECT_EQ(tcsb("tax run.json" + kScope).exit_code, 1);
  EXPECT_EQ(tcsb("tax run.json --bound 1.5" + kScope).exit_code, 0);
}

TEST_F(Tax, TooFewRepetitionsAreUndecidedAndRunsPool) {
  make_run(3, 1.02, "a.json");
  Outcome o = tcsb("tax a.json" + kScope);
  EXPECT_EQ(o.exit_code, 4) << o.err;
  EXPECT_EQ(ojson::parse(o.out)["tax"]["verdict"], "undecided");
  // A second run of the same suite and build (its own process, times a little apart) makes six ratios.
  make_run(3, 1.03, "b.json");
  o = tcsb("tax a.json b.json --out verdict.json" + kScope);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(o.out.empty());
  const ojson verdict = ojson::parse(read_file(dir_ / "verdict.json"));
  EXPECT_EQ(verdict["tax"]["nets"][0]["runs"], 2);
  EXPECT_EQ(verdict["tax"]["runs"], ojson({"a.json", "b.json"}));
  EXPECT_EQ(o.err.find("one run"), std::string::npos) << o.err;
}

TEST_F(Tax, OverTheNetsIsOneClaim) {
  make_run(6, 1.02);
  const Outcome o = tcsb("tax run.json --over-nets" + kScope);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const ojson verdict = ojson::parse(o.out);
  EXPECT_EQ(verdict["tax"]["over_nets"], true);
  ASSERT_EQ(verdict["tax"]["nets"].size(), 1u);
  EXPECT_EQ(verdict["tax"]["nets"][0]["net"], "n9");
  EXPECT_NE(o.err.find("over the nets"), std::string::npos) << o.err;
}

TEST_F(Tax, RunsOfAModifiedTreeAreWarnedOf) {
  make_run(3, 1.02, "a.json");
  make_run(3, 1.03, "b.json");
  for (const char* file : {"a.json", "b.json"}) {
    ojson doc = ojson::parse(read_file(dir_ / file));
    doc["context"]["git_commit"] = "0123abc-dirty";
    write_file(dir_ / file, doc.dump(2));
  }
  const Outcome o = tcsb("tax a.json b.json" + kScope);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("a.json was built from a modified tree (0123abc-dirty)"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("b.json was built from a modified tree"), std::string::npos) << o.err;
}

TEST_F(Tax, WhatCannotBeJudgedIsOneLineAndExit2) {
  make_run(6, 1.02);
  expect_bad_input(tcsb("tax run.json"), "nothing to judge");  // 81 nodes: below the default 66 049
  expect_bad_input(tcsb("tax run.json run.json" + kScope), "the same run as run.json");
  fs::copy_file(dir_ / "run.json", dir_ / "copy.json");
  expect_bad_input(tcsb("tax run.json copy.json" + kScope), "copy.json: the same run as run.json");
  ojson other = ojson::parse(read_file(dir_ / "run.json"));
  other["suite"]["steps"] = 21;
  write_file(dir_ / "other.json", other.dump());
  set_times("other.json", 1.02);  // another process's times: refused for its suite, not as a copy
  expect_bad_input(tcsb("tax run.json other.json" + kScope), "cannot be pooled");
  expect_bad_input(tcsb("tax run.json --bound 0" + kScope), "--bound");
  expect_bad_input(tcsb("tax run.json --min-nodes 1 --compression 1"), "--compression");
  expect_bad_input(tcsb("tax missing.json" + kScope), "missing.json");
  write_file(dir_ / "verdict.json", "kept");
  expect_bad_input(tcsb("tax run.json --out verdict.json"), "nothing to judge");
  EXPECT_EQ(read_file(dir_ / "verdict.json"), "kept") << "bad input must not touch the output file";
}

TEST_F(Tax, ANetMissingFromAShardIsIgnoredThereSoAClearFailureFails) {
  make_shards(2.5);
  const Outcome o = tcsb("tax shard-1.json shard-2.json" + kScope);
  EXPECT_EQ(o.exit_code, 1) << o.err;  // undecided (exit 4, an interval from 0) when the missing net counted as 0
  const ojson verdict = ojson::parse(o.out);
  ASSERT_EQ(verdict["tax"]["nets"].size(), 2u);
  for (const ojson& net : verdict["tax"]["nets"]) {
    EXPECT_EQ(net["runs"], 1) << net.dump();
    EXPECT_EQ(net["verdict"], "fail") << net.dump();
  }
}

TEST_F(Tax, EachProcessIsPooledOnceWhateverItsFileSays) {
  make_shards(1.02);
  ASSERT_EQ(tcsb("merge shard-1.json shard-2.json --quiet --out merged.json").exit_code, 0);
  expect_bad_input(tcsb("tax merged.json shard-2.json" + kScope), "shard-2.json: the same run as merged.json");
  // Issue 60: split by repetitions, no case of a shard is a case of the merged result, only some of its repetitions;
  // `tcsb tax merged.json shard-1.json` pooled shard 1's three repetitions twice (nine ratios from six).
  make_shards(1.02, "repetitions");
  ASSERT_EQ(tcsb("merge shard-1.json shard-2.json --quiet --out merged.json").exit_code, 0);
  expect_bad_input(tcsb("tax merged.json shard-1.json" + kScope), "shard-1.json: the same run as merged.json");
  expect_bad_input(tcsb("tax shard-2.json merged.json" + kScope), "merged.json: the same run as shard-2.json");
  make_run(6, 1.02, "a.json");
  fs::copy_file(dir_ / "a.json", dir_ / "b.json");
  edit("b.json", [](ojson& doc) {
    doc["context"]["date_utc"] = "2030-01-01T00:00:00Z";
    doc["wall_s"] = 99.0;
  });
  expect_bad_input(tcsb("tax a.json b.json" + kScope), "b.json: the same run as a.json");
}

TEST_F(Tax, RunsOfDifferentBuildsAreRefusedNotWarnedOf) {
  make_run(3, 1.02, "a.json");
  make_run(3, 1.03, "b.json");
  // Another build than this one, whichever this is (the sanitizer build is Debug).
  const ojson context = ojson::parse(read_file(dir_ / "a.json"))["context"];
  const auto other = [&](const char* key, const std::string& a, const std::string& b) {
    return context[key] == a ? b : a;
  };
  for (const auto& [key, value] : std::vector<std::pair<std::string, ojson>>{
           {"build_type", other("build_type", "Debug", "Release")},
           {"compiler", context["compiler"].get<std::string>() + " (another)"},
           {"bullet_precision", other("bullet_precision", "double", "single")}}) {
    SCOPED_TRACE(key);
    fs::copy_file(dir_ / "b.json", dir_ / "other.json", fs::copy_options::overwrite_existing);
    edit("other.json", [&](ojson& doc) { doc["context"][key] = value; });
    expect_bad_input(tcsb("tax a.json other.json" + kScope), "cannot be pooled");
  }
}

TEST_F(Tax, ImpossibleRunsAreRefused) {
  make_run(6, 1.02, "run.json");
  fs::copy_file(dir_ / "run.json", dir_ / "zeros.json");
  edit("zeros.json", [](ojson& doc) {
    for (ojson& c : doc["cases"])
      for (ojson& r : c["repetitions"]) r["repetition"] = 0;
  });
  expect_bad_input(tcsb("tax zeros.json" + kScope), "zeros.json: cases[0].repetitions[1].repetition");
  fs::copy_file(dir_ / "run.json", dir_ / "big.json");
  edit("big.json", [](ojson& doc) {
    for (ojson& c : doc["cases"]) c["net_nodes"] = 70000;
  });
  expect_bad_input(tcsb("tax big.json" + kScope), "big.json: cases[0].net_nodes: 70000, but net n9 has 81 nodes");
}

}  // namespace
