// A suite with a scene, end to end through the executable: every method and the fidelity pass step in a world with a
// collider, each repetition reports its penetrations, and what run writes every reader takes; a suite without a
// scene writes no scene fields at all.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"

namespace tcsb::cli_test {
namespace {

using json = nlohmann::json;

const char* kSceneSuite = R"({
  "name": "scene", "description": "a 9x9 sheet dropped onto a sphere, for the CLI tests",
  "nets": [{"name": "s9", "width": 9, "height": 9, "size": [2.0, 2.0], "elevation": 0.7, "mass": {"total": 0.5},
            "pinned": "none"}],
  "methods": ["plain", "tcsb", "plain_equal"], "compression": [1.0, 0.5],
  "dt": 0.016666666666666666, "gravity": 9.81, "steps": 30, "warmup_steps": 5, "repetitions": 1, "seed": 1,
  "interleave_steps": 4,
  "solver": {"piterations": 4},
  "feedback": {"contact_saliency": 1.0},
  "fidelity": {"enabled": true, "ablations": true},
  "scene": {"colliders": [{"shape": "sphere", "radius": 0.5}, {"shape": "plane", "position": [0, -1, 0]}],
            "margin": 0.01, "sdf_voxel": 0.05}
})";

TEST_F(Cli, ASceneSuiteRunsEveryMethodInItsWorldAndCountsPenetrations) {
  write_file(dir_ / "scene.json", kSceneSuite);
  const Outcome o = tcsb("run scene.json --out result.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("deepest %"), std::string::npos) << o.err;  // the console's contact columns
  EXPECT_NE(o.err.find("contacts"), std::string::npos) << o.err;
  const json doc = json::parse(read_file(dir_ / "result.json"));
  EXPECT_EQ(doc["suite"]["scene"]["colliders"], json::array({"static sphere", "static plane"}));
  EXPECT_FALSE(doc["suite"]["scene"].contains("collisions"));  // Bullet's default, SDF_RS: as results before it
  EXPECT_EQ(doc["suite"]["feedback"]["contact_saliency"], 1.0);
  ASSERT_EQ(doc["cases"].size(), 4u);  // plain, tcsb at 1.0 and 0.5, plain_equal at 0.5
  for (const json& c : doc["cases"]) {
    EXPECT_EQ(c["status"], "ok") << c["label"];
    for (const json& r : c["repetitions"]) {
      ASSERT_TRUE(r.contains("penetrations")) << c["label"];
      EXPECT_GE(r["penetrations"]["node_steps"].get<long long>(), 0);
      EXPECT_GE(r["penetrations"]["deepest_pct"].get<double>(), 0.0);
      // Every body reaches the sphere within the run (it falls 0.2 m, 12 steps): Bullet holds some nodes on it.
      EXPECT_GT(r["penetrations"]["mean_contacts"].get<double>(), 0.0) << c["label"];
    }
  }
  ASSERT_TRUE(doc.contains("fidelity"));
  // What run wrote, the readers take (each checks it against the result schema first).
  for (const char* format : {"markdown", "gbench", "github-action-smaller"})
    EXPECT_EQ(tcsb(std::string("export result.json --format ") + format).exit_code, 0) << format;
}

TEST_F(Cli, WithoutRigidContactNoBodyTouchesTheSphereAndTheResultSaysSo) {
  json suite = json::parse(kSceneSuite);
  suite["scene"]["collisions"] = json::array();
  suite["fidelity"]["enabled"] = false;
  write_file(dir_ / "scene.json", suite.dump());
  const Outcome o = tcsb("run scene.json --out result.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const json doc = json::parse(read_file(dir_ / "result.json"));
  EXPECT_EQ(doc["suite"]["scene"]["collisions"], json::array());
  for (const json& c : doc["cases"])
    for (const json& r : c["repetitions"]) {
      EXPECT_EQ(r["penetrations"]["mean_contacts"].get<double>(), 0.0) << c["label"];
      EXPECT_GT(r["penetrations"]["node_steps"].get<long long>(), 0) << c["label"];  // it falls through the sphere
    }
  EXPECT_EQ(tcsb("export result.json --format markdown").exit_code, 0);  // the reader takes it (schema first)
}

TEST_F(Cli, ASuiteWithoutASceneWritesNoSceneFields) {
  run_small_suite(1);
  const json doc = json::parse(read_file(dir_ / "result.json"));
  EXPECT_FALSE(doc["suite"].contains("scene"));
  EXPECT_FALSE(doc["suite"]["feedback"].contains("contact_saliency"));
  for (const json& c : doc["cases"])
    for (const json& r : c["repetitions"]) EXPECT_FALSE(r.contains("penetrations")) << c["label"];
}

}  // namespace
}  // namespace tcsb::cli_test
