// `tcsb run --shard K/N [--split repetitions|nets]` and `tcsb merge`: merged shards are the unsharded run in every
// deterministic field, per repetition, each repetition marked with the shard that measured it; and bad sets of shards
// are refused with one line naming the file, nothing written.
#include <nlohmann/json.hpp>

#include <map>
#include <set>

#include "cli_fixture.h"

namespace tcsb::cli_test {
namespace {

using json = nlohmann::json;

/// Three small nets, plain and TC-SB: quick shards with a real split (the nets land in different shards).
std::string three_net_suite(const std::string& name, bool fidelity = false,
                            const std::string& methods = R"("plain", "tcsb")") {
  std::string nets;
  for (const int w : {9, 11, 13}) {
    nets += std::string(nets.empty() ? "" : ", ") + R"({"name": "n)" + std::to_string(w) + R"(", "width": )" +
            std::to_string(w) + R"(, "height": )" + std::to_string(w) +
            R"(, "size": [2.0, 2.0], "elevation": 2.0, "mass": {"total": 1.0}, "pinned": "corners"})";
  }
  return R"({"name": ")" + name + R"(", "description": "three small nets for the shard tests", "nets": [)" + nets +
         R"(], "methods": [)" + methods + R"(], "compression": [1.0, 0.5], "dt": 0.016666666666666666, "gravity": 9.81,
  "steps": 16, "warmup_steps": 4, "repetitions": 2, "seed": 3, "solver": {"piterations": 2},
  "fidelity": {"enabled": )" +
         (fidelity ? "true" : "false") + R"(, "rms_threshold_pct": 1.0, "pareto_targets": [], "ablations": false}})";
}

/// Every field of a result that does not depend on the machine's speed must be equal: the cases in order with their
/// N, L, I, statuses, operation work and every repetition's counts and final-state hash; the tables' deterministic
/// columns; the suite; the fidelity pass's deterministic fields.
void expect_same_deterministic_fields(const json& a, const json& b) {
  json sa = a["suite"], sb = b["suite"];
  EXPECT_EQ(sa, sb);
  EXPECT_EQ(a["status"], b["status"]);
  ASSERT_EQ(a["cases"].size(), b["cases"].size());
  for (std::size_t i = 0; i < a["cases"].size(); ++i) {
    const json &ca = a["cases"][i], &cb = b["cases"][i];
    SCOPED_TRACE(ca["label"].get<std::string>());
    for (const char* key : {"label", "net", "method", "compression", "target_nodes", "net_nodes", "net_links", "status",
                            "mean_nodes", "mean_links", "mean_interpolations"}) {
      EXPECT_EQ(ca[key], cb[key]) << key;
    }
    EXPECT_EQ(ca.value("op_work", json()), cb.value("op_work", json()));
    EXPECT_EQ(ca["step_ms"]["count"], cb["step_ms"]["count"]);
    ASSERT_EQ(ca["repetitions"].size(), cb["repetitions"].size());
    for (std::size_t r = 0; r < ca["repetitions"].size(); ++r) {
      const json &ra = ca["repetitions"][r], &rb = cb["repetitions"][r];
      for (const char* key : {"repetition", "status", "diverged_step", "mean_nodes", "mean_links",
                              "mean_interpolations", "operations", "final_state_hash"}) {
        EXPECT_EQ(ra[key], rb[key]) << "repetition " << r << " " << key;
      }
    }
  }
  ASSERT_EQ(a["table1"].size(), b["table1"].size());
  for (std::size_t i = 0; i < a["table1"].size(); ++i) {
    for (const char* key : {"operation", "N", "L", "count"}) EXPECT_EQ(a["table1"][i][key], b["table1"][i][key]);
  }
  ASSERT_EQ(a["table2"].size(), b["table2"].size());
  for (std::size_t i = 0; i < a["table2"].size(); ++i) {
    for (const char* key : {"method", "compression", "N", "L", "I", "node_ratio", "nets", "status"}) {
      EXPECT_EQ(a["table2"][i][key], b["table2"][i][key]) << key;
    }
  }
  ASSERT_EQ(a["scaling"]["step_ms_vs_nodes"].size(), b["scaling"]["step_ms_vs_nodes"].size());
  ASSERT_EQ(a.contains("fidelity"), b.contains("fidelity"));
  if (a.contains("fidelity")) {
    ASSERT_EQ(a["fidelity"]["cases"].size(), b["fidelity"]["cases"].size());
    for (std::size_t i = 0; i < a["fidelity"]["cases"].size(); ++i) {
      const json &fa = a["fidelity"]["cases"][i], &fb = b["fidelity"]["cases"][i];
      for (const char* key : {"net", "method", "compression", "target_nodes", "N", "status", "rms_pct", "max_pct",
                              "popping_pct", "energy_drift_pct", "converged_step", "final_state_hash"}) {
        EXPECT_EQ(fa[key], fb[key]) << "fidelity case " << i << " " << key;
      }
    }
    for (std::size_t i = 0; i < a["fidelity"]["rows"].size(); ++i) {
      EXPECT_EQ(a["fidelity"]["rows"][i]["rms_pct"], b["fidelity"]["rows"][i]["rms_pct"]);
      EXPECT_EQ(a["fidelity"]["rows"][i]["noise_floor_pct"], b["fidelity"]["rows"][i]["noise_floor_pct"]);
      EXPECT_EQ(a["fidelity"]["rows"][i]["interpolation_floor_pct"],
                b["fidelity"]["rows"][i]["interpolation_floor_pct"]);
    }
    // The floors per net (deterministic: the perturbation is seeded), in suite order; the reference's block times
    // are wall times, equal only in count.
    json floors_a = a["fidelity"]["floors"], floors_b = b["fidelity"]["floors"];
    for (json* floors : {&floors_a, &floors_b})
      for (json& f : *floors) f["reference_block_step_ms"] = f["reference_block_step_ms"].size();
    EXPECT_EQ(floors_a, floors_b);
    EXPECT_FALSE(a["fidelity"]["floors"].empty());
    EXPECT_EQ(a["max_compression"]["compression"], b["max_compression"]["compression"]);
  }
}

class Shards : public Cli {
 protected:
  json load(const std::string& file) const { return json::parse(read_file(dir_ / file)); }

