// Output that cannot lie and files that cannot be hijacked, through the real binary: a write to a full or closed
// stdout (or a reader that quit) is exit 3 with one error line for every command, never exit 0 with a truncated
// report or death by SIGPIPE; --out is never written through a planted symlink, never equal to an input, and a
// name the file system cannot hold is refused before the run.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace tcsb::cli_test;

const std::string kBinary = TCSB_BINARY;

/// "tcsb: error: cannot write to stdout: <reason>" somewhere in `err`, and no "internal error".
void expect_stdout_error(const Outcome& o, const std::string& reason, const std::string& what) {
  EXPECT_EQ(o.exit_code, 3) << what << "\n" << o.err;
  EXPECT_NE(o.err.find("tcsb: error: cannot write to stdout: " + reason), std::string::npos) << what << "\n" << o.err;
  EXPECT_EQ(o.err.find("internal error"), std::string::npos) << what << "\n" << o.err;
}

class Output : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    write_file(dir_ / "small.json", kSmallSuite);
  }
  /// A finished run of the small suite, as result.json.
  void make_result() { run_small_suite(1); }
  /// `tcsb ARGS` with stdout redirected as `redirect` says (">/dev/full", ">&-"), under a timeout.
  Outcome tcsb_with_stdout(const std::string& args, const std::string& redirect) const {
    return shell("( timeout 60 '" + kBinary + "' " + args + " " + redirect + " )");
  }
  /// The names in the temp directory.
  std::set<std::string> listing(const fs::path& dir) const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
  }
};

TEST_F(Output, AFullStdoutIsExit3ForEveryCommand) {
  make_result();
  for (const std::string args :
       {"run small.json --quiet", "export result.json --format gbench", "validate small.json", "list", "--version",
        "--help", "frames --suite small.json --steps 1", "reproduce --suite small.json --quiet"}) {
    expect_stdout_error(tcsb_with_stdout(args, ">/dev/full"), "No space left on device", args);
  }
}

TEST_F(Output, AFullOutOrSummaryFileIsExit3WithoutInternalError) {
  make_result();
  // The gate decides only with 9 repetitions (fewer: exit 2 before any summary), so compare gets a run of its own.
  write_file(dir_ / "gate.json", nine_by_nine_suite("gate", 9));
  ASSERT_EQ(tcsb("run gate.json --quiet --out gated.json").exit_code, 0);
  for (const std::string args :
       {"compare gated.json gated.json --summary /dev/full", "export result.json --format gbench --out /dev/full"}) {
    const Outcome o = tcsb(args);
    EXPECT_EQ(o.exit_code, 3) << args << "\n" << o.err;
    EXPECT_NE(o.err.find("tcsb: error: cannot write /dev/full: No space left on device"), std::string::npos)
        << args << "\n"
        << o.err;
    EXPECT_EQ(o.err.find("internal error"), std::string::npos) << args << "\n" << o.err;
  }
}

TEST_F(Output, AClosedStdoutIsExit3AndNeverReachesAnOutputFile) {
  for (const std::string args : {"validate small.json", "list", "--version"}) {
    expect_stdout_error(tcsb_with_stdout(args, ">&-"), "Bad file descriptor", args);
  }
  // Nothing goes to stdout with --out: success, and the report holds only the report (had the output file taken
  // descriptor 1, stray stdout writes would land in it).
  const Outcome o = tcsb_with_stdout("run small.json --quiet --out out.json", ">&-");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(nlohmann::json::accept(read_file(dir_ / "out.json")));
}

TEST_F(Output, AReaderThatQuitIsExit3NotDeathBySigpipe) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ::close(fds[0]);  // nobody will ever read: the first write fails, deterministically
  const fs::path err = dir_ / "stderr.txt";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGPIPE, SIG_DFL);  // as a shell would start it, whatever the test runner ignores
    ::dup2(fds[1], STDOUT_FILENO);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(e, STDERR_FILENO);
    ::execl(kBinary.c_str(), "tcsb", "list", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_FALSE(WIFSIGNALED(status)) << "killed by signal " << WTERMSIG(status);
  Outcome o;
  o.exit_code = WEXITSTATUS(status);
  o.err = read_file(err);
  expect_stdout_error(o, "Broken pipe", "list into a closed pipe");
}

