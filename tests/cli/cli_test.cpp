// The real tcsb executable, run in a temporary directory: exit codes, exactly one error line on bad usage or bad
// input, no output file touched on failure, and a tiny real run whose report has every contract key. No test
// asserts a timing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace tcsb::cli_test;

/// Two repetitions: the CLI tests check files and exit codes, not timings.

TEST_F(Cli, UnknownFlagIsOneErrorLineAndExit2) {
  const Outcome o = tcsb("--bogus");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_EQ(o.err.rfind("tcsb: error: ", 0), 0u) << o.err;
  EXPECT_NE(o.err.find("--bogus"), std::string::npos) << o.err;
}

TEST_F(Cli, MissingArgumentIsOneErrorLineAndExit2) {
  const Outcome o = tcsb("run");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_EQ(o.err.rfind("tcsb: error: ", 0), 0u) << o.err;
}

TEST_F(Cli, MissingSuiteFileIsNamed) {
  const Outcome o = tcsb("run no_such_suite.json --out out.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("no_such_suite.json"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.json"));
}

TEST_F(Cli, UnknownKeyNamesFileAndFieldAndWritesNothing) {
  std::string suite = kTinySuite;
  suite.replace(suite.find("\"seed\""), 0, "\"bogus_key\": 3, ");
  write_file(dir_ / "bad.json", suite);
  const Outcome o = tcsb("run bad.json --out out.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("bad.json"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("bogus_key"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.json"));
  EXPECT_TRUE(o.out.empty());
}

TEST_F(Cli, WrongTypeNamesFieldAndKeepsAnExistingOutput) {
  std::string suite = kTinySuite;
  suite.replace(suite.find("\"steps\": 20"), 11, "\"steps\": \"many\"");
  write_file(dir_ / "bad.json", suite);
  write_file(dir_ / "out.json", "old content\n");
  const Outcome o = tcsb("run bad.json --out out.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("bad.json: steps"), std::string::npos) << o.err;
  EXPECT_EQ(read_file(dir_ / "out.json"), "old content\n");
}

TEST_F(Cli, UnwritableOutIsRejectedBeforeRunning) {
  write_file(dir_ / "tiny.json", kTinySuite);
  const Outcome o = tcsb("run tiny.json --out no_such_dir/out.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("no_such_dir"), std::string::npos) << o.err;
}

TEST_F(Cli, UnknownFormatIsRejected) {
  write_file(dir_ / "tiny.json", kTinySuite);
  const Outcome o = tcsb("run tiny.json --format nope");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("nope"), std::string::npos) << o.err;
}

TEST_F(Cli, ValidateBundledCi) {
  const Outcome o = tcsb("validate ci");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_EQ(o.out.rfind("ci: ok (4 nets, ", 0), 0u) << o.out;
  EXPECT_NE(o.out.find("MiB)"), std::string::npos) << o.out;
}

TEST_F(Cli, ListShowsTheBundledSuites) {
  const Outcome o = tcsb("list");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  for (const char* name : {"paper", "ci", "scaling"}) EXPECT_NE(o.out.find(name), std::string::npos) << name;
}

TEST_F(Cli, SuitesDirectoryCanBeOverridden) {
  fs::create_directories(dir_ / "suites");
  write_file(dir_ / "suites/mine.json", kTinySuite);
  const std::string env = "TCSB_SUITES_DIR='" + (dir_ / "suites").string() + "'";
  const Outcome list = tcsb("list", env);
  EXPECT_EQ(list.exit_code, 0) << list.err;
  EXPECT_NE(list.out.find("mine"), std::string::npos) << list.out;
  EXPECT_EQ(list.out.find("scaling"), std::string::npos) << list.out;
  EXPECT_EQ(tcsb("validate mine", env).exit_code, 0);
}

TEST_F(Cli, VersionMentionsBullet) {
  const Outcome o = tcsb("--version");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_EQ(o.out.rfind("tcsb ", 0), 0u) << o.out;
  EXPECT_NE(o.out.find("Bullet 3.24"), std::string::npos) << o.out;
}

TEST_F(Cli, HelpExits0) {
  const Outcome o = tcsb("--help");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("run"), std::string::npos);
}

