// Suite fields: the vocabulary a suite's JSON is read in — the typed reader of every input (base/json_fields.h), the
// ranges the suite's fields share, and an object reader that refuses unknown keys. The suite's keys themselves are in
// suite.cpp, the block readers and suite_settings_table.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "base/json_fields.h"
#include "suite/suite.h"

namespace tcsb::suite_fields {

using json = nlohmann::json;

using tcsb::describe;
using tcsb::fmt_number;
using tcsb::index_path;
using tcsb::kAnyFinite;
using tcsb::key_path;
using tcsb::NumberRange;

/// The ranges the suite's fields share.
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr NumberRange kPositive{0.0, true}, kNonNegative{0.0, false};
inline constexpr NumberRange kFraction{0.0, true, 1.0, false};  // (0, 1]
inline constexpr NumberRange kUnit{0.0, false, 1.0, false};     // [0, 1]

/// What Bullet can represent: it computes in single precision (at most 3.4e38; squares overflow beyond 1.8e19; its
/// own "infinite" is BT_LARGE_FLOAT, 1e18), so a scene's coordinates, lengths and speeds are bounded far below that,
/// at a thousand kilometres (float's spacing there is 6 cm, coarser than any cloth's links), and its other
/// quantities (masses, coefficients, densities, gravity) at 1e9. Beyond, a sphere of radius 1e39 was infinite and
/// collided with nothing, and a normal of [0, 1e155, 0] overflowed to the zero vector.
inline constexpr double kMaxSceneLength = 1e6, kMaxSceneQuantity = 1e9;
inline constexpr NumberRange kSceneCoordinate{-kMaxSceneLength, false, kMaxSceneLength, false};
inline constexpr NumberRange kSceneLength{0.0, true, kMaxSceneLength, false};          // (0, 1e6]
inline constexpr NumberRange kSceneQuantity{0.0, true, kMaxSceneQuantity, false};      // (0, 1e9]
inline constexpr NumberRange kSceneNonNegative{0.0, false, kMaxSceneQuantity, false};  // [0, 1e9]

/// Typed access to a suite's JSON (base/json_fields.h: the one reader of every input and its rules).
using Reader = JsonFields<json>;

/// One JSON object at `path`: rejects keys outside `allowed`, then reads members, building their paths for errors.
/// The read() overloads leave `out` alone when an optional key is absent, so the struct's default stands.
class Object {
 public:
  Object(const Reader& r, const json& j, std::string path, std::initializer_list<std::string_view> allowed)
      : Object(r, j, std::move(path), std::span<const std::string_view>(allowed.begin(), allowed.size())) {}
  Object(const Reader& r, const json& j, std::string path, std::span<const std::string_view> allowed)
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
  void read(const char* key, double& out, const NumberRange& range, bool required = false) const {
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