  /// Every repetition of the merged result names the shard that measured it, one of 1..n, and the repetitions of
  /// one net in one repetition (its cases side by side) name the same one.
  void expect_processes_are_the_shards(const json& merged, int n) {
    std::map<std::string, int> process_of;  // "net#repetition"
    for (const json& c : merged["cases"]) {
      for (const json& r : c["repetitions"]) {
        ASSERT_TRUE(r.contains("process")) << c["label"];
        const int p = r["process"].get<int>();
        EXPECT_GE(p, 1);
        EXPECT_LE(p, n);
        const std::string key = c["net"].get<std::string>() + "#" + std::to_string(r["repetition"].get<int>());
        const auto [it, fresh] = process_of.try_emplace(key, p);
        if (!fresh) {
          EXPECT_EQ(it->second, p) << key;
        }
      }
    }
  }

  /// Runs every shard of `n` of `suite` (with `flags`, split by `split`) into shard_N_K.json and merges them into
  /// merged_N.json.
  void run_and_merge(const std::string& suite, int n, const std::string& flags,
                     const std::string& split = "repetitions") {
    std::string files;
    for (int k = 1; k <= n; ++k) {
      const std::string file = "shard_" + std::to_string(n) + "_" + std::to_string(k) + ".json";
      const Outcome o = tcsb("run " + suite + " --quiet " + flags + " --split " + split + " --shard " +
                             std::to_string(k) + "/" + std::to_string(n) + " --out " + file);
      ASSERT_EQ(o.exit_code, 0) << o.err;
      const json shard = load(file);
      EXPECT_EQ(shard["context"]["shard"], (json{{"k", k}, {"n", n}, {"split", split}}));
      files += " " + file;
    }
    // Given in reverse: the order of the files on the command line does not matter.
    std::string reversed;
    for (int k = n; k >= 1; --k) reversed += " shard_" + std::to_string(n) + "_" + std::to_string(k) + ".json";
    const Outcome m = tcsb("merge --quiet" + reversed + " --out merged_" + std::to_string(n) + ".json");
    ASSERT_EQ(m.exit_code, 0) << m.err;
    // The merged file is a result like any other: export reads it (and checks it against the schema).
    const Outcome e = tcsb("export merged_" + std::to_string(n) + ".json --format markdown");
    EXPECT_EQ(e.exit_code, 0) << e.err;
  }
};

TEST_F(Shards, MergedShardsOfTheCiSuiteEqualTheUnshardedRun) {
  // Two repetitions instead of nine keep the test short; every run here uses the same override, so the settings
  // agree, and the split and the merge do not depend on the repetition count.
  const std::string flags = "--repetitions 2";
  ASSERT_EQ(tcsb("run ci --quiet " + flags + " --out whole.json").exit_code, 0);
  const json whole = load("whole.json");
  // Under AddressSanitizer every run is several times slower: one split there, all four in the Release build.
  const std::vector<int> splits = kAddressSanitized ? std::vector<int>{3} : std::vector<int>{1, 2, 3, 7};
  for (const int n : splits) {
    SCOPED_TRACE("n = " + std::to_string(n));
    run_and_merge("ci", n, flags);
    const json merged = load("merged_" + std::to_string(n) + ".json");
    expect_same_deterministic_fields(whole, merged);
    EXPECT_EQ(merged["context"]["merged_shards"], n);
    EXPECT_FALSE(merged["context"].contains("shard"));
    EXPECT_FALSE(merged.contains("merge_data"));
    expect_processes_are_the_shards(merged, n);
  }
  // The unsharded run is one process: its repetitions name none.
  for (const json& c : whole["cases"])
    for (const json& r : c["repetitions"]) EXPECT_FALSE(r.contains("process"));
}

TEST_F(Shards, MergedShardsSplitByNetEqualTheUnshardedRunToo) {
  const std::string flags = "--repetitions 2";
  ASSERT_EQ(tcsb("run ci --quiet " + flags + " --out whole.json").exit_code, 0);
  run_and_merge("ci", 3, flags, "nets");
  const json merged = load("merged_3.json");
  expect_same_deterministic_fields(load("whole.json"), merged);
  expect_processes_are_the_shards(merged, 3);
}

TEST_F(Shards, AMergedCompliantRunKeepsItsConvergedReference) {
  // The fidelity pass of a compliant suite records how its reference's small steps were found; a merge rebuilds the
  // floors from the shards' JSON and must keep it.
  std::string suite = nine_by_nine_suite("c", 2);
  suite.replace(suite.find(R"("mass": {"total": 1.0},)"), std::string(R"("mass": {"total": 1.0},)").size(), "");
  suite.replace(suite.rfind('}'), 1,
                R"(, "tcsb": {"masses": "cut"}, "fidelity": {"enabled": true}, "material": {"model": "compliant",)"
                R"( "stretch_stiffness": 50, "density": 0.2, "substeps": 4}})");
  write_file(dir_ / "c.json", suite);
  ASSERT_EQ(tcsb("run c.json --quiet --out whole.json").exit_code, 0);
  run_and_merge("c.json", 2, "");
  const json whole = load("whole.json"), merged = load("merged_2.json");
  ASSERT_TRUE(whole["fidelity"]["floors"][0].contains("reference"));
  EXPECT_EQ(merged["fidelity"]["floors"][0]["reference"], whole["fidelity"]["floors"][0]["reference"]);
}

TEST_F(Shards, ASplitByRepetitionSpreadsEveryNetsRepetitionsWithAllItsCases) {
  // Three nets of two repetitions in three shards: the six (net, repetition) units go round the shards, each with
  // every case of its net, and no repetition is run twice.
  write_file(dir_ / "three.json", three_net_suite("three"));
  std::multiset<std::string> runs;  // "label#repetition"
  for (int k = 1; k <= 3; ++k) {
    std::string file = "r";
    file += std::to_string(k) + ".json";
    ASSERT_EQ(tcsb("run three.json --quiet --shard " + std::to_string(k) + "/3 --out " + file).exit_code, 0);
    const json shard = load(file);
    std::map<std::string, std::set<int>> repetitions_of_net;
    for (const json& c : shard["cases"]) {
      std::set<int> reps;
      for (const json& r : c["repetitions"]) {
        reps.insert(r["repetition"].get<int>());
        runs.insert(c["label"].get<std::string>() + "#" + std::to_string(r["repetition"].get<int>()));
      }
      const auto [it, fresh] = repetitions_of_net.try_emplace(c["net"].get<std::string>(), reps);
      if (!fresh) {
        EXPECT_EQ(it->second, reps) << "the cases of " << c["net"] << " differ in repetitions";
      }
    }
  }
  EXPECT_EQ(runs.size(), 18u);  // 3 nets x (plain, tcsb@1.0, tcsb@0.5) x 2 repetitions, each once
  EXPECT_EQ(std::set<std::string>(runs.begin(), runs.end()).size(), 18u);
}

TEST_F(Shards, ShardsSplitByNetAndCoverEveryCaseOnce) {
  write_file(dir_ / "three.json", three_net_suite("three"));
  std::multiset<std::string> labels;
  std::set<std::string> nets_with_cases;
  for (int k = 1; k <= 2; ++k) {
    std::string file = "s";  // (appended: GCC 12 warns falsely on "literal" + std::string&&)
    file += std::to_string(k) + ".json";
    ASSERT_EQ(tcsb("run three.json --quiet --split nets --shard " + std::to_string(k) + "/2 --out " + file).exit_code,
              0);
    std::set<std::string> nets;
    const json shard = load(file);  // named: a range-for over a temporary's member would dangle
    for (const json& c : shard["cases"]) {
      labels.insert(c["label"].get<std::string>());
      nets.insert(c["net"].get<std::string>());
    }
    for (const std::string& net : nets) EXPECT_TRUE(nets_with_cases.insert(net).second) << net << " in two shards";
  }
  EXPECT_EQ(labels.size(), 9u);  // 3 nets x (plain, tcsb@1.0, tcsb@0.5), each once
  EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()).size(), 9u);
  EXPECT_EQ(nets_with_cases.size(), 3u);
}

