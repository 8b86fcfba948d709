#include "base/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>

namespace tcsb {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& what, int error) {
  throw WriteError("cannot write " + path.string() + ": " + what + std::strerror(error));
}

/// Writes all of `text` to `fd`; false (errno set) on failure.
bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/// The permission bits open(..., 0666) would give a new file: what the umask leaves of rw-rw-rw-. (mkstemp makes
/// 0600, which would hide a report from the group that reads it.) Reading the umask means setting it: nothing else
/// creates files at the same moment, so the brief change is harmless.
mode_t new_file_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

/// The temporary file being written, for the signal handler: a fixed buffer (a handler may not allocate), valid
/// while `g_temporary_set` is 1.
char g_temporary[PATH_MAX + 1];
volatile std::sig_atomic_t g_temporary_set = 0;

/// Removes the temporary file, then ends the process by the same signal (its exit status stays the signal's).
extern "C" void remove_temporary_and_end(int signal) {
  if (g_temporary_set) ::unlink(g_temporary);
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

/// A temporary file made by mkstemp in `dir`: removed again unless it was renamed into place, also when a signal
/// ends the process meanwhile (remove_temporary_files_on_signals).
class TempFile {
 public:
  explicit TempFile(const fs::path& dir) : name_((dir / ".tcsb-out-XXXXXX").string()) {
    if (name_.size() >= sizeof g_temporary) {  // too long for the handler's buffer: not removed on a signal
      fd_ = ::mkostemp(name_.data(), O_CLOEXEC);
      error_ = fd_ < 0 ? errno : 0;
      return;
    }
    // mkostemp fills the name in inside the buffer the signal handler reads, before it creates the file: a signal
    // at any moment after the file exists finds its name there (before, it unlinks a name that is no file: harmless).
    std::memcpy(g_temporary, name_.c_str(), name_.size() + 1);
    g_temporary_set = 1;
    fd_ = ::mkostemp(g_temporary, O_CLOEXEC);
    error_ = fd_ < 0 ? errno : 0;
    if (created()) {
      name_ = g_temporary;
    } else {
      g_temporary_set = 0;
    }
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (created() && !renamed_) ::unlink(name_.c_str());
    g_temporary_set = 0;  // after: a signal in between removes what is gone already, harmlessly
  }
  bool created() const { return error_ == 0; }
  int error() const { return error_; }
  int fd() const { return fd_; }
  /// Closes the file; false (errno set) when the close reports a failed write (NFS reports them only here).
  bool close() {
    const int fd = fd_;
    fd_ = -1;
    return ::close(fd) == 0;
  }
  /// Renames the (closed) file to `target`; false (errno set) on failure.
  bool rename_to(const fs::path& target) {
    renamed_ = ::rename(name_.c_str(), target.c_str()) == 0;
    return renamed_;
  }

 private:
  std::string name_;
  int fd_ = -1;
  int error_ = 0;
  bool renamed_ = false;
};

/// The directory a temporary file for `path` goes in.
fs::path directory_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

/// What a rename must replace: a symlink's target (so the link survives), else `given` itself (also a dangling link).
fs::path replaced_file(const fs::path& given) {
  std::error_code ec;
  if (!fs::is_symlink(fs::symlink_status(given, ec))) return given;
  const fs::path resolved = fs::canonical(given, ec);
  return ec ? given : resolved;
}

/// True if `path` exists and is neither a regular file nor a directory (a device, a FIFO, a socket): written into.
bool is_special(const fs::path& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

/// Writes straight into an existing device or pipe (/dev/null, /dev/stdout, a FIFO): nothing there can be replaced
/// atomically, and renaming a file over it would destroy it (replace /dev/null with a regular file). Opened without
/// O_CREAT and O_TRUNC, and checked after opening: should the name have become a regular file meanwhile, false is
/// returned and nothing was written.
bool write_into_special(const fs::path& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) fail(path, "", errno);
  struct stat st {};
  if (::fstat(fd, &st) != 0 || S_ISREG(st.st_mode)) {
    ::close(fd);
    return false;
  }
  if (!write_all(fd, text)) {
    const int error = errno;
    ::close(fd);
    fail(path, "", error);
  }
  if (::close(fd) != 0) fail(path, "", errno);
  return true;
}

/// The longest file name the file system holding `dir` accepts.
long name_max(const fs::path& dir) {
  const long n = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  return n > 0 ? n : NAME_MAX;
}

}  // namespace

void write_file_atomically(const fs::path& given, const std::string& text) {
  if (is_special(given) && write_into_special(given, text)) return;
  const fs::path path = replaced_file(given);
  const fs::path dir = directory_of(path);
  TempFile tmp(dir);
  if (!tmp.created()) fail(path, "cannot create a temporary file in " + dir.string() + ": ", tmp.error());
  if (::fchmod(tmp.fd(), new_file_mode()) != 0) fail(path, "", errno);
  if (!write_all(tmp.fd(), text)) fail(path, "", errno);
  if (!tmp.close()) fail(path, "", errno);
  if (!tmp.rename_to(path)) fail(path, "cannot rename the temporary file into place: ", errno);
}

void remove_temporary_files_on_signals() {
  std::signal(SIGXFSZ, SIG_IGN);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    if (::sigaction(signal, nullptr, &previous) != 0 || previous.sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporary_and_end;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal, &action, nullptr);
  }
}

std::string output_problem(const fs::path& given) {
  std::error_code ec;
  const fs::path path = replaced_file(given);
  const fs::path dir = directory_of(path);
  if (!fs::is_directory(dir, ec)) return "directory " + dir.string() + " does not exist";
  if (fs::is_directory(path, ec)) return "is a directory";
  if (is_special(path)) return "";  // written into, nothing is created beside it
  if (const long max = name_max(dir); static_cast<long>(path.filename().string().size()) > max) {
    return "the file name is longer than " + std::to_string(max) + " bytes, the most the file system allows";
  }
  TempFile probe(dir);  // removed again at once
  if (!probe.created()) {
    return "cannot create files in directory " + dir.string() + " (" + std::strerror(probe.error()) + ")";
  }
  return "";
}

}  // namespace tcsb