TEST_F(Cli, TinyRunWritesACompleteReport) {
  write_file(dir_ / "tiny.json", kTinySuite);
  const Outcome o = tcsb("run tiny.json --out out.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(o.out.empty()) << "with --out, stdout stays empty";
  EXPECT_NE(o.err.find("Table 2"), std::string::npos) << o.err;
  const std::string text = read_file(dir_ / "out.json");
  for (const char* bad : {"NaN", "Infinity"}) EXPECT_EQ(text.find(bad), std::string::npos) << bad;
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  ASSERT_FALSE(doc.is_discarded());
  for (const char* key :
       {"schema_version", "tool", "context", "suite", "cases", "table1", "table2", "scaling", "status", "wall_s"}) {
    EXPECT_TRUE(doc.contains(key)) << key;
  }
  EXPECT_EQ(doc["schema_version"], 2);
  EXPECT_TRUE(doc["context"].contains("suite_sha256"));
  EXPECT_EQ(doc["context"]["suite_sha256"].get<std::string>().size(), 64u);
  EXPECT_TRUE(doc["scaling"].contains("step_ms_vs_nodes"));
  EXPECT_TRUE(doc["scaling"].contains("op_ms_vs_nodes"));
  EXPECT_EQ(doc["cases"].size(), 3u);
  EXPECT_EQ(doc["table1"].size(), 4u);
  EXPECT_EQ(doc["table2"].size(), 3u);
  EXPECT_TRUE(doc["status"] == "ok" || doc["status"] == "diverged");
  // Deterministic facts only (never a timing): the uncompressed TC-SB simulates every node of the net.
  EXPECT_EQ(doc["cases"][0]["net_nodes"], 81);
  for (const auto& c : doc["cases"]) EXPECT_EQ(c["repetitions"].size(), 2u);
}

TEST_F(Cli, TinyRunToStdout) {
  write_file(dir_ / "tiny.json", kTinySuite);
  const Outcome o = tcsb("run tiny.json --quiet");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_EQ(o.err.find("Table 2"), std::string::npos) << "--quiet prints no console report";
  EXPECT_TRUE(nlohmann::json::accept(o.out));
}

TEST_F(Cli, BudgetFlagsOverrideTheSuite) {
  write_file(dir_ / "tiny.json", kTinySuite);
  const Outcome o = tcsb("run tiny.json --quiet --compression 0.4 --max-step-ms 50 --out out.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir_ / "out.json"));
  EXPECT_EQ(j["suite"]["compression"], nlohmann::json::array({0.4}));
  EXPECT_DOUBLE_EQ(j["suite"]["feedback"]["max_step_ms"].get<double>(), 50.0);
  bool found = false;
  for (const auto& c : j["cases"]) found |= c["label"] == "n9/tcsb@0.4";
  EXPECT_TRUE(found);
}

TEST_F(Cli, CompressionFlagSizesPlainEqual) {
  std::string suite = kTinySuite;
  const std::string methods = R"("methods": ["plain", "tcsb"])";
  suite.replace(suite.find(methods), methods.size(), R"("methods": ["plain", "tcsb", "plain_equal"])");
  write_file(dir_ / "equal.json", suite);
  const Outcome ok = tcsb("run equal.json --quiet --compression 0.4 --out out.json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir_ / "out.json"));
  bool found = false;
  for (const auto& c : j["cases"]) found |= c["label"] == "n9/plain_equal@0.4";
  EXPECT_TRUE(found);
  fs::remove(dir_ / "out.json");
  const Outcome none = tcsb("run equal.json --quiet --compression 1.0 --out out.json");  // no budget below 1
  EXPECT_EQ(none.exit_code, 2) << none.err;
  EXPECT_EQ(count_lines(none.err), 1) << none.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.json"));
}

TEST_F(Cli, BadBudgetFlagsAreUsageErrors) {
  write_file(dir_ / "tiny.json", kTinySuite);
  for (const char* flags : {"--compression 0", "--compression 1.5", "--compression 0.5,0.5", "--max-step-ms=-1"}) {
    const Outcome o = tcsb(std::string("run tiny.json --out out.json ") + flags);
    EXPECT_EQ(o.exit_code, 2) << flags;
    EXPECT_EQ(count_lines(o.err), 1) << flags << ": " << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.json")) << flags;
  }
}

TEST_F(Cli, RepetitionsFlagOverridesTheSuiteForRunAndReproduce) {
  write_file(dir_ / "tiny.json", kTinySuite);  // 2 repetitions
  // --budget 0: no extra repetitions for undecided claims, so every case has exactly the 3 asked for.
  for (const char* command : {"run tiny.json --quiet", "reproduce --suite tiny.json --quiet --budget 0"}) {
    fs::remove(dir_ / "out.json");
    const Outcome o = tcsb(std::string(command) + " --repetitions 3 --out out.json");
    // reproduce may fail claims on one tiny net (exit 1) or leave them undecided (4); what matters here is that it
    // ran 3 repetitions.
    ASSERT_TRUE(o.exit_code == 0 || o.exit_code == 1 || o.exit_code == 4) << command << ": " << o.err;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir_ / "out.json"));
    EXPECT_EQ(j["suite"]["repetitions"], 3) << command;
    for (const auto& c : j["cases"]) EXPECT_EQ(c["repetitions"].size(), 3u) << command << " " << c["label"];
  }
}

TEST_F(Cli, ReproduceInSeveralProcessesMergesThemAndSaysSoInItsIntervals) {
  write_file(dir_ / "tiny.json", kTinySuite);
  // Six repetitions in three processes (two each), no extra ones: every interval pools the three processes.
  const Outcome o = tcsb("reproduce --suite tiny.json --quiet --budget 0 --repetitions 6 --processes 3 --out out.json");
  ASSERT_TRUE(o.exit_code == 0 || o.exit_code == 1 || o.exit_code == 4) << o.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir_ / "out.json"));
  EXPECT_EQ(j["context"]["merged_shards"], 3);
  std::set<int> processes;
  for (const auto& c : j["cases"]) {
    ASSERT_EQ(c["repetitions"].size(), 6u) << c["label"];
    for (const auto& r : c["repetitions"]) processes.insert(r["process"].get<int>());
  }
  EXPECT_EQ(processes, (std::set<int>{1, 2, 3}));
  int with_interval = 0;
  for (const auto& c : j["reproduction"]["claims"]) {
    if (c["interval"].is_null()) continue;
    EXPECT_EQ(c["processes"], 3) << c["id"];
    ++with_interval;
  }
  EXPECT_GT(with_interval, 0);
  // One process (the default) says 1; a count beyond the repetitions is refused before anything runs.
  ASSERT_TRUE(tcsb("reproduce --suite tiny.json --quiet --budget 0 --repetitions 6 --out one.json").exit_code != 2);
  const nlohmann::json one = nlohmann::json::parse(read_file(dir_ / "one.json"));  // (a temporary's member would die)
  for (const auto& c : one["reproduction"]["claims"]) {
    if (c["interval"].is_null()) continue;
    EXPECT_EQ(c["processes"], 1) << c["id"];
  }
  const Outcome bad = tcsb("reproduce --suite tiny.json --quiet --repetitions 2 --processes 3 --out bad.json");
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("--processes"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.json"));
}

