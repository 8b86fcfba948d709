// Suites with axes through the real executable: `tcsb validate` counts configurations, bad axes are refused in one
// line with nothing written, a run with axes equals the suite run once per configuration without them, and shards
// of it merge into that run; `tcsb compare` pairs its cases one to one.
#include <nlohmann/json.hpp>

#include <regex>
#include <set>

#include "cli_fixture.h"

namespace tcsb::cli_test {
namespace {

using json = nlohmann::json;

/// The CLI tests' 9x9 suite with `axes` added (or, with a null `axes`, without them), the settings in `settings`
/// applied first ({"solver.piterations": 4, ...}: section.key paths).
std::string suite_text(const json& axes, const json& settings = json::object(), int nets = 1) {
  json s = json::parse(nine_by_nine_suite("axes", 2));
  for (int i = 1; i < nets; ++i) {  // more nets: 11x11, 13x13, ...
    json net = s["nets"][0];
    net["name"] = std::string("n").append(std::to_string(9 + 2 * i));  // not "n" + ...: GCC 12 -Wrestrict
    net["width"] = net["height"] = 9 + 2 * i;
    s["nets"].push_back(net);
  }
  for (const auto& [path, value] : settings.items()) {
    const std::size_t dot = path.find('.');
    if (dot == std::string::npos)
      s[path] = value;
    else
      s[path.substr(0, dot)][path.substr(dot + 1)] = value;
  }
  if (!axes.is_null()) s["axes"] = axes;
  return s.dump(2);
}

/// "n9/tcsb@0.5[piterations=2,blend_steps=4]" -> "n9/tcsb@0.5".
std::string without_configuration(const std::string& label) { return label.substr(0, label.find('[')); }

/// The fields of two cases that do not depend on the machine's speed are equal (labels up to the configuration).
void expect_same_case(const json& a, const json& b) {
  SCOPED_TRACE(a["label"].get<std::string>());
  EXPECT_EQ(without_configuration(a["label"]), without_configuration(b["label"]));
  for (const char* key : {"net", "method", "compression", "target_nodes", "net_nodes", "net_links", "status",
                          "mean_nodes", "mean_links", "mean_interpolations"})
    EXPECT_EQ(a[key], b[key]) << key;
  EXPECT_EQ(a.value("op_work", json()), b.value("op_work", json()));
  ASSERT_EQ(a["repetitions"].size(), b["repetitions"].size());
  for (std::size_t r = 0; r < a["repetitions"].size(); ++r) {
    for (const char* key : {"repetition", "status", "operations", "mean_nodes", "mean_links", "final_state_hash"})
      EXPECT_EQ(a["repetitions"][r][key], b["repetitions"][r][key]) << "repetition " << r << " " << key;
  }
}

/// Table 1 and Table 2's deterministic columns are equal.
void expect_same_tables(const json& a, const json& b) {
  ASSERT_EQ(a["table1"].size(), b["table1"].size());
  for (std::size_t i = 0; i < a["table1"].size(); ++i)
    for (const char* key : {"operation", "N", "L", "count"}) EXPECT_EQ(a["table1"][i][key], b["table1"][i][key]);
  ASSERT_EQ(a["table2"].size(), b["table2"].size());
  for (std::size_t i = 0; i < a["table2"].size(); ++i)
    for (const char* key : {"method", "compression", "N", "L", "I", "node_ratio", "nets", "status"})
      EXPECT_EQ(a["table2"][i][key], b["table2"][i][key]) << key;
  EXPECT_EQ(a["scaling"]["step_ms_vs_nodes"].size(), b["scaling"]["step_ms_vs_nodes"].size());
}

class Axes : public Cli {
 protected:
  json load(const std::string& file) const { return json::parse(read_file(dir_ / file)); }
};

const json kTwoByTwo = {{"solver.piterations", {2, 4}}, {"tcsb.blend_steps", {2, 4}}};

TEST_F(Axes, ValidateCountsConfigurationsCasesMemoryAndWallTime) {
  write_file(dir_ / "axes.json", suite_text(kTwoByTwo));
  const Outcome o = tcsb("validate axes.json");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  // 4 configurations x (plain, tcsb@1.0, tcsb@0.5).
  EXPECT_TRUE(
      std::regex_match(o.out, std::regex("axes\\.json: ok \\(1 nets, 4 configurations, 12 cases, 2 repetitions, "
                                         "estimated peak memory [0-9.]+ MiB, estimated wall time "
                                         "(about [0-9]+|under 1) s\\)\n")))
      << o.out;
  // Without axes, the line it always printed.
  write_file(dir_ / "plain.json", suite_text(json()));
  const Outcome p = tcsb("validate plain.json");
  EXPECT_TRUE(std::regex_match(
      p.out, std::regex("plain\\.json: ok \\(1 nets, 3 cases, 2 repetitions, estimated peak memory [0-9.]+ MiB\\)\n")))
      << p.out;
}

TEST_F(Axes, BadAxesAreRefusedInOneLineNamingTheFieldAndNothingIsWritten) {
  const std::vector<std::pair<json, std::string>> bad = {
      {{{"solver.pitterations", {2}}}, "axes.solver.pitterations: unknown setting"},
      {{{"solver.piterations", {2, "8"}}}, "axes.solver.piterations[1]: must be an integer in [1, 1000], got string"},
      {{{"solver.piterations", json::array()}}, "axes.solver.piterations: must not be empty"},
      {{{"solver.piterations", {2, 2}}}, "axes.solver.piterations[1]: duplicate value 2"},
      {{{"repetitions", {2, 3}}}, "axes.repetitions: cannot be an axis"},
      {{{"feedback.parallel", {true, false}}}, "axes.feedback.parallel: cannot be an axis"},
      {{{"seed", json::array()}, {"steps", {1}}}, "axes.seed: must not be empty"},
  };
  for (const auto& [axes, message] : bad) {
    SCOPED_TRACE(axes.dump());
    write_file(dir_ / "bad.json", suite_text(axes));
    for (const std::string command : {"validate bad.json", "run bad.json --quiet --out out.json"}) {
      const Outcome o = tcsb(command);
      EXPECT_EQ(o.exit_code, 2) << command;
      EXPECT_EQ(count_lines(o.err), 1) << o.err;
      EXPECT_NE(o.err.find("bad.json: " + message), std::string::npos) << o.err;
      EXPECT_TRUE(o.out.empty());
      EXPECT_FALSE(fs::exists(dir_ / "out.json"));
    }
  }
  json many_seeds = json::array(), many_steps = json::array();
  for (int i = 0; i < 100; ++i) many_seeds.push_back(i);
  for (int i = 1; i <= 11; ++i) many_steps.push_back(i);
  write_file(dir_ / "bad.json", suite_text({{"seed", many_seeds}, {"steps", many_steps}}));
  const Outcome o = tcsb("run bad.json --quiet --out out.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("bad.json: axes: 100 x 11 = 1100 configurations, more than the 1000"), std::string::npos)
      << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.json"));
}

TEST_F(Axes, CommandsOfOneConfigurationRefuseAxes) {
  write_file(dir_ / "axes.json", suite_text(kTwoByTwo));
  for (const std::string command :
       {"reproduce --suite axes.json --quiet --out out.json", "frames --suite axes.json --out out.json"}) {
    const Outcome o = tcsb(command);
    EXPECT_EQ(o.exit_code, 2) << command << ": " << o.err;
    EXPECT_EQ(count_lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("axes.json: axes: "), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.json"));
  }
}

TEST_F(Axes, ARunWithAxesIsTheSuiteRunOncePerConfiguration) {
  write_file(dir_ / "axes.json", suite_text(kTwoByTwo));
  const Outcome o = tcsb("run axes.json --out axes_run.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const json run = load("axes_run.json");
  EXPECT_EQ(run["suite"]["axes"], kTwoByTwo);
  ASSERT_EQ(run["configurations"].size(), 4u);
  ASSERT_EQ(run["cases"].size(), 12u);
  EXPECT_TRUE(run["table2"].empty());  // per configuration only
  std::set<std::string> labels;
  for (const json& c : run["cases"]) labels.insert(c["label"].get<std::string>());
  EXPECT_EQ(labels.size(), 12u);
  // The console groups the tables by configuration.
  EXPECT_NE(o.err.find("== Configuration 1 of 4: piterations=2,blend_steps=2 =="), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("== Configuration 4 of 4: piterations=4,blend_steps=4 =="), std::string::npos) << o.err;

  std::size_t c = 0;
  for (const int piterations : {2, 4}) {
    for (const int blend_steps : {2, 4}) {
      const std::string label =
          "piterations=" + std::to_string(piterations) + ",blend_steps=" + std::to_string(blend_steps);
      SCOPED_TRACE(label);
      write_file(dir_ / "alone.json",
                 suite_text(json(), {{"solver.piterations", piterations}, {"tcsb.blend_steps", blend_steps}}));
      ASSERT_EQ(tcsb("run alone.json --quiet --out alone_run.json").exit_code, 0);
      const json alone = load("alone_run.json");
      const json& configuration = run["configurations"][c];
      EXPECT_EQ(configuration["label"], label);
      EXPECT_EQ(configuration["axes"], (json{{"solver.piterations", piterations}, {"tcsb.blend_steps", blend_steps}}));
      EXPECT_EQ(configuration["cases"], 3);
      expect_same_tables(configuration, alone);
      ASSERT_EQ(alone["cases"].size(), 3u);
      for (std::size_t i = 0; i < 3; ++i) {
        const json& with_axes = run["cases"][3 * c + i];
        EXPECT_EQ(with_axes["configuration"]["label"], label);
        EXPECT_EQ(with_axes["label"], alone["cases"][i]["label"].get<std::string>() + "[" + label + "]");
        expect_same_case(with_axes, alone["cases"][i]);
      }
      ++c;
    }
  }
  // The settings change what a case computes: the configurations are not all one run.
  std::set<std::string> hashes;
  for (const json& k : run["cases"]) hashes.insert(k["repetitions"][0]["final_state_hash"].get<std::string>());
  EXPECT_GT(hashes.size(), 3u);
}

TEST_F(Axes, ShardsOfASuiteWithAxesMergeIntoTheWholeRunAndCompareOneToOne) {
  // Nine repetitions: the fewest with which the gate decides (fewer leave it undecided, exit 2).
  write_file(dir_ / "axes.json", suite_text({{"tcsb.blend_steps", {2, 4}}}, {{"repetitions", 9}}, 2));
  ASSERT_EQ(tcsb("run axes.json --quiet --out whole.json").exit_code, 0);
  const json whole = load("whole.json");
  ASSERT_EQ(whole["cases"].size(), 12u);  // 2 configurations x 2 nets x 3 cases
  std::string shards;
  std::set<std::string> covered;
  for (int k = 1; k <= 3; ++k) {
    const std::string file = "shard_" + std::to_string(k) + ".json";
    const Outcome o = tcsb("run axes.json --quiet --split nets --shard " + std::to_string(k) + "/3 --out " + file);
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const json shard = load(file);
    // A configuration's cases of one net stay together in one shard.
    std::set<std::string> units;
    for (const json& c : shard["cases"]) {
      units.insert(c["net"].get<std::string>() + c["configuration"]["label"].get<std::string>());
      EXPECT_TRUE(covered.insert(c["label"].get<std::string>()).second) << c["label"] << " in two shards";
    }
    EXPECT_EQ(shard["cases"].size(), 3 * units.size());
    EXPECT_EQ(shard["configurations"].size(), 2u);
    shards += " " + file;
  }
  EXPECT_EQ(covered.size(), 12u);
  const Outcome m = tcsb("merge" + shards + " --out merged.json");
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const json merged = load("merged.json");
  EXPECT_EQ(merged["suite"], whole["suite"]);
  ASSERT_EQ(merged["cases"].size(), whole["cases"].size());
  for (std::size_t i = 0; i < whole["cases"].size(); ++i) {
    EXPECT_EQ(merged["cases"][i]["label"], whole["cases"][i]["label"]);
    EXPECT_EQ(merged["cases"][i]["configuration"], whole["cases"][i]["configuration"]);
    expect_same_case(merged["cases"][i], whole["cases"][i]);
  }
  ASSERT_EQ(merged["configurations"].size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(merged["configurations"][c]["label"], whole["configurations"][c]["label"]);
    expect_same_tables(merged["configurations"][c], whole["configurations"][c]);
  }
  // The gate pairs every case and repetition one to one: no behaviour changes between the two.
  const Outcome g = tcsb("compare --threshold 10 whole.json merged.json");
  EXPECT_NE(g.err.find(", 0 behaviour changes"), std::string::npos) << g.err;
  // A merged result with axes is a result like any other.
  EXPECT_EQ(tcsb("export merged.json --format markdown").exit_code, 0);
}

}  // namespace
}  // namespace tcsb::cli_test
