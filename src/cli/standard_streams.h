// Output that cannot lie: whatever a command prints to stdout (a report, a table, --help) either arrives whole or
// the exit code says it did not (3, "a failure to run or write", DESIGN §6), with one line naming the reason. A
// full disk, a closed descriptor and a reader that quit early are all write errors, never exit 0 with a truncated
// report and never a silent death by SIGPIPE. stderr carries diagnostics (the console report, warnings, compare's
// summary unless --summary): its failures do not change the exit code, since there is nowhere left to say so.
#pragma once

namespace tcsb::cli {

/// Call first thing in main. Ignores SIGPIPE (a write to a pipe nobody reads then fails with EPIPE and is reported);
/// gives a closed descriptor 0, 1 or 2 a placeholder (/dev/null opened read-only), so a write to a closed stdout
/// still fails (EBADF) and no file tcsb opens later (a report) can take that number and receive stray output;
/// and routes std::cout through a buffer that remembers the first failed write's reason (errno).
void prepare_standard_streams();

/// The exit code once stdout is flushed and closed: `code` if everything written to it arrived; else kExitInternal
/// after one line "tcsb: error: cannot write to stdout: <reason>" — unless `code` is already kExitUsage or
/// kExitInternal, whose own error line is out and says more.
int finish_stdout(int code);

}  // namespace tcsb::cli
