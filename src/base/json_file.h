// Reading a JSON input file (a suite, a result, the paper's numbers) without trusting it: only a regular file, of a
// bounded size, nested to a bounded depth, with nothing but whitespace after the document, no duplicate keys and
// no number too large for a double. Every input goes through here, so the three readers cannot drift apart. Each
// failure is an InputError "FILE: FIELD: problem" (bad input, exit 2), never a crash, a hang or an internal error.
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace tcsb {

/// Bounds on one JSON input file.
struct JsonLimits {
  std::size_t max_bytes;  ///< larger files are refused before they are read
  int max_depth;          ///< deeper nesting of arrays and objects is refused while parsing
};

/// The deepest nesting any tcsb file needs is 6 (a result: case, repetitions, samples); 64 leaves room for growth
/// while keeping the parser, the schema check and dump() (which all recurse) far from the stack's end.
inline constexpr int kMaxJsonDepth = 64;
/// Suites and the paper's numbers are hand-written (the bundled ones are about 2 KiB): 16 MiB is a generous bound.
inline constexpr JsonLimits kSuiteJsonLimits{std::size_t{16} << 20, kMaxJsonDepth};
/// A result holds every repetition's per-step samples: the CI baseline is 120 KiB, a long paper run a few MiB.
/// 256 MiB stays parseable in memory (nlohmann needs roughly 4-8x the text) on a machine that can run the suite.
inline constexpr JsonLimits kResultJsonLimits{std::size_t{256} << 20, kMaxJsonDepth};

/// The bytes of `path`, which must be a regular file of at most `max_bytes` bytes. A FIFO, a device (/dev/zero), a
/// directory or a missing file is refused by name; a FIFO is never opened for reading, so it cannot hang.
std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes);

/// Parses `text` (the contents of `file`, named in errors) as one JSON document within `limits.max_depth`. Refuses
/// malformed JSON (with the parser's position), anything but whitespace after the document (a NUL byte included),
/// duplicate keys (nlohmann would silently keep the last), and numbers that overflow a double (1e309), naming the
/// field being read where there is one ("nets[2].mass.total").
template <class Json>
Json parse_json_text(const std::string& text, const std::string& file, int max_depth = kMaxJsonDepth);

/// read_input_file, then parse_json_text.
template <class Json>
Json read_json_file(const std::filesystem::path& path, const JsonLimits& limits) {
  return parse_json_text<Json>(read_input_file(path, limits.max_bytes), path.string(), limits.max_depth);
}

extern template nlohmann::json parse_json_text<nlohmann::json>(const std::string&, const std::string&, int);
extern template nlohmann::ordered_json parse_json_text<nlohmann::ordered_json>(const std::string&, const std::string&,
                                                                               int);

}  // namespace tcsb
