// Running the real tcsb executable in a fresh temporary directory per test, capturing exit code, stdout and
// stderr: what every CLI test needs.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace tcsb::cli_test {

namespace fs = std::filesystem;

/// Whether the executable under test is built with AddressSanitizer (the whole tree is, tests included). ASan
/// reserves terabytes of shadow address space at start-up, so a sanitized process cannot start under `ulimit -v`:
/// tests that need an address-space limit run in the Release build only.
#ifdef __SANITIZE_ADDRESS__
inline constexpr bool kAddressSanitized = true;
#else
inline constexpr bool kAddressSanitized = false;
#endif

/// What one run of the executable did.
struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

/// A whole file as bytes ("" if it cannot be read).
inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Writes `text` to `p`, replacing it.
inline void write_file(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

/// Newlines in `text`.
inline int count_lines(const std::string& text) {
  int n = 0;
  for (const char c : text) n += c == '\n';
  return n;
}

/// A suite small enough to run in well under a second: one 9x9 net, plain and TC-SB at 1.0 and 0.5, 20 steps.
/// Tests edit its text ("steps": 20, "seed") to make bad or different suites.
inline std::string nine_by_nine_suite(const std::string& name, int repetitions) {
  return R"({
  "name": ")" +
         name + R"(", "description": "one 9x9 net for the CLI tests",
  "nets": [{"name": "n9", "width": 9, "height": 9, "size": [2.0, 2.0], "elevation": 2.0, "mass": {"total": 1.0},
            "pinned": "corners"}],
  "methods": ["plain", "tcsb"], "compression": [1.0, 0.5],
  "dt": 0.016666666666666666, "gravity": 9.81, "steps": 20, "warmup_steps": 5, "repetitions": )" +
         std::to_string(repetitions) + R"(, "seed": 1,
  "solver": {"piterations": 2}
})";
}

/// The 9 x 9 suite with two repetitions ("tiny") and with one ("small"), as the CLI tests write them.
inline const std::string kTinySuite = nine_by_nine_suite("tiny", 2);
inline const std::string kSmallSuite = nine_by_nine_suite("small", 1);

/// A fresh temporary directory per test, and tcsb run inside it.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tcsb_cli_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Runs `tcsb ARGS` in the temp directory (with optional environment assignments before it).
  Outcome tcsb(const std::string& args, const std::string& env = "") const {
    return shell(env + " '" + TCSB_BINARY + "' " + args);
  }

  /// Runs a shell command in the temp directory, capturing its output like tcsb().
  Outcome shell(const std::string& command_line) const {
    const std::string command = "cd '" + dir_.string() + "' && " + command_line + " >stdout.txt 2>stderr.txt";
    const int status = std::system(command.c_str());
    Outcome o;
    o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    o.out = read_file(dir_ / "stdout.txt");
    o.err = read_file(dir_ / "stderr.txt");
    return o;
  }

  /// Writes the 9 x 9 suite "small" with `repetitions` as small.json and runs it into result.json, which must succeed.
  void run_small_suite(int repetitions) {
    write_file(dir_ / "small.json", nine_by_nine_suite("small", repetitions));
    const Outcome o = tcsb("run small.json --quiet --out result.json");
    ASSERT_EQ(o.exit_code, 0) << o.err;
  }

  fs::path dir_;
};

}  // namespace tcsb::cli_test
