// Parsers that cannot be crashed or hung, through the real binary: every JSON input (a suite, a result, the paper's
// numbers) is refused with exit 2 and one line naming the file when it is nested too deeply, too large, followed by
// anything but whitespace, holds a number no double can (1e309), or is not a regular file (a directory, a FIFO,
// /dev/zero). Each command runs under `timeout` and a memory limit, so a regression fails instead of hanging CI or
// exhausting the machine.
#include <sys/stat.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "cli_fixture.h"

namespace {

using namespace tcsb::cli_test;

class Input : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    run_small_suite(1);
    write_file(dir_ / "paper.json", read_file(fs::path(TCSB_SOURCE_DIR) / "results/paper.json"));
  }

  /// `tcsb ARGS` under a 20 s timeout (exit 124 when it hangs) and a 2 GiB address-space limit (not for a sanitized
  /// binary, which cannot start under one: cli_fixture.h; the timeout still bounds it).
  Outcome bounded(const std::string& args) const {
    const std::string limit = kAddressSanitized ? "" : "ulimit -v 2097152; ";
    return shell("( " + limit + "timeout 20 '" + std::string(TCSB_BINARY) + "' " + args + " )");
  }

  /// Every command that reads `file` in its role (suite, result, paper) refuses it: exit 2, one line naming it,
  /// containing `problem`.
  void expect_refused_everywhere(const std::string& file, const std::string& problem) const {
    const std::vector<std::string> commands{"validate " + file,
                                            "run " + file + " --quiet --out out.json",
                                            "export " + file + " --format gbench",
                                            "compare " + file + " result.json",
                                            "compare result.json " + file,
                                            "reproduce --suite small.json --paper " + file + " --quiet --out out.json"};
    for (const std::string& args : commands) {
      const Outcome o = bounded(args);
      EXPECT_EQ(o.exit_code, 2) << args << "\n" << o.err;
      EXPECT_EQ(count_lines(o.err), 1) << args << "\n" << o.err;
      EXPECT_EQ(o.err.rfind("tcsb: error: " + file + ": ", 0), 0u) << args << "\n" << o.err;
      EXPECT_NE(o.err.find(problem), std::string::npos) << args << "\n" << o.err;
      EXPECT_FALSE(fs::exists(dir_ / "out.json")) << args;
    }
  }
};

TEST_F(Input, DeepNestingIsRefusedNotAStackOverflow) {
  write_file(dir_ / "deep.json", std::string(100000, '[') + std::string(100000, ']'));
  expect_refused_everywhere("deep.json", "nested deeper than 64 levels");
  write_file(dir_ / "deep_open.json", std::string(100000, '['));
  expect_refused_everywhere("deep_open.json", "nested deeper than 64 levels");
  // Deep inside a member the result schema leaves open ("fidelity"), the old reader accepted the file, and
  // rendering it recursed without bound (export --format json never finished).
  nlohmann::ordered_json result = nlohmann::ordered_json::parse(read_file(dir_ / "result.json"));
  result["fidelity"] = "PLACEHOLDER";
  std::string text = result.dump();
  text.replace(text.find("\"PLACEHOLDER\""), 13, std::string(100000, '[') + std::string(100000, ']'));
  write_file(dir_ / "deep_member.json", text);
  for (const std::string args : {"export deep_member.json --format json", "compare result.json deep_member.json"}) {
    const Outcome o = bounded(args);
    EXPECT_EQ(o.exit_code, 2) << args << "\n" << o.err;
    EXPECT_EQ(o.err, "tcsb: error: deep_member.json: not valid JSON: arrays and objects nested deeper than 64 levels, "
                     "the most tcsb reads\n")
        << args;
  }
}