TEST_F(Cli, BadRepetitionsAreUsageErrors) {
  write_file(dir_ / "tiny.json", kTinySuite);
  for (const char* command : {"run tiny.json", "reproduce --suite tiny.json"}) {
    for (const char* flag :
         {"--repetitions 0", "--repetitions 1001", "--repetitions=-2", "--repetitions 2.5", "--repetitions many"}) {
      const std::string line = std::string(command) + " --out out.json " + flag;
      const Outcome o = tcsb(line);
      EXPECT_EQ(o.exit_code, 2) << line;
      EXPECT_EQ(count_lines(o.err), 1) << line << ": " << o.err;
      EXPECT_NE(o.err.find("--repetitions"), std::string::npos) << line << ": " << o.err;
      EXPECT_FALSE(fs::exists(dir_ / "out.json")) << line;
    }
  }
}

TEST_F(Cli, BadBudgetsAreUsageErrors) {
  write_file(dir_ / "tiny.json", kTinySuite);
  for (const char* flag : {"--budget=-1", "--budget nan", "--budget inf", "--budget 1e9", "--budget soon"}) {
    const std::string line = std::string("reproduce --suite tiny.json --out out.json ") + flag;
    const Outcome o = tcsb(line);
    EXPECT_EQ(o.exit_code, 2) << line;
    EXPECT_EQ(count_lines(o.err), 1) << line << ": " << o.err;
    EXPECT_NE(o.err.find("--budget"), std::string::npos) << line << ": " << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.json")) << line;
  }
}

