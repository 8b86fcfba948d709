#include "cli/shard_processes.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/temporary_directory.h"
#include "result/result_file.h"

extern char** environ;

namespace tcsb::cli {
namespace {

/// This executable's path (the shards run the very build that judges them: merge refuses shards of other builds).
std::filesystem::path own_executable() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw std::runtime_error("--processes: cannot find this executable (/proc/self/exe: " + error.message() + ")");
  return self;
}

/// Runs `argv` to its end; throws naming `what` unless it exits 0.
void run_process(const std::vector<std::string>& argv, const std::string& what) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (const int e = posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), environ); e != 0)
    throw std::runtime_error(what + ": cannot start " + argv[0] + " (" + std::strerror(e) + ")");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error(what + ": lost its process (" + std::strerror(errno) + ")");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(what + " did not succeed (" +
                             (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                                                : "signal " + std::to_string(WTERMSIG(status))) +
                             ")");
}

}  // namespace

MergedShards run_in_processes(const std::filesystem::path& suite_file, const std::optional<int>& repetitions,
                              int processes, int suite_repetitions) {
  if (processes < 1 || processes > suite_repetitions)
    throw UsageError("--processes: expected 1 to the suite's " + std::to_string(suite_repetitions) +
                     " repetitions, got " + std::to_string(processes));
  const std::filesystem::path self = own_executable();
  const TemporaryDirectory directory("tcsb-processes", "--processes");
  std::vector<ShardDocument> shards;
  for (int k = 1; k <= processes; ++k) {
    const std::string shard = std::to_string(k) + "/" + std::to_string(processes);
    const std::filesystem::path out = directory.path() / ("shard-" + std::to_string(k) + ".json");
    std::vector<std::string> argv{self.string(), "run",         suite_file.string(), "--quiet",
                                  "--split",     "repetitions", "--shard",           shard,
                                  "--out",       out.string()};
    if (repetitions) {
      argv.push_back("--repetitions");
      argv.push_back(std::to_string(*repetitions));
    }
    run_process(argv, "--processes: process " + shard);
    shards.push_back({out.string(), load_result_file(out.string()).document});
  }
  return merge_shards(shards);
}

}  // namespace tcsb::cli
