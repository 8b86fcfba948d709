#include "cli/callgrind_launch.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

#include "case/instruction_meter.h"
#include "cli/cli_common.h"
#include "cli/temporary_directory.h"

namespace tcsb::cli {
namespace {

/// The program's own arguments, as the kernel has them (NUL-separated).
std::vector<std::string> own_command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  std::string arg;
  for (const char c : all) {
    if (c != '\0') {
      arg += c;
      continue;
    }
    args.push_back(arg);
    arg.clear();
  }
  if (args.empty()) throw std::runtime_error("/proc/self/cmdline: cannot read this process's command line");
  return args;
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  const std::string dirs(path);
  for (std::size_t begin = 0; begin <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', begin), dirs.size());
    const std::filesystem::path candidate = std::filesystem::path(dirs.substr(begin, end - begin)) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
    begin = end + 1;
  }
  return false;
}

/// The file the inner process creates as it begins (note_started_under_callgrind): its absence when the child has
/// ended means valgrind never started tcsb.
std::filesystem::path started_marker(const std::filesystem::path& out) { return out.string() + ".started"; }

/// SIGINT or SIGTERM received while the child runs (0: none), and the child to pass it on to.
volatile sig_atomic_t g_signal = 0;
volatile pid_t g_child = 0;

void pass_on(int sig) {
  g_signal = sig;
  if (g_child > 0) ::kill(g_child, sig);
}

/// While it lives, SIGINT and SIGTERM do not end this process at once: they are passed on to the child, whose end
/// is then waited for, so that the scratch directory is removed before the signal ends this process too. A signal
/// this process ignores (a background job's SIGINT) stays ignored.
class PassSignalsOn {
 public:
  PassSignalsOn() {
    g_signal = 0;
    g_child = 0;
    for (std::size_t i = 0; i < 2; ++i) {
      struct sigaction current {};
      ::sigaction(kSignals[i], nullptr, &current);
      if (current.sa_handler == SIG_IGN) continue;
      struct sigaction act {};
      act.sa_handler = pass_on;
      ::sigemptyset(&act.sa_mask);
      act.sa_flags = 0;  // no SA_RESTART: waitpid returns EINTR, and the loop waits again
      installed_[i] = ::sigaction(kSignals[i], &act, &previous_[i]) == 0;
    }
  }
  ~PassSignalsOn() {
    for (std::size_t i = 0; i < 2; ++i)
      if (installed_[i]) ::sigaction(kSignals[i], &previous_[i], nullptr);
    g_child = 0;
  }
  PassSignalsOn(const PassSignalsOn&) = delete;
  PassSignalsOn& operator=(const PassSignalsOn&) = delete;

  static constexpr int kSignals[2] = {SIGINT, SIGTERM};

 private:
  struct sigaction previous_[2]{};
  bool installed_[2] = {false, false};
};

/// How the child ended: its wait status, and whether it had begun tcsb under valgrind.
struct ChildEnd {
  int status = 0;
  bool started = false;
};

ChildEnd run_child(std::vector<std::string>& args, const std::filesystem::path& out) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const PassSignalsOn passing;
  // Blocked across the fork: the child must not run this process's handler; it takes the defaults before exec.
  sigset_t block, previous;
  ::sigemptyset(&block);
  ::sigaddset(&block, SIGINT);
  ::sigaddset(&block, SIGTERM);
  ::sigprocmask(SIG_BLOCK, &block, &previous);
  const pid_t child = ::fork();
  if (child == 0) {
    for (const int sig : PassSignalsOn::kSignals) {
      struct sigaction current {};
      ::sigaction(sig, nullptr, &current);
      if (current.sa_handler != SIG_IGN) ::signal(sig, SIG_DFL);
    }
    ::sigprocmask(SIG_SETMASK, &previous, nullptr);
    ::setenv(kCallgrindOutEnv, out.c_str(), 1);
    ::execvp("valgrind", argv.data());
    ::_exit(kExitInternal);  // exec failed: nothing started (no marker)
  }
  const int fork_errno = errno;
  if (child > 0) g_child = child;
  ::sigprocmask(SIG_SETMASK, &previous, nullptr);  // a signal that came meanwhile is handled (passed on) now
  if (child < 0) throw std::system_error(fork_errno, std::generic_category(), "fork");
  ChildEnd end;
  while (::waitpid(child, &end.status, 0) < 0) {
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
  }
  std::error_code ec;
  end.started = std::filesystem::exists(started_marker(out), ec);
  return end;
}

}  // namespace

void note_started_under_callgrind() {
  const char* out = std::getenv(kCallgrindOutEnv);
  if (out && *out) std::ofstream(started_marker(out)).put('\n');
}

int rerun_under_callgrind() {
  if (!instruction_meter_available())
    throw UsageError("--measure instructions: this tcsb was built without valgrind/callgrind.h (Debian's valgrind)");
  if (!on_path("valgrind"))
    throw UsageError("--measure instructions: valgrind is not on PATH (install Debian's valgrind package)");
  const std::vector<std::string> own = own_command_line();
  ChildEnd end;
  {
    const TemporaryDirectory scratch("tcsb-callgrind", "--measure instructions");
    const std::filesystem::path out = scratch.path() / "callgrind.out";
    // One file with every dump (--combine-dumps), names written out in full (--compress-strings=no): what
    // run/callgrind_dumps.h reads. -q: callgrind's own banner would bury tcsb's messages.
    std::vector<std::string> args = {"valgrind",
                                     "-q",
                                     "--tool=callgrind",
                                     "--callgrind-out-file=" + out.string(),
                                     "--combine-dumps=yes",
                                     "--compress-strings=no",
                                     "--compress-pos=no",
                                     std::filesystem::read_symlink("/proc/self/exe").string()};
    args.insert(args.end(), own.begin() + 1, own.end());
    end = run_child(args, out);
  }  // the scratch directory, callgrind's output with it, is gone: now a signal may end this process
  if (const int sig = g_signal) {
    ::signal(sig, SIG_DFL);
    ::raise(sig);  // ends the process as the signal would have, after the clean-up
  }
  const std::string run = "--measure instructions: ";
  if (WIFSIGNALED(end.status)) {
    print_error(run + "the run under valgrind was ended by signal " + std::to_string(WTERMSIG(end.status)) + " (" +
                ::strsignal(WTERMSIG(end.status)) + ")");
    return kExitInternal;
  }
  const int code = WIFEXITED(end.status) ? WEXITSTATUS(end.status) : kExitInternal;
  if (!end.started) {
    // Valgrind's own failure (a missing tool, too little memory, an exec that failed): not a gate's exit 1.
    print_error(run + "valgrind could not start the run (it exited with " + std::to_string(code) +
                "; its own message, if any, is above)");
    return kExitInternal;
  }
  // `tcsb run` ends with 0, 2 or 3; another code is valgrind's, failing after the run began.
  if (code != kExitOk && code != kExitUsage && code != kExitInternal) {
    print_error(run + "valgrind failed during the run (exit " + std::to_string(code) + ")");
    return kExitInternal;
  }
  return code;
}

std::filesystem::path callgrind_out_file() {
  const char* out = std::getenv(kCallgrindOutEnv);
  if (!out || !*out)
    throw UsageError("--measure instructions: start tcsb without valgrind; it runs itself under callgrind");
  return out;
}

}  // namespace tcsb::cli