TEST_F(Cli, ReproducePrintsTheProjectsTargetsOnlyWithTargets) {
  write_file(dir_ / "tiny.json", kTinySuite);
  const std::string table = "Targets of this project (reported, not gating):\n";  // the heading of the table
  for (const bool with_targets : {false, true}) {
    fs::remove(dir_ / "out.json");
    const Outcome o = tcsb(std::string("reproduce --suite tiny.json --quiet --budget 0 --out out.json") +
                           (with_targets ? " --targets" : ""));
    ASSERT_TRUE(o.exit_code == 0 || o.exit_code == 1 || o.exit_code == 4) << o.err;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir_ / "out.json"));
    const nlohmann::json& targets = j["reproduction"]["targets"];
    ASSERT_FALSE(targets.empty()) << "the JSON holds the targets either way";
    EXPECT_NE(o.err.find("Claims of the paper"), std::string::npos) << o.err;
    EXPECT_EQ(o.err.find(table) != std::string::npos, with_targets) << o.err;
    for (const auto& t : targets) {  // each target's row, by its id, only with the flag
      const std::string id = t["id"];
      EXPECT_EQ(o.err.find("  " + id + " ") != std::string::npos, with_targets) << id << ": " << o.err;
    }
    if (!with_targets) {
      EXPECT_NE(o.err.find("--targets prints them"), std::string::npos) << "where to find them: " << o.err;
    }
  }
  // The bare `tcsb` is `tcsb reproduce`, so it takes the flag too.
  const Outcome help = tcsb("--help");
  EXPECT_NE(help.out.find("--targets"), std::string::npos) << help.out;
  const Outcome reproduce_help = tcsb("reproduce --help");
  EXPECT_NE(reproduce_help.out.find("--targets"), std::string::npos) << reproduce_help.out;
}

TEST_F(Cli, ReproduceGivesEveryClaimAVerdictAndExitsByThem) {
  write_file(dir_ / "tiny.json", kTinySuite);  // 2 repetitions: too few for an interval, so look 1 decides nothing
  const Outcome o = tcsb("reproduce --suite tiny.json --quiet --budget 60 --out out.json");
  const nlohmann::json j = nlohmann::json::parse(read_file(dir_ / "out.json"));
  const nlohmann::json& r = j["reproduction"];
  bool any_fail = false, any_undecided = false;
  for (const auto& c : r["claims"]) {
    const std::string v = c["verdict"];
    ASSERT_TRUE(v == "pass" || v == "fail" || v == "undecided") << c["id"];
    any_fail = any_fail || v == "fail";
    any_undecided = any_undecided || v == "undecided";
    if (c["id"].get<std::string>().rfind("op_work_", 0) == 0) {  // Figure 4's witness: work counts, exact
      EXPECT_EQ(c["evidence"], "deterministic") << c["id"];
      continue;
    }
    EXPECT_EQ(c["evidence"], "repeated") << c["id"];        // the paper's other claims are judged on intervals ...
    EXPECT_TRUE(c["look"].is_number_integer()) << c["id"];  // ... at a look
  }
  const std::string overall = r["verdict"];
  EXPECT_EQ(overall, any_fail ? "fail" : any_undecided ? "undecided" : "pass");
  EXPECT_EQ(o.exit_code, any_fail ? 1 : any_undecided ? 4 : 0) << o.err;
  // Look 1 had no intervals; the looks after it added repetitions (to at least 5: enough for an interval).
  ASSERT_GE(r["sequential"]["looks"].size(), 2u) << o.err;
  EXPECT_EQ(r["sequential"]["looks"][1]["extra_repetitions"], 3);
  std::size_t most = 0;
  for (const auto& c : j["cases"]) most = std::max(most, c["repetitions"].size());
  EXPECT_GE(most, 5u);
  EXPECT_EQ(j["suite"]["repetitions"], 2);  // the suite as given; the cases say how many ran
}

