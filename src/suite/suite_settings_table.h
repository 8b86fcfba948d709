// The suite's scalar settings, each written once: its path in the suite file, the Suite member it sets, its range,
// whether a sweep axis may vary it and when the result's suite block records it. The suite reader's allowed keys and
// reads, the axes (suite_axes.h), the result's suite block (report/json_report.h) and the check of the result schema's
// suite properties (tests/report/suite_settings_schema_test.cpp) all come from here, so adding a setting is its
// member, its row and its user (docs/design.md, "Adding a suite setting"). Structured blocks (nets, the scene, the
// material, fidelity) keep readers of their own.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "suite/suite.h"
#include "suite/suite_fields.h"

namespace tcsb {

/// What a setting holds, from its member's type.
enum class SettingType { kInteger, kUnsigned, kNumber, kBoolean, kChoice, kDirection };

/// When the result's suite block records a setting. Every rule but kAlways keeps the blocks of suites that do not
/// use a setting as they were before it existed, so their results still compare with older baselines.
enum class Written {
  kAlways,
  kUnlessDefault,  ///< only when it differs from a default Suite's
  kWithView,       ///< only when feedback.view is on (the view terms' parameters)
  kNever,          ///< never in the suite block (the seed is the context's)
};

/// One option of a choice: its name in the file and its enumerator's value.
using SettingChoice = std::pair<std::string_view, int>;

/// What a setting's value may be: an integer's bounds, a number's (or a direction's coordinates') range, or a
/// choice's options in the order messages list them.
struct SettingRange {
  long long lo = 0, hi = 0;
  NumberRange numbers{0.0, false};
  std::span<const SettingChoice> choices;
};

struct SuiteSetting;

/// SuiteSetting::axis of a setting no sweep axis may vary.
inline constexpr int kNoAxis = 0;

/// The member a setting sets: its type and typed access through type-erased functions (made by suite_member).
struct SettingMember {
  SettingType type;
  /// Reads `value` into the member of `suite`, checked against the row's range; `at` names it in errors.
  void (*read)(const SuiteSetting& row, const suite_fields::Reader& r, const nlohmann::json& value,
               const std::string& at, Suite& suite);
  /// The member's value as the suite file spells it (a choice by name); numbers unrounded.
  nlohmann::ordered_json (*value)(const SuiteSetting& row, const Suite& suite);
  /// Whether `suite` holds a default Suite's value.
  bool (*is_default)(const Suite& suite);
};

/// One row of the table.
struct SuiteSetting {
  std::string_view path;  ///< "feedback.view_static_share": the section's name, a dot, the key; root keys bare
  SettingMember member;
  SettingRange range;
  /// kNoAxis, or its place in configuration labels: a sweep axis may vary it (suite_axes.h says which may).
  int axis = kNoAxis;
  bool required = false;
  Written written = Written::kAlways;
  /// What else a value of the setting decides, applied after each read (e.g. dt is also the compliant step).
  void (*then)(Suite& suite) = nullptr;

  /// "feedback", or "" for a key of the suite's root.
  std::string_view section() const;
  /// "view_static_share".
  std::string_view key() const;
};

/// Every row, in the order the result's suite block lists them (and the file's messages list keys).
std::span<const SuiteSetting> suite_settings();

/// The row of `path`, or nullptr.
const SuiteSetting* find_suite_setting(std::string_view path);

/// The keys of `section`'s rows ("" for the root's), in table order: what that object of the suite file accepts.
std::vector<std::string_view> suite_setting_keys(std::string_view section);

/// Reads `value` into `suite` as the row's setting, with its checks, then what the setting also decides.
void read_suite_setting(const SuiteSetting& row, const suite_fields::Reader& r, const nlohmann::json& value,
                        const std::string& at, Suite& suite);

/// Reads the rows of `section` present in `object` (that section of the suite file) into `suite`, in table order;
/// a missing required one is an error, a missing optional one leaves the default.
void read_suite_settings(const suite_fields::Reader& r, const suite_fields::Object& object, std::string_view section,
                         Suite& suite);

/// Whether the result's suite block records `row` for `suite` (its Written rule).
bool suite_setting_written(const SuiteSetting& row, const Suite& suite);

}  // namespace tcsb