TEST_F(Shards, AnEmptyShardWritesAValidEmptyResultAndMerges) {
  write_file(dir_ / "three.json", three_net_suite("three"));
  ASSERT_EQ(tcsb("run three.json --quiet --out whole.json").exit_code, 0);
  run_and_merge("three.json", 5, "", "nets");  // five shards of three nets: two are empty
  int empty = 0;
  for (int k = 1; k <= 5; ++k) {
    const json shard = load("shard_5_" + std::to_string(k) + ".json");
    empty += shard["cases"].empty();
  }
  EXPECT_EQ(empty, 2);
  EXPECT_EQ(tcsb("export shard_5_5.json --format markdown").exit_code, 0);  // valid against the schema
  expect_same_deterministic_fields(load("whole.json"), load("merged_5.json"));
  run_and_merge("three.json", 7, "");  // seven shards of three nets' two repetitions: one is empty
  EXPECT_TRUE(load("shard_7_7.json")["cases"].empty());
  expect_same_deterministic_fields(load("whole.json"), load("merged_7.json"));
}

TEST_F(Shards, AFidelityPassIsShardedAndMergedToo) {
  write_file(dir_ / "fid.json", three_net_suite("fid", true));
  ASSERT_EQ(tcsb("run fid.json --quiet --out whole.json").exit_code, 0);
  run_and_merge("fid.json", 2, "");
  const json whole = load("whole.json");
  ASSERT_TRUE(whole.contains("fidelity"));
  expect_same_deterministic_fields(whole, load("merged_2.json"));
}