TEST_F(Cli, FramesRecordsBothBodiesAtTheRequestedSteps) {
  write_file(dir_ / "tiny.json", kTinySuite);
  const Outcome o = tcsb("frames --suite tiny.json --net n9 --compression 0.5 --steps 0,5,10 --out frames.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir_ / "frames.json"));
  // Like every file tcsb writes: a schema version, the tool, and the context it was recorded in.
  EXPECT_EQ(j["schema_version"], 1);
  EXPECT_EQ(j["tool"], "tcsb");
  EXPECT_EQ(j["kind"], "frames");
  EXPECT_TRUE(j["context"]["git_commit"].is_string());
  EXPECT_EQ(j["context"]["suite_path"], "tiny.json");
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["net"]["width"], 9);
  ASSERT_EQ(j["frames"].size(), 3u);
  EXPECT_EQ(j["frames"][2]["step"], 10);
  EXPECT_EQ(j["calibrated"], false);
  for (const auto& f : j["frames"]) {
    EXPECT_EQ(f["plain"].size(), 81u);
    EXPECT_EQ(f["tcsb_surface"].size(), 81u);
    EXPECT_EQ(f["tcsb_nodes"][0].size(), 3u);
    EXPECT_TRUE(f["tcsb_links"][0][2].is_string());
  }
}

TEST_F(Cli, BadFramesArgumentsAreUsageErrors) {
  write_file(dir_ / "tiny.json", kTinySuite);
  for (const char* flags : {"--net n99", "--steps 5,3", "--steps=-1", "--steps 100001", "--compression 0",
                            "--compression 1.5", "--steps x", "--calibrated"}) {  // tiny.json has no calibration
    const std::string line = std::string("frames --suite tiny.json --out frames.json ") + flags;
    const Outcome o = tcsb(line);
    EXPECT_EQ(o.exit_code, 2) << line;
    EXPECT_EQ(count_lines(o.err), 1) << line << ": " << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "frames.json")) << line;
  }
}

}  // namespace

namespace {

using namespace tcsb::cli_test;

TEST_F(Cli, CalibrateWritesTheFileASuiteThenUsesAndValidateChecks) {
  write_file(dir_ / "s.json", nine_by_nine_suite("s", 1));
  const Outcome made = tcsb("calibrate s.json --quiet");
  ASSERT_EQ(made.exit_code, 0) << made.err;
  EXPECT_TRUE(made.out.empty()) << made.out;
  ASSERT_TRUE(fs::exists(dir_ / "s.calibration.json"));  // beside the suite by default
  EXPECT_NE(read_file(dir_ / "s.calibration.json").find("\"levels\""), std::string::npos);
  // The suite names it: validate reads and checks it; a run adds the calibrated rows.
  std::string suite = nine_by_nine_suite("s", 1);
  suite.replace(suite.rfind('}'), 1, ", \"fidelity\": {\"enabled\": true, \"calibration\": \"s.calibration.json\"}}");
  write_file(dir_ / "with.json", suite);
  const Outcome valid = tcsb("validate with.json");
  EXPECT_EQ(valid.exit_code, 0) << valid.err;
  const Outcome run = tcsb("run with.json --quiet --out out.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string result = read_file(dir_ / "out.json");
  EXPECT_NE(result.find("\"tcsb_calibrated\""), std::string::npos);
  EXPECT_NE(result.find("\"uniform_grid_calibrated\""), std::string::npos);
  // Another iteration count: refused in one line naming the field, nothing written.
  std::string other = suite;
  other.replace(other.find("\"piterations\": 2"), 16, "\"piterations\": 3");
  write_file(dir_ / "other.json", other);
  const Outcome refused = tcsb("run other.json --out refused.json");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(count_lines(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("fidelity.calibration"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir_ / "refused.json"));
  // --check measures it on another suite's nets (here: the same net under half the gravity) and writes nothing.
  std::string half = nine_by_nine_suite("s", 1);
  half.replace(half.find("\"gravity\": 9.81"), 15, "\"gravity\": 4.905");
  write_file(dir_ / "half.json", half);
  const Outcome checked = tcsb("calibrate half.json --check s.calibration.json");
  ASSERT_EQ(checked.exit_code, 0) << checked.err;
  EXPECT_NE(checked.out.find("level 1: kLST"), std::string::npos) << checked.out;
  EXPECT_FALSE(fs::exists(dir_ / "half.calibration.json"));
  const Outcome other_iterations = tcsb("calibrate other.json --check s.calibration.json");
  EXPECT_EQ(other_iterations.exit_code, 2);
  EXPECT_NE(other_iterations.err.find("--check"), std::string::npos) << other_iterations.err;
  // A missing suite: exit 2, no calibration written.
  const Outcome missing = tcsb("calibrate nope.json");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(count_lines(missing.err), 1) << missing.err;
}

}  // namespace
