// Calibration files on the command line: a suite cannot steer where `tcsb calibrate` writes (nor where a run reads)
// outside its own directory tree, no command's --out may replace a file it reads (the suite's calibration
// included), a calibration that fits no level is refused, and shards of a calibrated suite merge wherever they lie.
#include <nlohmann/json.hpp>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace tcsb::cli_test;
using ojson = nlohmann::ordered_json;

/// The 9 x 9 suite with a fidelity pass whose calibration is `calibration`.
std::string calibrated_suite(const std::string& name, const std::string& calibration) {
  std::string suite = nine_by_nine_suite(name, 1);
  suite.replace(suite.rfind('}'), 1,
                ", \"fidelity\": {\"enabled\": true, \"calibration\": " + ojson(calibration).dump() + "}}");
  return suite;
}

class Calibration : public Cli {
 protected:
  /// s.json (no calibration), its fitted s.calibration.json, and with.json naming it.
  void make_calibration() {
    write_file(dir_ / "s.json", nine_by_nine_suite("s", 1));
    const Outcome made = tcsb("calibrate s.json --quiet");
    ASSERT_EQ(made.exit_code, 0) << made.err;
    write_file(dir_ / "with.json", calibrated_suite("s", "s.calibration.json"));
  }

  static void expect_bad_input(const Outcome& o, const std::string& expected) {
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_EQ(count_lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find(expected), std::string::npos) << o.err;
  }
};

TEST_F(Calibration, APathLeavingTheSuitesTreeIsRefusedAndNothingIsOverwritten) {
  fs::create_directories(dir_ / "sub");
  write_file(dir_ / "victim.txt", "keep");
  fs::create_directory_symlink("..", dir_ / "sub" / "up");
  const std::string absolute = (dir_ / "victim.txt").string();
  for (const std::string& named : {std::string("../victim.txt"), absolute, std::string("up/victim.txt")}) {
    SCOPED_TRACE(named);
    write_file(dir_ / "sub" / "s.json", calibrated_suite("s", named));
    expect_bad_input(tcsb("calibrate sub/s.json --quiet"), "sub/s.json: fidelity.calibration");
    EXPECT_EQ(read_file(dir_ / "victim.txt"), "keep");
    expect_bad_input(tcsb("validate sub/s.json"), "fidelity.calibration");
    expect_bad_input(tcsb("run sub/s.json --quiet --out r.json"), "fidelity.calibration");
    EXPECT_FALSE(fs::exists(dir_ / "r.json"));
  }
  // Inside the tree, a subdirectory is fine.
  fs::create_directories(dir_ / "sub" / "cal");
  write_file(dir_ / "sub" / "s.json", calibrated_suite("s", "cal/s.calibration.json"));
  const Outcome inside = tcsb("calibrate sub/s.json --quiet");
  EXPECT_EQ(inside.exit_code, 0) << inside.err;
  EXPECT_TRUE(fs::exists(dir_ / "sub" / "cal" / "s.calibration.json"));
}

TEST_F(Calibration, NoCommandsOutMayReplaceTheSuiteOrItsCalibration) {
  make_calibration();
  const std::string suite = read_file(dir_ / "with.json");
  const std::string calibration = read_file(dir_ / "s.calibration.json");
  for (const std::string& line :
       {std::string("calibrate with.json --quiet --out with.json"), std::string("calibrate s.json --out s.json"),
        std::string("run with.json --quiet --out s.calibration.json"),
        std::string("frames --suite with.json --calibrated --steps 2 --out s.calibration.json"),
        std::string("reproduce --suite with.json --quiet --out ./s.calibration.json"),
        std::string("merge shard.json --quiet --out s.calibration.json")}) {
    SCOPED_TRACE(line);
    if (line.starts_with("merge")) {
      ASSERT_EQ(tcsb("run with.json --quiet --shard 1/1 --out shard.json").exit_code, 0);
    }
    const Outcome o = tcsb(line);
    expect_bad_input(o, "is the input file");
    EXPECT_EQ(read_file(dir_ / "with.json"), suite);
    EXPECT_EQ(read_file(dir_ / "s.calibration.json"), calibration);
  }
}

TEST_F(Calibration, ACalibrationWithoutTheLevelsTheNetsNeedIsRefused) {
  make_calibration();
  ojson calibration = ojson::parse(read_file(dir_ / "s.calibration.json"));
  ASSERT_GE(calibration["levels"].size(), 1u);
  calibration["levels"] = ojson::array();
  write_file(dir_ / "s.calibration.json", calibration.dump(2));
  expect_bad_input(tcsb("validate with.json"), "with.json: fidelity.calibration");
  expect_bad_input(tcsb("run with.json --quiet --out r.json"), "\"levels\": []");
  EXPECT_FALSE(fs::exists(dir_ / "r.json"));
  // Nor does calibrate write one: a net under 9 x 9 has no level to fit.
  std::string tiny = nine_by_nine_suite("tiny", 1);
  tiny.replace(tiny.find("\"width\": 9, \"height\": 9"), 23, "\"width\": 8, \"height\": 8");
  write_file(dir_ / "tiny.json", tiny);
  expect_bad_input(tcsb("calibrate tiny.json --quiet"), "tiny.json: nets");
  EXPECT_FALSE(fs::exists(dir_ / "tiny.calibration.json"));
}

TEST_F(Calibration, ShardsOfACalibratedSuiteMergeWhereverTheyLie) {
  make_calibration();
  fs::create_directories(dir_ / "shards");
  for (const char* k : {"1", "2"}) {
    const Outcome o = tcsb(std::string("run with.json --quiet --shard ") + k + "/2 --out shards/" + k + ".json");
    ASSERT_EQ(o.exit_code, 0) << o.err;
  }
  // Looked up beside the suite, not the shards: a stale file of that name beside them is not read.
  write_file(dir_ / "shards" / "s.calibration.json", "stale");
  const Outcome merged = tcsb("merge shards/1.json shards/2.json --quiet --out merged.json");
  EXPECT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_NE(read_file(dir_ / "merged.json").find("\"tcsb_calibrated\""), std::string::npos);
}

TEST_F(Calibration, ACompliantSuiteIsNotCalibrated) {
  // One material at every level: nothing to fit, and a fit would make it two.
  std::string suite = nine_by_nine_suite("c", 1);
  suite.replace(suite.find(R"("mass": {"total": 1.0},)"), std::string(R"("mass": {"total": 1.0},)").size(), "");
  suite.replace(
      suite.rfind('}'), 1,
      R"(, "tcsb": {"masses": "cut"}, "material": {"model": "compliant", "stretch_stiffness": 50, "density": 0.2,)"
      R"( "substeps": 4}})");
  write_file(dir_ / "c.json", suite);
  expect_bad_input(tcsb("calibrate c.json --quiet"), "material.model");
  EXPECT_FALSE(fs::exists(dir_ / "c.calibration.json"));
  // It runs, with its fidelity pass, and what it writes is a result the schema accepts (export checks it).
  write_file(dir_ / "f.json", suite.replace(suite.rfind('}'), 1, R"(, "fidelity": {"enabled": true}})"));
  const Outcome run = tcsb("run f.json --quiet --out out.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Outcome exported = tcsb("export out.json --format markdown --out out.md");
  EXPECT_EQ(exported.exit_code, 0) << exported.err;
}

}  // namespace