TEST_F(Shards, ShardsOfASuiteWithEveryMethodMerge) {
  // plain_equal was once missing from merge's list of methods, so shards of the scaling suite could not merge.
  write_file(dir_ / "all.json", three_net_suite("all", false, R"("plain", "bullet_patch", "tcsb", "plain_equal")"));
  ASSERT_EQ(tcsb("run all.json --quiet --out whole.json").exit_code, 0);
  run_and_merge("all.json", 2, "");
  expect_same_deterministic_fields(load("whole.json"), load("merged_2.json"));
}

TEST_F(Shards, BadShardIndicesAreRefusedNamingTheFlag) {
  write_file(dir_ / "three.json", three_net_suite("three"));
  for (const std::string bad : {"0/3", "4/3", "3", "1/0", "a/b", "1/3x", "-1/3", "1//3", "+1/3"}) {
    const Outcome o = tcsb("run three.json --quiet --shard '" + bad + "' --out x.json");
    EXPECT_EQ(o.exit_code, 2) << bad;
    EXPECT_EQ(count_lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("--shard"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.json"));
  }
  const Outcome other_format = tcsb("run three.json --quiet --shard 1/2 --format gbench");
  EXPECT_EQ(other_format.exit_code, 2);
  EXPECT_NE(other_format.err.find("--shard"), std::string::npos);
}

// A shard is checked against the machine's memory for its own nets only: under a limit the whole suite does not fit
// (its 1025 x 1025 net), the shard of the small net runs.
TEST_F(Shards, AShardOfSmallNetsRunsWhereTheWholeSuiteWouldNotFit) {
  if (kAddressSanitized) GTEST_SKIP() << "no sanitized process starts under ulimit -v (cli_fixture.h)";
  write_file(dir_ / "mixed.json", R"({"name": "mixed", "description": "a net too large for the limit and a small one",
  "nets": [{"name": "n9", "width": 9, "height": 9, "size": [2.0, 2.0], "elevation": 2.0, "mass": {"total": 1.0}},
           {"name": "n1025", "width": 1025, "height": 1025, "size": [8.0, 8.0], "elevation": 8.0,
            "mass": {"total": 1.0}}],
  "methods": ["plain"], "dt": 0.016666666666666666, "gravity": 9.81, "steps": 10, "warmup_steps": 2,
  "repetitions": 1, "seed": 1, "solver": {"piterations": 2}})");
  const std::string limited =
      "sh -c 'ulimit -v 150000; exec \"" + std::string(TCSB_BINARY) + "\" run mixed.json --quiet ";
  const Outcome whole = shell(limited + "--out whole.json'");
  EXPECT_EQ(whole.exit_code, 2) << whole.err;
  EXPECT_NE(whole.err.find("n1025"), std::string::npos) << whole.err;
  // The largest net goes to shard 1, so shard 2 of 2 holds n9 alone.
  const Outcome small = shell(limited + "--split nets --shard 2/2 --out small.json'");
  ASSERT_EQ(small.exit_code, 0) << small.err;
  const json shard = load("small.json");
  ASSERT_EQ(shard["cases"].size(), 1u);
  EXPECT_EQ(shard["cases"][0]["label"], "n9/plain");
}

class BadShardSets : public Shards {
 protected:
  void SetUp() override {
    Shards::SetUp();
    write_file(dir_ / "three.json", three_net_suite("three"));
    write_file(dir_ / "other.json", three_net_suite("other"));
    for (int k = 1; k <= 3; ++k) {
      const std::string shard = std::to_string(k) + "/3";
      ASSERT_EQ(tcsb("run three.json --quiet --shard " + shard + " --out s" + std::to_string(k) + ".json").exit_code,
                0);
    }
    ASSERT_EQ(tcsb("run other.json --quiet --shard 2/3 --out foreign2.json").exit_code, 0);
    ASSERT_EQ(tcsb("run three.json --quiet --shard 2/4 --out quarter2.json").exit_code, 0);
    ASSERT_EQ(tcsb("run three.json --quiet --split nets --shard 2/3 --out nets2.json").exit_code, 0);
    ASSERT_EQ(tcsb("run three.json --quiet --out whole.json").exit_code, 0);
  }

  /// `tcsb merge FILES --out merged.json` must exit 2 with one line naming `culprit`, and write nothing.
  void expect_refused(const std::string& files, const std::string& culprit) {
    const Outcome o = tcsb("merge " + files + " --out merged.json");
    EXPECT_EQ(o.exit_code, 2) << files << "\n" << o.err;
    EXPECT_EQ(count_lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find(culprit), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "merged.json")) << files;
  }
};

