// A scratch directory for the processes a command starts (shards of --processes, the run under callgrind), removed
// with everything in it when it goes out of scope.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace tcsb::cli {

class TemporaryDirectory {
 public:
  /// Creates TMPDIR/PREFIX.XXXXXX; throws std::runtime_error starting with `what` when it cannot.
  TemporaryDirectory(const std::string& prefix, const std::string& what) {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + ".XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error(what + ": cannot create a temporary directory");
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace tcsb::cli
