// A scene of many bodies end to end through the executable: its run writes the world pass's block, which the
// result's schema takes, and a bad scene exits 2 with one line naming the field; its frames are the world pass's
// (the fly-by), and what they cannot be asked for exits 2 with one line naming the option. A longer geomorph shows the
// same operations with smaller jumps.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../world/world_suite_json.h"
#include "cli_fixture.h"

namespace tcsb::cli_test {
namespace {

using json = nlohmann::json;

TEST_F(Cli, AWorldSuiteWritesTheWorldPass) {
  write_file(dir_ / "row.json", testing::world_suite_json().dump());
  const Outcome o = tcsb("run row.json --out result.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("World pass: 3 bodies"), std::string::npos) << o.err;  // the console's table
  EXPECT_NE(o.err.find("discrete_lod"), std::string::npos) << o.err;
  const json doc = json::parse(read_file(dir_ / "result.json"));
  EXPECT_EQ(doc["suite"]["scene"]["bodies"], 3);
  EXPECT_EQ(doc["suite"]["feedback"]["budget_scope"], "world");
  ASSERT_EQ(doc["world"]["methods"].size(), 4u);
  EXPECT_EQ(doc["world"]["methods"][0]["method"], "full_resolution");
  const Outcome read = tcsb("export result.json --format markdown");  // read back through the schema
  EXPECT_EQ(read.exit_code, 0) << read.err;
}

TEST_F(Cli, ALongerGeomorphSpreadsTheSameOperationsJumpsOverMoreBoundaries) {
  json suite = testing::world_suite_json();
  write_file(dir_ / "blend.json", suite.dump());
  suite["fidelity"]["geomorph_boundaries"] = 24;
  write_file(dir_ / "long.json", suite.dump());
  ASSERT_EQ(tcsb("run blend.json --out blend-result.json").exit_code, 0);
  const Outcome o = tcsb("run long.json --out long-result.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const json blend = json::parse(read_file(dir_ / "blend-result.json"));
  const json longer = json::parse(read_file(dir_ / "long-result.json"));
  EXPECT_FALSE(blend["world"].contains("geomorph_boundaries"));
  EXPECT_EQ(longer["world"]["geomorph_boundaries"], 24);
  for (std::size_t m = 1; m < blend["world"]["methods"].size(); ++m) {
    const json& a = blend["world"]["methods"][m];
    const json& b = longer["world"]["methods"][m];
    EXPECT_EQ(a["mean_nodes"], b["mean_nodes"]) << a["method"] << ": the morph is shown, never simulated";
    if (a["method"] != "tcsb_world" && a["method"] != "tcsb_body") continue;
    EXPECT_GT(a["popping_px"].get<double>(), 0.0) << a["method"];
    EXPECT_LT(b["popping_px"].get<double>(), a["popping_px"].get<double>()) << a["method"];
  }
  EXPECT_EQ(tcsb("export long-result.json --format markdown").exit_code, 0);  // read back through the schema
}

TEST_F(Cli, AWorldSuiteWithCurvesWritesItsSpeedUpAtEqualError) {
  json j = testing::world_suite_json();
  j["fidelity"] = {{"curves", {{"budgets", {0.25}}, {"solver_divisors", {2}}}}};
  write_file(dir_ / "row.json", j.dump());
  const Outcome o = tcsb("run row.json --out result.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("World pass, speed-up at equal error"), std::string::npos) << o.err;
  const json doc = json::parse(read_file(dir_ / "result.json"));
  // The reference, three methods at each of 0.25 and the suite's 0.5, the noise floor and full resolution at half
  // the passes.
  const json& methods = doc["world"]["methods"];
  ASSERT_EQ(methods.size(), 9u);
  EXPECT_EQ(methods[1]["budget"], 0.25);
  EXPECT_EQ(methods[7]["method"], "noise_floor");
  EXPECT_EQ(methods[8]["solver_divisor"], 2);
  const json& equal_error = doc["world"]["equal_error"];
  EXPECT_TRUE(equal_error["scene"]["missing"].is_null()) << equal_error["scene"]["missing"];
  ASSERT_EQ(equal_error["scene"]["rows"].size(), 2u);
  EXPECT_TRUE(equal_error["scene"]["rows"][0]["discrete_lod"]["status"].is_string());
  ASSERT_EQ(equal_error["same_nodes"].size(), 2u);
  const Outcome read = tcsb("export result.json --format markdown");  // read back through the schema
  ASSERT_EQ(read.exit_code, 0) << read.err;
  EXPECT_NE(read.out.find("Many bodies: speed-up at equal error"), std::string::npos);
}

class WorldCli : public Cli {
 protected:
  /// `tcsb run` of the suite refuses it: exit 2, one line naming `field`, no result written.
  void expect_run_refused(const json& suite, const std::string& field) {
    write_file(dir_ / "row.json", suite.dump());
    const Outcome o = tcsb("run row.json --quiet --out result.json");
    EXPECT_EQ(o.exit_code, 2);
    EXPECT_EQ(count_lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find(field), std::string::npos) << o.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "result.json"));
  }
};

TEST_F(WorldCli, AWorldCurveBudgetOfEveryNodeExitsTwoNamingTheField) {
  json j = testing::world_suite_json();
  j["fidelity"] = {{"curves", {{"budgets", {0.25, 1.0}}, {"solver_divisors", {2}}}}};
  expect_run_refused(j, "fidelity.curves.budgets[1]");
}

TEST_F(WorldCli, OverlappingBodiesExitTwoNamingTheField) {
  json j = testing::world_suite_json();
  j["scene"]["bodies"][1]["position"] = {-2.5, 2.0, 0.0};
  expect_run_refused(j, "scene.bodies[1].position");
}

TEST_F(Cli, AWorldSuitesFramesAreTheWorldPasssEveryKthStep) {
  write_file(dir_ / "row.json", testing::world_suite_json().dump());
  const Outcome o = tcsb("frames --suite row.json --compression 0.3 --every 15 --out frames.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const json doc = json::parse(read_file(dir_ / "frames.json"));
  EXPECT_EQ(doc["kind"], "world_frames");
  EXPECT_EQ(doc["compression"], 0.3);
  ASSERT_EQ(doc["bodies"].size(), 3u);
  ASSERT_EQ(doc["methods"].size(), 2u);
  EXPECT_EQ(doc["methods"][0]["method"], "tcsb_world");
  EXPECT_EQ(doc["methods"][1]["method"], "discrete_lod");
  ASSERT_EQ(doc["frames"].size(), 5u);  // steps 0, 15, 30, 45, 60 of 20 warm-up and 40 measured
  EXPECT_EQ(doc["frames"][4]["step"], 60);
  for (const json& frame : doc["frames"]) {
    EXPECT_EQ(frame["camera"]["position"].size(), 3u);
    ASSERT_EQ(frame["scenes"].size(), 2u);
    for (const json& scene : frame["scenes"]) {
      ASSERT_EQ(scene["bodies"].size(), 3u);
      for (const json& body : scene["bodies"]) {
        EXPECT_EQ(body["xyz"].size(), 3u * 81u);
        EXPECT_EQ(body["levels"].size(), 81u);
      }
    }
  }
  const Outcome read = tcsb("compare frames.json frames.json");  // not a run result
  EXPECT_EQ(read.exit_code, 2) << read.err;
}

TEST_F(Cli, AWorldSuitesFramesRefuseWhatTheyCannotHoldInOneLine) {
  write_file(dir_ / "row.json", testing::world_suite_json().dump());
  for (const auto& [flags, needle] :
       std::vector<std::pair<std::string, std::string>>{{"--net b9", "--net"},
                                                        {"--calibrated", "--calibrated"},
                                                        {"--compression 1", "--compression"},
                                                        {"--steps 0,61", "ends after 60 steps"},
                                                        {"--every 0", "--every"},
                                                        {"--every 5 --steps 5", "--every"}}) {
    const Outcome o = tcsb("frames --suite row.json --out frames.json " + flags);
    EXPECT_EQ(o.exit_code, 2) << flags << ": " << o.err;
    EXPECT_EQ(count_lines(o.err), 1) << flags << ": " << o.err;
    EXPECT_NE(o.err.find(needle), std::string::npos) << flags << ": " << o.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "frames.json")) << flags;
  }
}

}  // namespace
}  // namespace tcsb::cli_test
