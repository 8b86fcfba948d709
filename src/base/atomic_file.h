// Writing a report file atomically: a temp file beside the target, then rename, so a failed run never leaves a
// truncated or half-written output behind. The temp file is created exclusively (mkstemp: a fresh random name,
// O_EXCL, never through a symlink), so whoever can write the output directory cannot make tcsb overwrite another
// file by planting a link at a predictable name.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace tcsb {

/// An output could not be written (a full disk, a closed pipe, a read-only directory): exit code 3, not bad input.
/// The message is "cannot write FILE: reason".
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `text` to `path` atomically (temp file in the same directory, then rename). Throws WriteError naming the
/// file on failure; the target is then untouched and no temporary file is left. A symlink is kept (its target is
/// replaced); an existing device or pipe (/dev/null, /dev/stdout, a FIFO) is written into directly, never
/// replaced. The new file gets the permissions an ordinary new file would (0666 less the umask).
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

/// Makes the signals that end the process mid-write leave no temporary file behind: SIGXFSZ (a write beyond
/// `ulimit -f`) is ignored, so the write fails with EFBIG and is a WriteError (exit 3) like a full disk; SIGINT,
/// SIGTERM and SIGHUP remove the temporary file being written, if any, and then end the process as they would
/// have (a signal the parent set to be ignored stays ignored). Call once, first thing in main.
void remove_temporary_files_on_signals();

/// Why write_file_atomically(path, ...) would fail now, or "" if it should succeed: the directory is missing, the
/// path is a directory, the file name is longer than the file system allows, or no file can be created beside it
/// (tried for real, with a temporary file that is removed at once: root passes access() on read-only mounts).
std::string output_problem(const std::filesystem::path& path);

}  // namespace tcsb
