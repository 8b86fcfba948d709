// InputError: the one error type for bad input files, so every reader (suites, result files, the paper's reference
// values) reports the same one line, and every command maps it to exit 2 the same way.
#pragma once

#include <stdexcept>
#include <string>

namespace tcsb {

/// An input file that cannot be used (a suite, a result, a paper reference). what() is one line naming the file and
/// the field; the commands turn it into exit 2.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& problem)
      : std::runtime_error(file + ": " + (field.empty() ? std::string() : field + ": ") + problem), file_(file),
        field_(field) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_, field_;
};

}  // namespace tcsb