TEST_F(BadShardSets, TheGoodSetMerges) { EXPECT_EQ(tcsb("merge s1.json s2.json s3.json --quiet").exit_code, 0); }

// Timings are not deterministic, so the merged case must carry what its shards measured: its step breakdown is the
// median of its repetitions' parts, which the shards record per repetition (merge_data.breakdown_ms).
TEST_F(BadShardSets, TheMergedCasesStepBreakdownIsTheMedianOfItsRepetitionsParts) {
  ASSERT_EQ(tcsb("merge s1.json s2.json s3.json --quiet --out merged.json").exit_code, 0);
  const json merged = load("merged.json");
  std::map<std::string, std::vector<double>> bullet;  // by label, over every shard's repetitions
  for (const std::string file : {"s1.json", "s2.json", "s3.json"}) {
    const json shard = load(file);
    for (const auto& [label, parts] : shard["merge_data"]["breakdown_ms"].items())
      for (const json& p : parts) bullet[label].push_back(p[0].get<double>());
  }
  for (const json& m : merged["cases"]) {
    std::vector<double> values = bullet[m["label"].get<std::string>()];
    ASSERT_EQ(values.size(), 2u) << m["label"];  // two repetitions, wherever they ran
    EXPECT_NEAR(m["step_breakdown_ms"]["bullet"].get<double>(), (values[0] + values[1]) / 2, 1e-12) << m["label"];
    EXPECT_GT(m["step_breakdown_ms"]["bullet"].get<double>(), 0) << m["label"];
  }
}

