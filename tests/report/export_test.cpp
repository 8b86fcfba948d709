// The exports for other tools: Google Benchmark's JSON (what tools/compare.py reads) and github-action-benchmark's
// two custom formats. The CLI tests run Google Benchmark's own compare.py on real exports when it is installed.
#include <gtest/gtest.h>

#include "analysis/statistics.h"
#include "render_run.h"
#include "report/format_registry.h"
#include "report/gbench_export.h"
#include "report/github_action_export.h"
#include "report/json_report.h"
#include "synthetic_run.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

RunResult two_net_run() {
  RunResult r;
  r.suite = testing::synthetic_suite(2);
  r.suite.compression = {0.5};
  r.suite.steps = 200;
  r.suite.repetitions = 3;
  r.cases = {testing::make_case(r.suite, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0, {1.0, 2.0, 4.0}),
             testing::make_case(r.suite, 0, Method::kTcsb, 0.5, 50, 100, 3, 0.5, {0.5, 0.5, 1.0}),
             testing::make_case(r.suite, 1, Method::kPlain, std::nullopt, 400, 800, 0, 3.0, {3.0}),
             testing::make_case(r.suite, 1, Method::kTcsb, 0.5, 200, 400, 3, 1.0, {})};
  for (RepetitionResult& rep : r.cases[1].repetitions) {
    rep.mean_nodes = 50;
    rep.mean_links = 100;
    rep.mean_interpolations = 3;
  }
  testing::diverge(r.cases[3], 9);
  r.cases[3].repetitions.erase(r.cases[3].repetitions.begin());  // only the diverged one is left
  // The exports read the case's summary of its ok repetitions' step times, as the runner writes it.
  for (CaseResult& c : r.cases) {
    std::vector<double> ok_ms;
    for (const RepetitionResult& rep : c.repetitions)
      if (rep.status == "ok") ok_ms.push_back(rep.mean_step_ms);
    c.step_ms = summarize(ok_ms);
  }
  r.context.host = "box";
  r.context.cores = 2;
  r.context.mhz = 2000.4;
  r.context.caches = {{1, "Data", 49152, 1}};
  r.context.load_average_1m = 0.5;
  r.context.optimized = true;
  return r;
}

ResultView view_of(const RunResult& r) { return read_result(testing::native_json_of(r), "result"); }

std::vector<ojson> named(const ojson& benchmarks, const std::string& name) {
  std::vector<ojson> out;
  for (const ojson& b : benchmarks) {
    if (b["name"] == name) out.push_back(b);
  }
  return out;
}

TEST(GbenchExport, ContextHasGoogleBenchmarksKeys) {
  const ojson c = gbench_json(view_of(two_net_run()))["context"];
  EXPECT_EQ(c["host_name"], "box");
  EXPECT_EQ(c["num_cpus"], 2);
  EXPECT_EQ(c["mhz_per_cpu"], 2000);
  EXPECT_EQ(c["cpu_scaling_enabled"], false);
  EXPECT_EQ(c["library_build_type"], "release");
  EXPECT_EQ(c["caches"][0], (ojson{{"type", "Data"}, {"level", 1}, {"size", 49152}, {"num_sharing", 1}}));
  EXPECT_EQ(c["load_avg"], ojson::array({0.5}));
  for (const char* key : {"date", "executable", "tcsb_suite", "tcsb_suite_sha256", "tcsb_git_commit"}) {
    EXPECT_TRUE(c.contains(key)) << key;
  }
}

