// Typed reading of a parsed JSON input (a suite, a result, a shard), every failure an InputError "FILE: FIELD:
// problem" naming the file and the field path ("nets[2].width: must be an integer in [2, 100000], got 1"). One reader
// for every input, so one rule holds everywhere:
//   - an integer is any number without a fractional part (JSON Schema's rule, which the result schema's check
//     applies too), so 3.0 reads as 3; a float is exact as an integer only below 2^53, larger ones are refused;
//   - null is read only where a field may be null (the *_or_null readers, nullopt: nothing was measured); every other
//     reader refuses it like any other wrong type;
//   - a required key that is absent is "required key is missing".
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "base/input_error.h"

namespace tcsb {

/// Shortest text that reads back as `v` ("0.5", "1e-06").
std::string fmt_number(double v);

/// A JSON value as it appears in error messages: short, one line, with its type when that is the problem.
template <class Json>
std::string describe(const Json& j);

/// "parent.key", or "key" at the top level.
std::string key_path(const std::string& parent, std::string_view key);
/// "parent[i]".
inline std::string index_path(const std::string& parent, std::size_t i) {
  return parent + "[" + std::to_string(i) + "]";
}

/// A range of real numbers for messages and checks; infinite bounds print as ">= lo" / "> lo".
struct NumberRange {
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

/// Any finite number: what a measured value in a result may be.
inline constexpr NumberRange kAnyFinite{-std::numeric_limits<double>::infinity(), true};

/// Whether an array read by JsonFields::array may be empty.
enum class EmptyArray { kRefused, kAllowed };

/// Typed access to one parsed document (`Json` is nlohmann::json or nlohmann::ordered_json) that throws InputError
/// naming the file and the field. Two ways in: a value at a path (`integer(j, "nets[0].width", 2, 100000)`), or a
/// member of an object at a path (`integer(object, "nets[0]", "width", 2, 100000)`), which also names a missing key.
template <class Json>
class JsonFields {
 public:
  explicit JsonFields(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(file_, field, problem);
  }

  // ---- a value at `path`
  /// An integer in [lo, hi] (see the rule above).
  std::int64_t integer(const Json& j, const std::string& path, std::int64_t lo, std::int64_t hi) const;
  /// An integer in [0, 2^64).
  std::uint64_t unsigned_integer(const Json& j, const std::string& path) const;
  double number(const Json& j, const std::string& path, const NumberRange& range) const;
  /// number(), or nullopt for null.
  std::optional<double> number_or_null(const Json& j, const std::string& path, const NumberRange& range) const;
  bool boolean(const Json& j, const std::string& path) const;
  std::string string(const Json& j, const std::string& path) const;
  const Json& array(const Json& j, const std::string& path, EmptyArray empty = EmptyArray::kRefused) const;
  const Json& object(const Json& j, const std::string& path) const;
  /// An array of exactly `n` numbers in `range`.
  template <std::size_t n>
  std::array<double, n> numbers(const Json& j, const std::string& path, const NumberRange& range) const {
    if (!j.is_array() || j.size() != n) {
      fail(path, "must be an array of " + std::to_string(n) + " numbers, got " + describe(j));
    }
    std::array<double, n> out{};
    for (std::size_t i = 0; i < n; ++i) out[i] = number(j[i], index_path(path, i), range);
    return out;
  }
  /// One of `options` (an enum spelled as a string).
  template <class E>
  E choice(const Json& j, const std::string& path,
           std::initializer_list<std::pair<std::string_view, E>> options) const {
    return choice(j, path, std::span<const std::pair<std::string_view, E>>(options.begin(), options.size()));
  }
  template <class E>
  E choice(const Json& j, const std::string& path, std::span<const std::pair<std::string_view, E>> options) const {
    if (j.is_string()) {
      for (const auto& [name, value] : options) {
        if (j.template get<std::string>() == name) return value;
      }
    }
    std::string list;
    for (const auto& option : options) list += (list.empty() ? "\"" : ", \"") + std::string(option.first) + "\"";
    fail(path, "must be one of " + list + ", got " + describe(j));
  }

  // ---- the member `key` of the object `parent` at `path`
  /// The member; fails when `parent` is not an object or has no `key`.
  const Json& member(const Json& parent, const std::string& path, std::string_view key) const;
  /// The member, or nullptr when absent; fails when `parent` is not an object.
  const Json* find(const Json& parent, const std::string& path, std::string_view key) const;
  const Json& object(const Json& parent, const std::string& path, std::string_view key) const {
    return object(member(parent, path, key), key_path(path, key));
  }
  const Json& array(const Json& parent, const std::string& path, std::string_view key) const {
    return array(member(parent, path, key), key_path(path, key), EmptyArray::kAllowed);
  }
  std::string string(const Json& parent, const std::string& path, std::string_view key) const {
    return string(member(parent, path, key), key_path(path, key));
  }
  double number(const Json& parent, const std::string& path, std::string_view key, const NumberRange& range) const {
    return number(member(parent, path, key), key_path(path, key), range);
  }
  std::int64_t integer(const Json& parent, const std::string& path, std::string_view key,
                       std::int64_t lo = std::numeric_limits<std::int64_t>::min(),
                       std::int64_t hi = std::numeric_limits<std::int64_t>::max()) const {
    return integer(member(parent, path, key), key_path(path, key), lo, hi);
  }
  /// A step number or other count that may be null: an integer in [0, INT_MAX], or nullopt.
  std::optional<int> integer_or_null(const Json& parent, const std::string& path, std::string_view key) const {
    const Json& j = member(parent, path, key);
    if (j.is_null()) return std::nullopt;
    return static_cast<int>(integer(j, key_path(path, key), 0, std::numeric_limits<int>::max()));
  }
  /// A finite number, or nullopt for null (the files write null where nothing was measured).
  std::optional<double> number_or_null(const Json& parent, const std::string& path, std::string_view key) const {
    return number_or_null(member(parent, path, key), key_path(path, key), kAnyFinite);
  }
  /// number_or_null that is also >= 0: a count or a mean of counts (N, L, I), a time or a spread is never negative.
  std::optional<double> non_negative_or_null(const Json& parent, const std::string& path, std::string_view key) const {
    return number_or_null(member(parent, path, key), key_path(path, key), NumberRange{0.0, false});
  }

 private:
  std::string file_;
};

extern template class JsonFields<nlohmann::json>;
extern template class JsonFields<nlohmann::ordered_json>;
extern template std::string describe<nlohmann::json>(const nlohmann::json&);
extern template std::string describe<nlohmann::ordered_json>(const nlohmann::ordered_json&);

}  // namespace tcsb
