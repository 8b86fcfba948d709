#include "base/json_fields.h"

#include <charconv>

namespace tcsb {
namespace {

/// Integral and below 2^53, so a float's conversion to an integer is exact.
bool is_exact_integer(double d) { return std::trunc(d) == d && std::abs(d) < 0x1p53; }

}  // namespace

std::string fmt_number(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

template <class Json>
std::string describe(const Json& j) {
  std::string text;
  if (j.is_string())
    text = "string " + j.dump();
  else if (j.is_object())
    text = "an object";
  else if (j.is_array())
    text = "an array";
  else
    text = j.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

std::string key_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

template <class Json>
std::int64_t JsonFields<Json>::integer(const Json& j, const std::string& path, std::int64_t lo, std::int64_t hi) const {
  // The message is built only on failure: a column of a shard reads millions of integers.
  const auto want = [&] {
    const bool any = lo == std::numeric_limits<std::int64_t>::min() && hi == std::numeric_limits<std::int64_t>::max();
    return "must be an integer" +
           (any ? std::string() : " in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  };
  std::int64_t v = 0;
  if (j.is_number_unsigned()) {
    const auto u = j.template get<std::uint64_t>();
    if (hi < 0 || u > static_cast<std::uint64_t>(hi)) fail(path, want() + ", got " + j.dump());
    v = static_cast<std::int64_t>(u);
  } else if (j.is_number_integer()) {
    v = j.template get<std::int64_t>();
  } else if (j.is_number_float() && is_exact_integer(j.template get<double>())) {
    v = static_cast<std::int64_t>(j.template get<double>());  // 3.0 is an integer in JSON
  } else {
    fail(path, want() + ", got " + describe(j));
  }
  if (v < lo || v > hi) fail(path, want() + ", got " + j.dump());
  return v;
}

template <class Json>
std::uint64_t JsonFields<Json>::unsigned_integer(const Json& j, const std::string& path) const {
  if (j.is_number_unsigned()) return j.template get<std::uint64_t>();
  if (j.is_number_integer() && j.template get<std::int64_t>() >= 0) return j.template get<std::uint64_t>();
  if (j.is_number_float() && j.template get<double>() >= 0 && is_exact_integer(j.template get<double>())) {
    return static_cast<std::uint64_t>(j.template get<double>());
  }
  fail(path, "must be a non-negative integer, got " + describe(j));
}

template <class Json>
double JsonFields<Json>::number(const Json& j, const std::string& path, const NumberRange& range) const {
  if (!j.is_number()) fail(path, "must be " + range.text() + ", got " + describe(j));
  const auto v = j.template get<double>();
  if (!range.contains(v)) fail(path, "must be " + range.text() + ", got " + j.dump());
  return v;
}

template <class Json>
std::optional<double> JsonFields<Json>::number_or_null(const Json& j, const std::string& path,
                                                       const NumberRange& range) const {
  if (j.is_null()) return std::nullopt;
  if (!j.is_number() || !range.contains(j.template get<double>())) {
    fail(path, "must be " + range.text() + " or null, got " + describe(j));
  }
  return j.template get<double>();
}

template <class Json>
bool JsonFields<Json>::boolean(const Json& j, const std::string& path) const {
  if (!j.is_boolean()) fail(path, "must be true or false, got " + describe(j));
  return j.template get<bool>();
}

template <class Json>
std::string JsonFields<Json>::string(const Json& j, const std::string& path) const {
  if (!j.is_string()) fail(path, "must be a string, got " + describe(j));
  return j.template get<std::string>();
}

template <class Json>
const Json& JsonFields<Json>::array(const Json& j, const std::string& path, EmptyArray empty) const {
  if (!j.is_array()) fail(path, "must be an array, got " + describe(j));
  if (empty == EmptyArray::kRefused && j.empty()) fail(path, "must not be empty");
  return j;
}

template <class Json>
const Json& JsonFields<Json>::object(const Json& j, const std::string& path) const {
  if (!j.is_object()) fail(path, "must be an object, got " + describe(j));
  return j;
}

template <class Json>
const Json* JsonFields<Json>::find(const Json& parent, const std::string& path, std::string_view key) const {
  object(parent, path);
  const auto it = parent.find(std::string(key));
  return it == parent.end() ? nullptr : &*it;
}

template <class Json>
const Json& JsonFields<Json>::member(const Json& parent, const std::string& path, std::string_view key) const {
  const Json* j = find(parent, path, key);
  if (j == nullptr) fail(key_path(path, key), "required key is missing");
  return *j;
}

template class JsonFields<nlohmann::json>;
template class JsonFields<nlohmann::ordered_json>;
template std::string describe<nlohmann::json>(const nlohmann::json&);
template std::string describe<nlohmann::ordered_json>(const nlohmann::ordered_json&);

}  // namespace tcsb
