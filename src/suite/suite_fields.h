// Suite fields: typed reading of a suite's JSON, every failure an InputError naming the file and the field path
// ("nets[2].width: must be an integer in [2, 100000], got 1"). The suite's schema itself is in suite.cpp; this is
// only the vocabulary it is written in.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>

#include "suite/suite.h"

namespace tcsb::suite_fields {

using json = nlohmann::json;

/// Shortest text that reads back as `v` ("0.5", "1e-06").
std::string fmt_number(double v);

/// A JSON value as it appears in error messages: short, one line, with its type when that is the problem.
std::string describe(const json& j);

/// "parent.key", or "key" at the top level.
std::string key_path(const std::string& parent, std::string_view key);
/// "parent[i]".
inline std::string index_path(const std::string& parent, std::size_t i) {
  return parent + "[" + std::to_string(i) + "]";
}

/// A range of real numbers for messages and checks; infinite bounds print as ">= lo" / "> lo".
struct Interval {
  double lo;
  bool lo_open;
  double hi = std::numeric_limits<double>::infinity();
  bool hi_open = true;
  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    if (std::isinf(lo) && std::isinf(hi)) return "a finite number";
    if (std::isinf(hi)) return "a finite number " + std::string(lo_open ? "> " : ">= ") + fmt_number(lo);
    return "a number in " + std::string(lo_open ? "(" : "[") + fmt_number(lo) + ", " + fmt_number(hi) +
           (hi_open ? ")" : "]");
  }
};

/// The ranges the suite's fields share.
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr Interval kPositive{0.0, true}, kNonNegative{0.0, false}, kAnyFinite{-kInfinity, true};
inline constexpr Interval kFraction{0.0, true, 1.0, false};  // (0, 1]
inline constexpr Interval kUnit{0.0, false, 1.0, false};     // [0, 1]

/// Typed access to a JSON document that throws InputError naming the file and the field.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(file_, field, problem);
  }

  long long integer(const json& j, const std::string& path, long long lo, long long hi) const {
    const std::string want = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
    if (!j.is_number_integer()) fail(path, want + describe(j));
    if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) fail(path, want + j.dump());
    const long long v = j.get<long long>();
    if (v < lo || v > hi) fail(path, want + j.dump());
    return v;
  }
  std::uint64_t unsigned_integer(const json& j, const std::string& path) const {
    if (!j.is_number_integer() || (!j.is_number_unsigned() && j.get<long long>() < 0)) {
      fail(path, "must be a non-negative integer, got " + describe(j));
    }
    return j.get<std::uint64_t>();
  }
  double number(const json& j, const std::string& path, const Interval& range) const {
    if (!j.is_number()) fail(path, "must be " + range.text() + ", got " + describe(j));
    const double v = j.get<double>();
    if (!range.contains(v)) fail(path, "must be " + range.text() + ", got " + j.dump());
    return v;
  }
  bool boolean(const json& j, const std::string& path) const {
    if (!j.is_boolean()) fail(path, "must be true or false, got " + describe(j));
    return j.get<bool>();
  }
  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "must be a string, got " + describe(j));
    return j.get<std::string>();
  }
  const json& array(const json& j, const std::string& path, bool allow_empty = false) const {
    if (!j.is_array()) fail(path, "must be an array, got " + describe(j));
    if (!allow_empty && j.empty()) fail(path, "must not be empty");
    return j;
  }
  /// An array of exactly `n` numbers in `range`.
  template <std::size_t n>
  std::array<double, n> numbers(const json& j, const std::string& path, const Interval& range) const {
    if (!j.is_array() || j.size() != n) {
      fail(path, "must be an array of " + std::to_string(n) + " numbers, got " + describe(j));
    }
    std::array<double, n> out{};
    for (std::size_t i = 0; i < n; ++i) out[i] = number(j[i], index_path(path, i), range);
    return out;
  }
  /// One of `options` (an enum spelled as a string).
  template <class E>
  E choice(const json& j, const std::string& path,
           std::initializer_list<std::pair<std::string_view, E>> options) const {
    if (j.is_string()) {
      for (const auto& [name, value] : options) {
        if (j.get<std::string>() == name) return value;
      }
    }
    std::string list;
    for (const auto& option : options) list += (list.empty() ? "\"" : ", \"") + std::string(option.first) + "\"";
    fail(path, "must be one of " + list + ", got " + describe(j));
  }

 private:
  std::string file_;
};

/// One JSON object at `path`: rejects keys outside `allowed`, then reads members, building their paths for errors.
/// The read() overloads leave `out` alone when an optional key is absent, so the struct's default stands.
class Object {
 public:
  Object(const Reader& r, const json& j, std::string path, std::initializer_list<std::string_view> allowed)
      : r_(r), j_(j), path_(std::move(path)) {
    if (!j.is_object()) r.fail(path_, "must be an object, got " + describe(j));
    for (const auto& item : j.items()) {
      if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
      std::string list;
      for (const std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      r.fail(at(item.key()), "unknown key (expected one of: " + list + ")");
    }
  }
  std::string at(std::string_view key) const { return key_path(path_, key); }
  /// The member `key`, or nullptr; with `required`, a missing key is an error.
  const json* find(const char* key, bool required = false) const {
    const auto it = j_.find(key);
    if (it != j_.end()) return &*it;
    if (required) r_.fail(at(key), "required key is missing");
    return nullptr;
  }
  const json& need(const char* key) const { return *find(key, true); }

  void read(const char* key, int& out, long long lo, long long hi, bool required = false) const {
    if (const json* v = find(key, required)) out = static_cast<int>(r_.integer(*v, at(key), lo, hi));
  }
  void read(const char* key, double& out, const Interval& range, bool required = false) const {
    if (const json* v = find(key, required)) out = r_.number(*v, at(key), range);
  }
  void read(const char* key, bool& out) const {
    if (const json* v = find(key)) out = r_.boolean(*v, at(key));
  }
  template <class E>
  void read(const char* key, E& out, std::initializer_list<std::pair<std::string_view, E>> options) const {
    if (const json* v = find(key)) out = r_.choice(*v, at(key), options);
  }

 private:
  const Reader& r_;
  const json& j_;
  std::string path_;
};

}  // namespace tcsb::suite_fields
