// The suite settings table: every row is read from its section of the suite file and reads back the value it
// writes, paths and axis places are unique, and the axes are its axis rows in label order.
#include "suite/suite_settings_table.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "../world/world_suite_json.h"
#include "small_suite_json.h"
#include "suite/suite_axes.h"

namespace tcsb {
namespace {

using json = nlohmann::json;

/// `suite` with `value` at the row's place in the file.
json with_setting(json suite, const SuiteSetting& row, const json& value) {
  json& object = row.section().empty() ? suite : suite[std::string(row.section())];
  object[std::string(row.key())] = value;
  return suite;
}

TEST(SuiteSettingsTable, EveryRowReadsBackTheValueItWrites) {
  const Suite defaults;
  for (const SuiteSetting& row : suite_settings()) {
    const json written = json::parse(row.member.value(row, defaults).dump());
    const Suite parsed = parse_suite_text(with_setting(testing::small_suite_json(), row, written).dump(), "table.json");
    EXPECT_EQ(row.member.value(row, parsed), row.member.value(row, defaults)) << row.path;
  }
}

/// A value the row accepts that is not `current`.
json other_value(const SuiteSetting& row, const json& current) {
  switch (row.member.type) {
    case SettingType::kBoolean: return !current.get<bool>();
    case SettingType::kChoice:
      for (const SettingChoice& c : row.range.choices)
        if (current != c.first) return c.first;
      break;
    case SettingType::kDirection: return current == json{0.0, 0.0, 1.0} ? json{1.0, 0.0, 0.0} : json{0.0, 0.0, 1.0};
    case SettingType::kUnsigned: return current.get<std::uint64_t>() + 1;
    case SettingType::kInteger: return current == row.range.lo ? row.range.lo + 1 : row.range.lo;
    case SettingType::kNumber: return current == 0.25 ? 0.5 : 0.25;
  }
  ADD_FAILURE() << row.path << " has no other value";
  return current;
}

TEST(SuiteSettingsTable, EveryRowSetsItsOwnMember) {
  // A value other than the default: a row pointing at another member would leave its own at the default.
  const Suite base = parse_suite_text(testing::small_suite_json().dump(), "table.json");
  for (const SuiteSetting& row : suite_settings()) {
    const json other = other_value(row, json::parse(row.member.value(row, base).dump()));
    json suite = with_setting(testing::small_suite_json(), row, other);
    // What some settings need beside them (suite.cpp refuses them alone).
    if (row.path == "interleave_across_nets") suite["interleave_steps"] = 4;
    if (row.path == "feedback.view")
      suite["scene"] = json::parse(R"({"camera": {"position": [0, 20, 30], "target": [0, 7, 0], "up": [0, 1, 0],
                                       "fov_deg": 45, "image": [1280, 720]}})");
    if (row.path == "feedback.interface_tension" || row.path == "feedback.pin_level_pull")
      suite["feedback"]["interface_charge"] = 1;
    if (row.path == "feedback.pin_level_pull") suite["feedback"]["interface_tension"] = 1;
    if (row.path == "feedback.budget_scope") {  // one budget for a scene of bodies, seen by a moving camera
      suite["scene"] = testing::world_suite_json()["scene"];
      suite["nets"][0] = testing::world_suite_json()["nets"][0];
      suite["nets"].erase(1);
    }
    const Suite parsed = parse_suite_text(suite.dump(), "table.json");
    EXPECT_EQ(json::parse(row.member.value(row, parsed).dump()), other) << row.path;
  }
}

TEST(SuiteSettingsTable, PathsAndAxisPlacesAreUnique) {
  std::set<std::string_view> paths;
  std::set<int> places;
  for (const SuiteSetting& row : suite_settings()) {
    EXPECT_TRUE(paths.insert(row.path).second) << row.path;
    if (row.axis != kNoAxis) {
      EXPECT_TRUE(places.insert(row.axis).second) << row.path;
    }
  }
}

TEST(SuiteSettingsTable, AxesAreTheAxisRowsInLabelOrder) {
  std::vector<std::string> expected;
  int last = kNoAxis;
  for (int place = 1; static_cast<std::size_t>(place) <= suite_settings().size(); ++place)
    for (const SuiteSetting& row : suite_settings())
      if (row.axis == place) {
        expected.emplace_back(row.path);
        EXPECT_GT(place, last);
        last = place;
      }
  EXPECT_EQ(axis_setting_paths(), expected);
}

TEST(SuiteSettingsTable, SectionsAcceptExactlyTheirRowsKeys) {
  EXPECT_EQ(suite_setting_keys("solver"),
            (std::vector<std::string_view>{"piterations", "viterations", "diterations", "damping", "stiffness"}));
  json suite = testing::small_suite_json();
  suite["solver"]["iterations"] = 3;
  try {
    parse_suite_text(suite.dump(), "table.json");
    ADD_FAILURE() << "an unknown solver key was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "table.json: solver.iterations: unknown key (expected one of: piterations, viterations, diterations, "
              "damping, stiffness)");
  }
}

}  // namespace
}  // namespace tcsb