TEST(GbenchExport, OneIterationEntryPerRepetitionThenAggregates) {
  const ojson b = gbench_json(view_of(two_net_run()))["benchmarks"];
  const std::vector<ojson> reps = named(b, "n0/tcsb@0.5");
  ASSERT_EQ(reps.size(), 3u) << "identical names, as Google Benchmark writes repetitions";
  EXPECT_EQ(reps[2]["run_type"], "iteration");
  EXPECT_EQ(reps[2]["run_name"], "n0/tcsb@0.5");
  EXPECT_EQ(reps[2]["repetition_index"], 2);
  EXPECT_EQ(reps[2]["repetitions"], 3);
  EXPECT_EQ(reps[2]["threads"], 1);
  EXPECT_EQ(reps[2]["iterations"], 200);
  EXPECT_EQ(reps[2]["time_unit"], "us");
  EXPECT_DOUBLE_EQ(reps[2]["real_time"].get<double>(), 1000.0);  // 1 ms
  EXPECT_EQ(reps[2]["cpu_time"], reps[2]["real_time"]);
  EXPECT_EQ(reps[2]["N"], 50.0);
  EXPECT_EQ(reps[2]["L"], 100.0);
  EXPECT_EQ(reps[2]["I"], 3.0);

  const std::vector<ojson> median = named(b, "n0/plain_median");
  ASSERT_EQ(median.size(), 1u);
  EXPECT_EQ(median[0]["run_type"], "aggregate");
  EXPECT_EQ(median[0]["aggregate_name"], "median");
  EXPECT_EQ(median[0]["aggregate_unit"], "time");
  EXPECT_EQ(median[0]["run_name"], "n0/plain");
  EXPECT_EQ(median[0]["iterations"], 3);
  EXPECT_DOUBLE_EQ(median[0]["real_time"].get<double>(), 2000.0);
  EXPECT_DOUBLE_EQ(named(b, "n0/plain_mean")[0]["real_time"].get<double>(), 7000.0 / 3.0);
  const std::vector<ojson> cv = named(b, "n0/plain_cv");
  ASSERT_EQ(cv.size(), 1u);
  EXPECT_EQ(cv[0]["aggregate_unit"], "percentage");
  EXPECT_NEAR(cv[0]["real_time"].get<double>(), std::sqrt(7.0 / 3.0) / (7.0 / 3.0), 1e-12) << "a fraction, not us";
  EXPECT_EQ(named(b, "n0/plain_stddev").size(), 1u);
}

TEST(GbenchExport, NoAggregatesForOneRepetitionAndNothingForDivergedOnes) {
  const ojson b = gbench_json(view_of(two_net_run()))["benchmarks"];
  EXPECT_EQ(named(b, "n1/plain").size(), 1u);
  EXPECT_TRUE(named(b, "n1/plain_mean").empty());
  EXPECT_TRUE(named(b, "n1/tcsb@0.5").empty()) << "its only repetition diverged: no NaN time";
  const std::string text = testing::render_of(GbenchFormat(), two_net_run());
  for (const char* bad : {"NaN", "nan", "Infinity", "null"}) EXPECT_EQ(text.find(bad), std::string::npos) << bad;
}

TEST(GithubActionExport, SmallerIsBetterStepTimes) {
  const ojson entries = github_action_step_times(view_of(two_net_run()));
  ASSERT_EQ(entries.size(), 3u) << "the diverged case has no number";
  EXPECT_EQ(entries[0]["name"], "n0/plain step time");
  EXPECT_EQ(entries[0]["unit"], "ms");
  EXPECT_DOUBLE_EQ(entries[0]["value"].get<double>(), 2.0);
  EXPECT_TRUE(entries[0]["range"].get<std::string>().starts_with("± "));
  EXPECT_NE(entries[0]["extra"].get<std::string>().find("3 repetitions"), std::string::npos);
  for (const ojson& e : entries) EXPECT_TRUE(e["value"].is_number());
}

TEST(GithubActionExport, BiggerIsBetterSpeedups) {
  const ojson entries = github_action_speedups(view_of(two_net_run()));
  ASSERT_EQ(entries.size(), 1u) << "TC-SB cases with a number only";
  EXPECT_EQ(entries[0]["name"], "n0/tcsb@0.5 speed-up vs plain");
  EXPECT_EQ(entries[0]["unit"], "x");
  // plain / TC-SB per repetition: 1/0.5, 2/0.5, 4/1 -> 2, 4, 4: median 4.
  EXPECT_DOUBLE_EQ(entries[0]["value"].get<double>(), 4.0);
  EXPECT_NE(entries[0]["extra"].get<std::string>().find("N/plain 0.500"), std::string::npos) << entries[0]["extra"];
}

TEST(ExportFormats, AreRegisteredAndRenderFromAResultFileAsFromARun) {
  const RunResult r = two_net_run();
  const ojson native = testing::native_json_of(r);
  for (const char* name : {"json", "gbench", "github-action-smaller", "github-action-bigger"}) {
    const std::unique_ptr<ReportFormat> format = make_format(name);
    ASSERT_NE(format, nullptr) << name;
    EXPECT_EQ(format->name(), name);
    const std::string text = testing::render_of(*format, r);
    EXPECT_EQ(text, format->render_native(native)) << name;
    EXPECT_TRUE(ojson::accept(text)) << name;
    EXPECT_EQ(text.back(), '\n');
  }
}

}  // namespace
}  // namespace tcsb