TEST_F(BadShardSets, AMissingShardIsRefused) {
  expect_refused("s1.json s3.json", "shard 2/3 is missing");
  expect_refused("s1.json s3.json", "s1.json");
}

TEST_F(BadShardSets, TheSameShardTwiceIsRefused) {
  expect_refused("s1.json s2.json s2.json s3.json", "given twice");
  fs::copy_file(dir_ / "s2.json", dir_ / "copy2.json");
  expect_refused("s1.json s2.json copy2.json s3.json", "copy2.json");
}

TEST_F(BadShardSets, ShardsOfTwoSuitesAreRefused) { expect_refused("s1.json foreign2.json s3.json", "foreign2.json"); }

TEST_F(BadShardSets, ShardsOfTwoSplitsAreRefused) {
  expect_refused("s1.json quarter2.json s3.json", "quarter2.json");
  // The same k/n split by net: its repetitions are not the ones shard 2/3 by repetition has.
  expect_refused("s1.json nets2.json s3.json", "nets2.json: context.shard.split");
}

TEST_F(BadShardSets, ARepetitionMissingOrGivenTwiceIsRefused) {
  // Shard 2's repetition renumbered as another's: one repetition would be missing from the merge, another twice.
  json shard = load("s2.json");
  ASSERT_FALSE(shard["cases"].empty());
  json& first = shard["cases"][0]["repetitions"][0];
  first["repetition"] = 1 - first["repetition"].get<int>();
  write_file(dir_ / "renumbered2.json", shard.dump());
  expect_refused("s1.json renumbered2.json s3.json", "renumbered2.json: cases[0].repetitions");
}

TEST_F(BadShardSets, ATruncatedShardIsRefused) {
  const std::string text = read_file(dir_ / "s2.json");
  write_file(dir_ / "cut2.json", text.substr(0, text.size() / 2));
  expect_refused("s1.json cut2.json s3.json", "cut2.json");
}

TEST_F(BadShardSets, AnUnshardedResultIsRefused) { expect_refused("s1.json whole.json s3.json", "whole.json"); }

TEST_F(BadShardSets, AShardWithEditedCasesIsRefused) {
  json shard = json::parse(read_file(dir_ / "s1.json"));
  shard["cases"].erase(shard["cases"].begin());  // still valid against the schema, but not shard 1's cases
  write_file(dir_ / "edited1.json", shard.dump());
  expect_refused("edited1.json s2.json s3.json", "edited1.json");
}