TEST_F(Input, ANulByteAndGarbageAfterTheDocumentAreRefused) {
  const std::string garbage = std::string(1, '\0') + "garbage";
  write_file(dir_ / "suite_nul.json", kSmallSuite + garbage);
  write_file(dir_ / "result_nul.json", read_file(dir_ / "result.json") + garbage);
  write_file(dir_ / "paper_nul.json", read_file(dir_ / "paper.json") + garbage);
  for (const auto& [args, file] : {std::pair<std::string, std::string>{"validate suite_nul.json", "suite_nul.json"},
                                   {"export result_nul.json --format gbench", "result_nul.json"},
                                   {"compare result.json result_nul.json", "result_nul.json"},
                                   {"reproduce --suite small.json --paper paper_nul.json --quiet", "paper_nul.json"}}) {
    const Outcome o = bounded(args);
    EXPECT_EQ(o.exit_code, 2) << args << "\n" << o.err;
    EXPECT_EQ(o.err, "tcsb: error: " + file + ": not valid JSON: a NUL byte at byte " +
                         std::to_string(read_file(dir_ / file).size() - garbage.size() + 1) + "\n")
        << args;
  }
  // Trailing text without the NUL is refused by the parser itself.
  write_file(dir_ / "result_text.json", read_file(dir_ / "result.json") + " x");
  const Outcome o = bounded("export result_text.json --format gbench");
  EXPECT_EQ(o.exit_code, 2) << o.err;
}

TEST_F(Input, ANumberTooLargeForADoubleIsBadInputNamingTheField) {
  const std::string result = read_file(dir_ / "result.json");
  write_file(dir_ / "huge.json", std::regex_replace(result, std::regex("\"gravity\": [0-9.]+"), "\"gravity\": 1e309",
                                                    std::regex_constants::format_first_only));
  ASSERT_NE(read_file(dir_ / "huge.json"), result);
  for (const std::string args : {"export huge.json --format gbench", "compare result.json huge.json"}) {
    const Outcome o = bounded(args);
    EXPECT_EQ(o.exit_code, 2) << args << "\n" << o.err;
    EXPECT_EQ(o.err, "tcsb: error: huge.json: suite.gravity: not valid JSON: number overflow parsing '1e309'\n")
        << args;
  }
  const std::string paper = read_file(dir_ / "paper.json");
  write_file(dir_ / "paper_huge.json",
             std::regex_replace(paper, std::regex("\"total_ms\": [0-9.]+"), "\"total_ms\": -1e999",
                                std::regex_constants::format_first_only));
  const Outcome o = bounded("reproduce --suite small.json --paper paper_huge.json --quiet");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("paper_huge.json: table2.rows[0].total_ms: not valid JSON: number overflow"), std::string::npos)
      << o.err;
}

TEST_F(Input, ADirectoryIsRefused) {
  fs::create_directories(dir_ / "dir.json");
  expect_refused_everywhere("dir.json", "it is a directory");
}

TEST_F(Input, AFifoIsRefusedWithoutHanging) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo.json").c_str(), 0600), 0);
  expect_refused_everywhere("fifo.json", "it is a pipe, not a regular file");
}

TEST_F(Input, AnEndlessDeviceIsRefusedWithoutReadingIt) {
  expect_refused_everywhere("/dev/zero", "not a regular file");
}

TEST_F(Input, AFileLargerThanTheLimitIsRefusedUnread) {
  // A valid suite padded past 16 MiB with whitespace: refused by size, before parsing.
  write_file(dir_ / "padded.json", std::string((16 << 20) + 1, ' ') + kSmallSuite);
  const Outcome o = bounded("validate padded.json");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(o.err, "tcsb: error: padded.json: cannot read the file: larger than 16 MiB, the most tcsb reads\n");
}

TEST_F(Input, ADuplicateKeyInAResultIsRefused) {
  const std::string result = read_file(dir_ / "result.json");
  const std::size_t tool = result.find("\"tool\": \"tcsb\"");
  ASSERT_NE(tool, std::string::npos);
  write_file(dir_ / "dup.json", result.substr(0, tool) + "\"tool\": \"tcsb\", " + result.substr(tool));
  const Outcome o = bounded("export dup.json --format gbench");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(o.err, "tcsb: error: dup.json: tool: duplicate key (each key may appear once)\n");
}

}  // namespace
