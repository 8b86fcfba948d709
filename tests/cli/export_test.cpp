// The formats for other tools through the real binary (`tcsb run --format`, `tcsb export`), Google Benchmark's
// own compare.py reading two exports, and a real run checked against the result schema.
#include <nlohmann/json.hpp>
#include <string>

#include "cli_fixture.h"
#include "result/result_schema.h"

namespace {

using namespace tcsb::cli_test;
using ojson = nlohmann::ordered_json;

// Debian's libbenchmark-tools; compare.py needs SciPy (python3-scipy), which pyenv-style pythons may lack.
const char* const kCompareScript = "/usr/share/benchmark/compare.py";
const char* const kSystemPython = "/usr/bin/python3";

class Export : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    run_small_suite(3);
  }
};

TEST_F(Export, ARealRunConformsToTheSchema) {
  const ojson doc = ojson::parse(read_file(dir_ / "result.json"));
  std::string problems;
  for (const tcsb::SchemaViolation& v : tcsb::check_result_document(doc)) problems += tcsb::describe(v) + "\n";
  EXPECT_EQ(problems, "");
}

TEST_F(Export, GbenchFromARunAndFromTheFileAgree) {
  const Outcome from_run = tcsb("run small.json --quiet --format gbench");
  ASSERT_EQ(from_run.exit_code, 0) << from_run.err;
  const Outcome from_file = tcsb("export result.json --format gbench");
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  for (const Outcome* o : {&from_run, &from_file}) {
    const ojson doc = ojson::parse(o->out);
    EXPECT_EQ(doc["context"]["tcsb_suite"], "small");
    ASSERT_EQ(doc["benchmarks"].size(), 3u * (3 + 4)) << "3 cases x (3 repetitions + 4 aggregates)";
    EXPECT_EQ(doc["benchmarks"][0]["name"], "n9/plain");
    EXPECT_EQ(doc["benchmarks"][0]["iterations"], 20);
  }
}