TEST_F(BadShardSets, AShardNoRunCouldWriteIsRefusedAsStrictlyAsCompareRefusesAResult) {
  // A repetition deleted, a negative operation time, a node count that is not the net's: each once merged and
  // rendered (Table 1 with a negative complete_ms).
  json shard = load("s1.json");
  shard["cases"][0]["repetitions"].erase(0);
  write_file(dir_ / "fewer1.json", shard.dump());
  expect_refused("fewer1.json s2.json s3.json", "fewer1.json: cases[0].repetitions");
  shard = load("s1.json");
  shard["cases"][0]["net_nodes"] = 66049;
  write_file(dir_ / "nodes1.json", shard.dump());
  expect_refused("nodes1.json s2.json s3.json", "nodes1.json: cases[0].net_nodes: 66049, but net");
  for (const std::string file : {"s1.json", "s2.json", "s3.json"}) {
    shard = load(file);
    for (auto& [label, columns] : shard["merge_data"]["op_samples"].items()) {
      if (columns["node_ns"].empty()) continue;
      columns["node_ns"][0] = -1000000;
      write_file(dir_ / "negative.json", shard.dump());
      const std::string others = file == "s1.json"   ? "s2.json s3.json"
                                 : file == "s2.json" ? "s1.json s3.json"
                                                     : "s1.json s2.json";
      expect_refused("negative.json " + others, "negative.json: merge_data.op_samples." + label);
      return;
    }
  }
  ADD_FAILURE() << "no shard recorded an operation";
}

TEST_F(BadShardSets, AShardWithAWallTimeNoRunTookIsRefused) {
  // Issue 60: a negative wall_s was summed into the merged result's; null is how a result writes a non-finite one.
  for (const json& wall : {json(-5.0), json(nullptr)}) {
    SCOPED_TRACE(wall.dump());
    json shard = load("s2.json");
    shard["wall_s"] = wall;
    write_file(dir_ / "wall2.json", shard.dump());
    expect_refused("s1.json wall2.json s3.json", "wall2.json: wall_s");
  }
  json shard = load("s2.json");
  if (shard.contains("fidelity") && shard["fidelity"].is_object()) {
    shard["fidelity"]["wall_s"] = -1.0;
    write_file(dir_ / "fwall2.json", shard.dump());
    expect_refused("s1.json fwall2.json s3.json", "fwall2.json: fidelity.wall_s");
  }
}

TEST_F(BadShardSets, ShardsOfTwoBuildsAreRefused) {
  json shard = json::parse(read_file(dir_ / "s3.json"));
  shard["context"]["git_commit"] = "0000000000000000000000000000000000000000";
  write_file(dir_ / "build3.json", shard.dump());
  expect_refused("s1.json s2.json build3.json", "build3.json");
}

TEST_F(BadShardSets, ShardsOfDifferentMachinesMergeWithAWarning) {
  json shard = json::parse(read_file(dir_ / "s2.json"));
  shard["context"]["host"] = "another-node";
  write_file(dir_ / "elsewhere2.json", shard.dump());
  const Outcome o = tcsb("merge --quiet s1.json elsewhere2.json s3.json --out merged.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("tcsb: warning: shards ran on different machines"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("another-node"), std::string::npos) << o.err;
  bool recorded = false;
  const json merged = load("merged.json");
  for (const json& w : merged["context"]["warnings"]) {
    recorded = recorded || w.get<std::string>().find("different machines") != std::string::npos;
  }
  EXPECT_TRUE(recorded);
  // Without the edit: one machine, no such warning.
  const Outcome same = tcsb("merge --quiet s1.json s2.json s3.json");
  EXPECT_EQ(same.err.find("different machines"), std::string::npos) << same.err;
}

TEST_F(BadShardSets, AnExistingOutputIsLeftAloneWhenRefused) {
  write_file(dir_ / "merged.json", "keep");
  const Outcome o = tcsb("merge s1.json s3.json --out merged.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(read_file(dir_ / "merged.json"), "keep");
}

}  // namespace
}  // namespace tcsb::cli_test
