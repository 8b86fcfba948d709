// `tcsb run --measure instructions` runs under Valgrind's callgrind, but a user types the command alone: the process
// starts the same command line again under callgrind, waits for it, and passes its exit code on. The inner process
// finds callgrind's output file through an environment variable and reads its counts from it after the run.
#pragma once

#include <filesystem>
#include <optional>

namespace tcsb::cli {

/// The environment variable through which the outer process tells the inner one where callgrind writes.
inline constexpr const char* kCallgrindOutEnv = "TCSB_CALLGRIND_OUT";

/// Runs this process's own command line (/proc/self/cmdline) again under `valgrind --tool=callgrind`, with callgrind's
/// output in a scratch directory that is removed afterwards, and returns the inner process's exit code. Throws
/// UsageError when valgrind is not on PATH or this build lacks valgrind/callgrind.h. When valgrind cannot start the
/// run (the inner process never began), fails during it (an exit code `run` never gives) or the run is killed, it
/// prints one line of its own and returns 3, never valgrind's code. SIGINT and SIGTERM are passed on to the run and
/// its end waited for; the scratch directory is removed, and then the signal ends this process.
int rerun_under_callgrind();

/// Inside the inner process, first thing: tells the outer one that valgrind started tcsb (a file beside callgrind's
/// output). Does nothing outside a run under callgrind.
void note_started_under_callgrind();

/// Inside the inner process: callgrind's output file. Throws UsageError when the process runs under Valgrind without
/// it (someone started valgrind by hand: tcsb starts callgrind itself, with the options its reader needs).
std::filesystem::path callgrind_out_file();

}  // namespace tcsb::cli