TEST_F(Export, GoogleBenchmarksComparePyReadsTwoExports) {
  if (!fs::exists(kCompareScript) || shell(std::string(kSystemPython) + " -c 'import scipy'").exit_code != 0) {
    GTEST_SKIP() << kCompareScript << " or SciPy missing (Debian: libbenchmark-tools python3-scipy)";
  }
  ASSERT_EQ(tcsb("run small.json --quiet --out second.json").exit_code, 0);
  ASSERT_EQ(tcsb("export result.json --format gbench --out a.json").exit_code, 0);
  ASSERT_EQ(tcsb("export second.json --format gbench --out b.json").exit_code, 0);
  const Outcome o = shell(std::string(kSystemPython) + " " + kCompareScript + " --no-color benchmarks a.json b.json");
  EXPECT_EQ(o.exit_code, 0) << o.out << o.err;
  EXPECT_NE(o.out.find("Comparing a.json to b.json"), std::string::npos) << o.out << o.err;
  EXPECT_NE(o.out.find("n9/tcsb@0.5_median"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("OVERALL_GEOMEAN"), std::string::npos) << o.out;
  EXPECT_EQ(o.err.find("Traceback"), std::string::npos) << o.err;
}

TEST_F(Export, GithubActionFormats) {
  const Outcome smaller = tcsb("export result.json --format github-action-smaller");
  ASSERT_EQ(smaller.exit_code, 0) << smaller.err;
  const ojson times = ojson::parse(smaller.out);
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(times[0]["name"], "n9/plain step time");
  EXPECT_EQ(times[0]["unit"], "ms");
  EXPECT_TRUE(times[0]["value"].is_number());

  const Outcome bigger = tcsb("run small.json --quiet --format github-action-bigger --out speedups.json");
  ASSERT_EQ(bigger.exit_code, 0) << bigger.err;
  const ojson speedups = ojson::parse(read_file(dir_ / "speedups.json"));
  ASSERT_EQ(speedups.size(), 2u) << "one per TC-SB case";
  EXPECT_EQ(speedups[1]["name"], "n9/tcsb@0.5 speed-up vs plain");
  EXPECT_EQ(speedups[1]["unit"], "x");
}

TEST_F(Export, MarkdownSectionOfAResultFile) {
  const Outcome from_file = tcsb("export result.json --format markdown --out result.md");
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  const std::string md = read_file(dir_ / "result.md");
  const ojson context = ojson::parse(read_file(dir_ / "result.json"))["context"];
  // The build's own commit, "-dirty" kept when this binary was built from uncommitted changes.
  const std::string commit = context["git_commit"].get<std::string>();
  EXPECT_EQ(md.substr(0, md.find('\n')), "## Run: suite `small`, " +
                                             context["date_utc"].get<std::string>().substr(0, 10) + ", " +
                                             commit.substr(0, 7) + (commit.ends_with("-dirty") ? "-dirty" : ""));
  EXPECT_NE(md.find("\nSource: suite `small` (1 nets, 3 repetitions of 20 steps) · "), std::string::npos) << md;
  EXPECT_NE(md.find("\n| method | compression | N | L | I | ms | ratio | node ratio | nets | status |\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("\n| plain | - | 81.00 | 144.0 | 0 | "), std::string::npos) << md;
  EXPECT_NE(md.find("\n### Table 1\n"), std::string::npos) << md;
  EXPECT_EQ(md.find("### Claims"), std::string::npos) << "a run has no reproduction block";
  // Rendering is a pure function of the file: the same file gives the same bytes.
  EXPECT_EQ(tcsb("export result.json --format markdown").out, md);
}

TEST_F(Export, BadInputIsOneLineAndWritesNothing) {
  const struct {
    const char* args;
    const char* expected;
  } cases[] = {
      {"export result.json --format nope --out x.json", "tcsb: error: --format: unknown format \"nope\""},
      {"export missing.json --format gbench --out x.json", "tcsb: error: missing.json: cannot read the file"},
      {"export small.json --format gbench --out x.json", "tcsb: error: small.json: tool: not a tcsb result"},
      {"export result.json --out x.json", "tcsb: error: "},
  };
  for (const auto& c : cases) {
    const Outcome o = tcsb(c.args);
    EXPECT_EQ(o.exit_code, 2) << c.args << "\n" << o.err;
    EXPECT_EQ(count_lines(o.err), 1) << c.args << "\n" << o.err;
    EXPECT_EQ(o.err.rfind(c.expected, 0), 0u) << c.args << "\n" << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.json")) << c.args;
  }
}

// One repetition of 1e308 ms: a speed-up of infinity once made export exit 3 ("internal error"). Every format
// ends 0 or 2, never 3.
TEST_F(Export, AnExtremeButFiniteTimeIsNeverAnInternalError) {
  for (const std::size_t which : {std::size_t{0}, std::size_t{2}}) {  // plain's, then TC-SB's
    ojson doc = ojson::parse(read_file(dir_ / "result.json"));
    doc["cases"][which]["repetitions"][1]["mean_step_ms"] = 1e308;
    write_file(dir_ / "extreme.json", doc.dump());
    for (const char* format : {"gbench", "github-action-smaller", "github-action-bigger", "markdown"}) {
      SCOPED_TRACE(std::string(format) + " case " + std::to_string(which));
      const Outcome o = tcsb(std::string("export extreme.json --format ") + format);
      EXPECT_TRUE(o.exit_code == 0 || o.exit_code == 2) << o.exit_code << " " << o.err;
      EXPECT_EQ(o.err.find("internal error"), std::string::npos) << o.err;
    }
  }
}

// dt 1.0 diverges at step 0: `run` wrote mean_step_ms 0.0 for it, which export, merge and compare then refused.
// What run writes, every reader accepts: no step time is null, its status says why.
TEST_F(Export, ARunDivergedAtStepZeroIsReadByEveryReader) {
  std::string suite = nine_by_nine_suite("wild", 9);
  suite.replace(suite.find("\"dt\": 0.016666666666666666"), 26, "\"dt\": 1.0");
  write_file(dir_ / "wild.json", suite);
  Outcome o = tcsb("run wild.json --quiet --out wild-result.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const ojson doc = ojson::parse(read_file(dir_ / "wild-result.json"));
  bool diverged = false;
  for (const ojson& c : doc["cases"])
    for (const ojson& r : c["repetitions"]) {
      diverged |= r["status"] == "diverged";
      if (r["status"] != "ok") {
        EXPECT_TRUE(r["mean_step_ms"].is_null() || r["mean_step_ms"].get<double>() > 0) << r;
      }
    }
  ASSERT_TRUE(diverged) << "dt 1.0 should diverge";
  for (const char* format : {"gbench", "github-action-smaller", "github-action-bigger", "markdown"}) {
    o = tcsb(std::string("export wild-result.json --format ") + format);
    EXPECT_EQ(o.exit_code, 0) << format << ": " << o.err;
  }
  o = tcsb("compare wild-result.json wild-result.json --absolute");
  EXPECT_NE(o.exit_code, 3) << o.err;
  EXPECT_EQ(o.err.find("wild-result.json: cases"), std::string::npos) << "the file itself refused: " << o.err;
  for (const char* k : {"1", "2"}) {
    o = tcsb(std::string("run wild.json --quiet --shard ") + k + "/2 --out shard" + k + ".json");
    ASSERT_EQ(o.exit_code, 0) << o.err;
  }
  o = tcsb("merge shard1.json shard2.json --quiet --out merged.json");
  EXPECT_EQ(o.exit_code, 0) << o.err;
}

}  // namespace
