#include "base/json_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>
#include <set>
#include <stdexcept>
#include <vector>

#include "base/input_error.h"

namespace tcsb {
namespace {

/// Why a file of this type is not read, or "" for a regular file.
std::string refused_type(const struct stat& st) {
  if (S_ISREG(st.st_mode)) return "";
  if (S_ISDIR(st.st_mode)) return "cannot read the file: it is a directory";
  if (S_ISFIFO(st.st_mode)) return "cannot read the file: it is a pipe, not a regular file";
  return "cannot read the file: it is a device or socket, not a regular file";
}

std::string too_large(std::size_t max_bytes) {
  return "cannot read the file: larger than " + std::to_string(max_bytes >> 20) + " MiB, the most tcsb reads";
}

/// Closes a file descriptor on every path out of read_input_file.
struct FdCloser {
  int fd;
  ~FdCloser() { ::close(fd); }
};

/// nlohmann's message without its "[json.exception.parse_error.101] " prefix, on one line.
std::string parser_message(const std::string& what) {
  std::string message = what;
  if (const auto close = message.find("] "); message.rfind("[json.exception", 0) == 0 && close != std::string::npos) {
    message.erase(0, close + 2);
  }
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}

}  // namespace

// Named, not anonymous: parse_json_text is a template of external linkage whose lambda captures a PathTracker, and a
// capture of a type with internal linkage there is what GCC's -Wsubobject-linkage warns of.
namespace json_file_detail {

/// "parent.key" / "parent[i]" of the value being parsed, kept up to date by the parser's callback.
class PathTracker {
 public:
  void open(bool is_array) { stack_.push_back(Frame{is_array, 0, {}, false, {}}); }
  void close() {
    stack_.pop_back();
    value_done();
  }
  /// Records the key of the next member; false if the object already had it.
  bool key(const std::string& name) {
    Frame& f = stack_.back();
    f.key = name;
    f.in_member = true;
    return f.seen.insert(name).second;
  }
  /// A value ended in the innermost container: in an array, the next element gets the next index; in an object,
  /// the member is complete.
  void value_done() {
    if (stack_.empty()) return;
    Frame& f = stack_.back();
    if (f.is_array)
      ++f.index;
    else
      f.in_member = false;
  }
  /// Where the parser is: down to the member whose value is being read (not one already complete).
  std::string path() const {
    std::string p;
    for (const Frame& f : stack_) {
      // One append per piece: GCC 12's -Wrestrict false positive on a chain of + starting at a literal.
      if (f.is_array) {
        p += '[';
        p += std::to_string(f.index);
        p += ']';
      } else if (f.in_member) {
        if (!p.empty()) p += '.';
        p += f.key;
      } else {
        break;
      }
    }
    return p;
  }

 private:
  struct Frame {
    bool is_array = false;
    std::size_t index = 0;
    std::string key;         ///< the member last begun
    bool in_member = false;  ///< its value is still being read
    std::set<std::string> seen;
  };
  std::vector<Frame> stack_;
};

}  // namespace json_file_detail

std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes) {
  const std::string file = path.string();
  const auto unreadable = [&file](int error) {
    return InputError(file, "", std::string("cannot read the file (") + std::strerror(error) + ")");
  };
  struct stat st {};
  // stat before open: opening a FIFO for reading blocks until a writer appears, and /dev/zero never ends.
  if (::stat(file.c_str(), &st) != 0) throw unreadable(errno);
  if (const std::string why = refused_type(st); !why.empty()) throw InputError(file, "", why);
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) throw InputError(file, "", too_large(max_bytes));
  // O_NONBLOCK: should the name be swapped for a FIFO after the stat, open returns at once instead of hanging.
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) throw unreadable(errno);
  const FdCloser closer{fd};
  if (::fstat(fd, &st) != 0) throw unreadable(errno);
  if (const std::string why = refused_type(st); !why.empty()) throw InputError(file, "", why);
  // The size is re-checked while reading: the file may grow after fstat.
  std::string text;
  try {
    text.reserve(static_cast<std::size_t>(st.st_size));
  } catch (const std::bad_alloc&) {
    throw InputError(file, "", "cannot read the file: too large for the memory available");
  }
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw unreadable(errno);
    }
    if (text.size() + static_cast<std::size_t>(n) > max_bytes) throw InputError(file, "", too_large(max_bytes));
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

template <class Json>
Json parse_json_text(const std::string& text, const std::string& file, int max_depth) {
  // nlohmann stops at a NUL byte as if the input ended there, so "{}\0anything" would pass; JSON text never holds a
  // raw NUL (not even inside a string), so any NUL is an error.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
    throw InputError(file, "", "not valid JSON: a NUL byte at byte " + std::to_string(nul + 1));
  }
  json_file_detail::PathTracker tracker;
  const typename Json::parser_callback_t callback = [&](int depth, nlohmann::json::parse_event_t event, Json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        // `depth` counts the containers around this one: refuse before nesting further.
        if (depth >= max_depth) {
          throw InputError(file, "",
                           "not valid JSON: arrays and objects nested deeper than " + std::to_string(max_depth) +
                               " levels, the most tcsb reads");
        }
        tracker.open(event == Event::array_start);
        break;
      case Event::key:
        if (!tracker.key(parsed.template get<std::string>())) {
          throw InputError(file, tracker.path(), "duplicate key (each key may appear once)");
        }
        break;
      case Event::object_end:
      case Event::array_end: tracker.close(); break;
      case Event::value: tracker.value_done(); break;
    }
    return true;
  };
  try {
    return Json::parse(text, callback);
  } catch (const nlohmann::json::exception& e) {
    // Not only parse_error: a number too large for a double (1e309) is an out_of_range error ("number overflow").
    // The tracker still points at the member being read, so the message names the field.
    throw InputError(file, tracker.path(), "not valid JSON: " + parser_message(e.what()));
  } catch (const std::bad_alloc&) {
    // Only the input can exhaust memory here (its size is bounded, but the machine may be small): bad input, not a
    // bug. Elsewhere bad_alloc stays an internal error.
    throw InputError(file, "", "too large to parse in the memory available");
  } catch (const std::length_error&) {
    throw InputError(file, "", "too large to parse in the memory available");
  }
}

template nlohmann::json parse_json_text<nlohmann::json>(const std::string&, const std::string&, int);
template nlohmann::ordered_json parse_json_text<nlohmann::ordered_json>(const std::string&, const std::string&, int);

}  // namespace tcsb
