// The result schema's suite properties and the suite settings table (suite/suite_settings_table.h) agree: every
// setting the suite block may record is a property of its section with a fitting type, required only if always
// written, and every scalar property is a setting of the table. A setting added on one side only fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "result/result_schema.h"
#include "suite/suite_settings_table.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// The suite block's keys that are not settings of the table: its identity and the structured blocks.
const std::set<std::string> kSuiteBlockStructure = {"name",    "description", "path",     "sha256",  "nets",
                                                    "methods", "compression", "material", "scene",   "fidelity",
                                                    "axes",    "solver",      "tcsb",     "feedback"};

bool is_ref(const ojson& property, const char* def) {
  return property.value("$ref", "") == std::string("#/$defs/") + def;
}

/// Why `property` cannot hold what `row` writes ("" when it can).
std::string type_mismatch(const SuiteSetting& row, const ojson& property) {
  switch (row.member.type) {
    case SettingType::kInteger:
    case SettingType::kUnsigned:
      if (property.value("type", "") == "integer" || is_ref(property, "count")) return "";
      return "an integer setting needs an integer property";
    case SettingType::kNumber:
      return is_ref(property, "number_or_null") ? "" : "a number setting needs #/$defs/number_or_null";
    case SettingType::kBoolean:
      if (property.value("type", "") == "boolean") return "";
      if (property.contains("const") && property["const"].is_boolean()) return "";
      return "a flag needs a boolean property";
    case SettingType::kChoice: {
      const ojson names =
          property.contains("enum") ? property["enum"] : ojson::array({property.value("const", ojson())});
      for (const ojson& name : names) {
        const auto known = [&](const SettingChoice& c) {
          return name.is_string() && name.get<std::string>() == c.first;
        };
        if (std::none_of(row.range.choices.begin(), row.range.choices.end(), known))
          return "the schema allows " + name.dump() + ", which is not one of the setting's choices";
      }
      return "";
    }
    case SettingType::kDirection:
      if (property.value("type", "") == "array" && property.value("minItems", 0) == 3) return "";
      return "a direction needs an array of 3";
  }
  return "unknown setting type";
}

/// Where the result schema's suite definition `suite` and the settings table disagree, one line each.
std::vector<std::string> disagreements(const ojson& suite) {
  std::vector<std::string> out;
  const auto section_of = [&](std::string_view section) -> const ojson& {
    return section.empty() ? suite : suite["properties"][std::string(section)];
  };
  std::set<std::string> sections = {""};
  for (const SuiteSetting& row : suite_settings()) {
    sections.insert(std::string(row.section()));
    if (row.written == Written::kNever) continue;
    const ojson& schema = section_of(row.section());
    const std::string key(row.key()), path(row.path);
    if (!schema["properties"].contains(key)) {
      out.push_back(path + ": written, but not in the schema");
      continue;
    }
    if (const std::string why = type_mismatch(row, schema["properties"][key]); !why.empty())
      out.push_back(path + ": " + why);
    // Required only if always written (a result without it is no result); a setting always written now may still be
    // optional, for results written before it existed.
    const ojson& required = schema.value("required", ojson::array());
    if (std::find(required.begin(), required.end(), ojson(key)) != required.end() && row.written != Written::kAlways)
      out.push_back(path + ": required by the schema, but written only when it matters");
  }
  for (const std::string& section : sections)
    for (const auto& [key, property] : section_of(section)["properties"].items()) {
      if (section.empty() && kSuiteBlockStructure.count(key)) continue;
      const std::string path = section.empty() ? key : section + "." + key;
      const SuiteSetting* row = find_suite_setting(path);
      if (!row || row->written == Written::kNever) out.push_back(path + ": in the schema, but no written setting");
    }
  return out;
}

const ojson& schema_suite() { return result_schema()["$defs"]["suite"]; }

TEST(SuiteSettingsSchema, SchemaAndTableAgree) { EXPECT_EQ(disagreements(schema_suite()), std::vector<std::string>{}); }

TEST(SuiteSettingsSchema, ASettingOnOneSideOnlyIsFound) {
  ojson extra = schema_suite();
  extra["properties"]["feedback"]["properties"]["view_blur_px"] = {{"$ref", "#/$defs/number_or_null"}};
  EXPECT_EQ(disagreements(extra),
            std::vector<std::string>{"feedback.view_blur_px: in the schema, but no written setting"});
  ojson missing = schema_suite();
  missing["properties"]["feedback"]["properties"].erase("view_static_share");
  EXPECT_EQ(disagreements(missing),
            std::vector<std::string>{"feedback.view_static_share: written, but not in the schema"});
}

TEST(SuiteSettingsSchema, ATypeOrRequirementThatDiffersIsFound) {
  ojson typed = schema_suite();
  typed["properties"]["solver"]["properties"]["piterations"] = {{"type", "boolean"}};
  EXPECT_EQ(disagreements(typed),
            std::vector<std::string>{"solver.piterations: an integer setting needs an integer property"});
  ojson required = schema_suite();
  required["properties"]["tcsb"]["required"].push_back("start_level");
  EXPECT_EQ(disagreements(required),
            std::vector<std::string>{"tcsb.start_level: required by the schema, but written only when it matters"});
}

}  // namespace
}  // namespace tcsb
