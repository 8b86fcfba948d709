// Atomic report writing: the target is replaced whole or not at all, a symlink survives, and a pipe or device is
// written into rather than replaced (renaming over /dev/null would turn it into a regular file).
#include "base/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <thread>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace tcsb {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class ReportWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tcsb_writer_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(ReportWriter, ReplacesARegularFileAndLeavesNoTemporary) {
  std::ofstream(dir_ / "out.json") << "old";
  write_file_atomically(dir_ / "out.json", "new\n");
  EXPECT_EQ(read_all(dir_ / "out.json"), "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(ReportWriter, KeepsASymlinkAndReplacesItsTarget) {
  std::ofstream(dir_ / "real.json") << "old";
  fs::create_symlink("real.json", dir_ / "link.json");
  write_file_atomically(dir_ / "link.json", "new");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
  EXPECT_EQ(read_all(dir_ / "real.json"), "new");
}

TEST_F(ReportWriter, WritesIntoAPipeInsteadOfReplacingIt) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A non-blocking reader first, so the writer's open does not wait and the test cannot hang.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  write_file_atomically(fifo, "through the pipe");
  char buf[64] = {};
  const ssize_t n = ::read(reader, buf, sizeof buf - 1);
  ::close(reader);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "through the pipe");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the pipe must not have been replaced by a regular file";
}

TEST_F(ReportWriter, FailureNamesTheFileAndTouchesNothing) {
  try {
    write_file_atomically(dir_ / "no_such_dir" / "out.json", "x");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("out.json"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
}

// The old code wrote its temporary file at ".NAME.PID.tmp", following symlinks: anyone who could write the directory
// could make tcsb overwrite any file it may write. The temporary file is now created exclusively.
TEST_F(ReportWriter, APlantedSymlinkAtTheOldTemporaryNameIsNotFollowed) {
  std::ofstream(dir_ / "victim") << "precious";
  const fs::path planted = dir_ / (".out.json." + std::to_string(::getpid()) + ".tmp");
  fs::create_symlink(dir_ / "victim", planted);
  write_file_atomically(dir_ / "out.json", "report");
  EXPECT_EQ(read_all(dir_ / "victim"), "precious");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir_ / "out.json")));
  EXPECT_EQ(read_all(dir_ / "out.json"), "report");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(planted)));  // left as it was
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);
}

// mkstemp creates 0600; the report must get what any new file gets (0666 less the umask).
TEST_F(ReportWriter, TheFileGetsTheModeOfAnOrdinaryNewFile) {
  for (const mode_t mask : {mode_t{022}, mode_t{077}, mode_t{002}}) {
    const mode_t old = ::umask(mask);
    write_file_atomically(dir_ / "out.json", "x");
    ::umask(old);
    struct stat st {};
    ASSERT_EQ(::stat((dir_ / "out.json").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask) << std::oct << mask;
  }
}

TEST_F(ReportWriter, WritingIntoAFullDeviceIsAWriteErrorNamingIt) {
  try {
    write_file_atomically("/dev/full", "x");
    FAIL() << "expected a WriteError";
  } catch (const WriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write /dev/full: No space left on device");
  }
}

TEST_F(ReportWriter, OutputProblemsAreFoundBeforeWritingAndTheCheckLeavesNoFile) {
  EXPECT_EQ(output_problem(dir_ / "out.json"), "");
  EXPECT_EQ(output_problem("/dev/null"), "");
  EXPECT_NE(output_problem(dir_ / "missing" / "out.json").find("does not exist"), std::string::npos);
  EXPECT_EQ(output_problem(dir_), "is a directory");
  EXPECT_NE(output_problem(dir_ / std::string(256, 'x')).find("longer than 255 bytes"), std::string::npos);
  EXPECT_EQ(output_problem(dir_ / std::string(255, 'x')), "");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 0);
  if (::geteuid() != 0) {  // root may create files in a read-only directory
    fs::create_directories(dir_ / "ro");
    fs::permissions(dir_ / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_NE(output_problem(dir_ / "ro" / "out.json").find("cannot create files"), std::string::npos);
    fs::permissions(dir_ / "ro", fs::perms::owner_all);
  }
}

/// Temporary files the writer left in `dir`.
int temporaries(const fs::path& dir) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir)) n += entry.path().filename().string().starts_with(".tcsb-out-");
  return n;
}

TEST_F(ReportWriter, AWriteBeyondTheFileSizeLimitIsAWriteErrorAndLeavesNoTemporary) {
  // In a child: the limit and the signal disposition are the process's.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporary_files_on_signals();
    const struct rlimit limit { 4096, 4096 };
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      write_file_atomically(dir_ / "out.json", std::string(1 << 20, 'x'));
    } catch (const WriteError&) {
      ::_exit(3);
    }
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 3);
  EXPECT_EQ(temporaries(dir_), 0);
  EXPECT_FALSE(fs::exists(dir_ / "out.json"));
}

TEST_F(ReportWriter, SigtermOrSigintDuringAWriteRemovesTheTemporary) {
  for (const int signal : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(signal);
    // The child writes 64 MB again and again; the signal arrives once a temporary is seen, mid-write.
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      remove_temporary_files_on_signals();
      const std::string text(64 << 20, 'x');
      for (;;) write_file_atomically(dir_ / "out.json", text);
    }
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (temporaries(dir_) == 0 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    const bool seen = temporaries(dir_) > 0;
    ::kill(child, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(seen) << "no temporary file appeared within a minute";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "the signal still ends the process";
    EXPECT_EQ(temporaries(dir_), 0);
    fs::remove(dir_ / "out.json");
  }
}

}  // namespace
}  // namespace tcsb