// The names the old code used, planted as symlinks to a file elsewhere before tcsb starts: `sh -c '...; exec tcsb'`
// keeps the shell's pid, so $$ is tcsb's pid.
TEST_F(Output, PlantedSymlinksAtTheOldProbeAndTemporaryNamesAreNotFollowed) {
  fs::create_directories(dir_ / "outdir");
  write_file(dir_ / "victim", "precious\n");
  write_file(dir_ / "bad.json", "{\"name\": 1}");
  for (const std::string suite : {"bad.json", "small.json"}) {
    const Outcome o = shell("sh -c 'ln -sf ../victim outdir/.tcsb-write-probe-$$ && "
                            "ln -sf ../victim outdir/.out.json.$$.tmp && exec \"" +
                            kBinary + "\" run " + suite + " --quiet --out outdir/out.json'");
    EXPECT_EQ(o.exit_code, suite == "bad.json" ? 2 : 0) << o.err;
    EXPECT_EQ(read_file(dir_ / "victim"), "precious\n") << suite;
  }
  // Only the planted links (two per run) and the report: no probe or temporary file left behind.
  std::size_t links = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "outdir")) {
    if (fs::is_symlink(e.symlink_status()))
      ++links;
    else
      EXPECT_EQ(e.path().filename(), "out.json");
  }
  EXPECT_EQ(links, 4u);
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir_ / "outdir" / "out.json")));
  EXPECT_TRUE(nlohmann::json::accept(read_file(dir_ / "outdir" / "out.json")));
}

TEST_F(Output, TheReportGetsTheModeAnOrdinaryNewFileWould) {
  const Outcome o = shell("umask 027 && '" + kBinary + "' run small.json --quiet --out out.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  struct stat st {};
  ASSERT_EQ(::stat((dir_ / "out.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
}

TEST_F(Output, OutEqualToAnInputIsRefusedHoweverItIsSpelled) {
  make_result();
  write_file(dir_ / "paper.json", read_file(fs::path(TCSB_SOURCE_DIR) / "results/paper.json"));
  fs::create_symlink("small.json", dir_ / "link.json");
  fs::create_hard_link(dir_ / "result.json", dir_ / "hard.json");
  const std::string suite_before = read_file(dir_ / "small.json");
  const std::string result_before = read_file(dir_ / "result.json");
  const std::string paper_before = read_file(dir_ / "paper.json");
  for (const std::string& args : std::vector<std::string>{
           "run small.json --quiet --out small.json", "run small.json --quiet --out ./small.json",
           "run small.json --quiet --out link.json", "run link.json --quiet --out small.json",
           "run small.json --quiet --out " + (dir_ / "small.json").string(),
           "export result.json --format gbench --out ./result.json",
           "export result.json --format gbench --out hard.json", "compare result.json hard.json --summary result.json",
           "compare result.json hard.json --summary hard.json",
           "reproduce --suite small.json --paper paper.json --quiet --out paper.json",
           "reproduce --suite small.json --paper paper.json --quiet --out ./small.json",
           "frames --suite small.json --steps 1 --out link.json"}) {
    const Outcome o = tcsb(args);
    EXPECT_EQ(o.exit_code, 2) << args << "\n" << o.err;
    EXPECT_EQ(count_lines(o.err), 1) << args << "\n" << o.err;
    EXPECT_NE(o.err.find("is the input file"), std::string::npos) << args << "\n" << o.err;
  }
  EXPECT_EQ(read_file(dir_ / "small.json"), suite_before);
  EXPECT_EQ(read_file(dir_ / "result.json"), result_before);
  EXPECT_EQ(read_file(dir_ / "paper.json"), paper_before);
}

TEST_F(Output, AnOutNameTheFileSystemCannotHoldIsRefusedBeforeTheRun) {
  const std::string too_long(256, 'x');  // NAME_MAX is 255 on Linux file systems
  const Outcome o = tcsb("run small.json --quiet --out " + too_long);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("longer than"), std::string::npos) << o.err;
  EXPECT_EQ(o.out, "") << "refused before the run: no report on stdout";
  // The longest name that fits is written (the temporary sibling's name does not grow with it).
  const std::string longest(255, 'y');
  const Outcome ok = tcsb("run small.json --quiet --out " + longest);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / longest));
}

// Under `ulimit -f` a merge --out was killed by SIGXFSZ (exit 153) and left its .tcsb-out-* temporary. A write
// beyond the limit is a write failure like a full disk: exit 3, one line, no temporary, the old file intact.
TEST_F(Output, AWriteBeyondUlimitFIsExit3AndLeavesNoTemporary) {
  for (const char* k : {"1", "2"}) {
    const Outcome o = tcsb(std::string("run small.json --quiet --shard ") + k + "/2 --out shard" + k + ".json");
    ASSERT_EQ(o.exit_code, 0) << o.err;
  }
  write_file(dir_ / "merged.json", "old");
  std::set<std::string> before = listing(dir_);
  const Outcome o =
      shell("sh -c 'ulimit -f 4; exec \"" + kBinary + "\" merge shard1.json shard2.json --quiet --out merged.json'");
  EXPECT_EQ(o.exit_code, 3) << o.err;
  EXPECT_EQ(count_lines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("tcsb: error: cannot write merged.json"), std::string::npos) << o.err;
  EXPECT_EQ(read_file(dir_ / "merged.json"), "old");
  std::set<std::string> after = listing(dir_);
  for (std::set<std::string>* names : {&before, &after}) {
    names->erase("stdout.txt");
    names->erase("stderr.txt");
  }
  EXPECT_EQ(after, before) << "a temporary was left behind";
}

}  // namespace
