#include "cli/callgrind_launch.h"

#include <sys/wait.h>
#include <unistd.h>

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

}  // namespace

int rerun_under_callgrind() {
  if (!instruction_meter_available())
    throw UsageError("--measure instructions: this tcsb was built without valgrind/callgrind.h (Debian's valgrind)");
  if (!on_path("valgrind"))
    throw UsageError("--measure instructions: valgrind is not on PATH (install Debian's valgrind package)");
  const std::vector<std::string> own = own_command_line();
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
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = ::fork();
  if (child < 0) throw std::system_error(errno, std::generic_category(), "fork");
  if (child == 0) {
    ::setenv(kCallgrindOutEnv, out.c_str(), 1);
    ::execvp("valgrind", argv.data());
    ::_exit(kExitInternal);  // exec failed
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  throw std::runtime_error("the run under callgrind ended by signal " + std::to_string(WTERMSIG(status)));
}

std::filesystem::path callgrind_out_file() {
  const char* out = std::getenv(kCallgrindOutEnv);
  if (!out || !*out)
    throw UsageError("--measure instructions: start tcsb without valgrind; it runs itself under callgrind");
  return out;
}

}  // namespace tcsb::cli
