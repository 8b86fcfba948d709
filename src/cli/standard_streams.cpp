#include "cli/standard_streams.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <iostream>
#include <streambuf>
#include <string>

#include "base/atomic_file.h"
#include "cli/cli_common.h"

namespace tcsb::cli {
namespace {

/// A buffered stream buffer writing to a file descriptor that keeps the reason of its first failed write. (stdio's
/// buffer reports a failure only as a flag, after errno has long been overwritten.) After a failure it discards
/// what it holds, so std::cout turns bad and stays bad.
class RecordingFdBuffer : public std::streambuf {
 public:
  explicit RecordingFdBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  /// errno of the first failed write, or 0.
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    setp(buffer_, buffer_ + sizeof buffer_);
    while (left > 0) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        if (error_ == 0) error_ = n < 0 ? errno : EIO;
        return false;
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    return error_ == 0;
  }

  int fd_;
  int error_ = 0;
  char buffer_[1 << 16];
};

/// std::cout's buffer. Never destroyed: the iostreams flush std::cout once more at exit, after every static object
/// of ours would have been.
RecordingFdBuffer* stdout_buffer = nullptr;

}  // namespace

void prepare_standard_streams() {
  std::signal(SIGPIPE, SIG_IGN);
  remove_temporary_files_on_signals();  // SIGXFSZ a write failure; SIGINT/SIGTERM leave no temporary file
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    // open returns the lowest free descriptor: `fd` itself, since the lower ones are open by now.
    const int placeholder = ::open("/dev/null", O_RDONLY | O_NOCTTY);
    if (placeholder != fd && placeholder >= 0) ::close(placeholder);
  }
  stdout_buffer = new RecordingFdBuffer(STDOUT_FILENO);
  std::cout.rdbuf(stdout_buffer);
}

int finish_stdout(int code) {
  std::cout.flush();
  int error = stdout_buffer != nullptr ? stdout_buffer->error() : 0;
  if (error == 0 && !std::cout) error = EIO;
  // close reports what a file system defers to the end (NFS, quotas). Nothing is written to stdout after this.
  if (::close(STDOUT_FILENO) != 0 && errno != EBADF && error == 0) error = errno;
  if (error == 0 || code == kExitUsage || code == kExitInternal) return code;
  print_error(std::string("cannot write to stdout: ") + std::strerror(error));
  return kExitInternal;
}

}  // namespace tcsb::cli
