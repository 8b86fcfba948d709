// The JSON Schema subset: each keyword accepts what it should and names what it rejects; schemas using anything
// else are refused instead of half-checked.
#include "base/json_schema_check.h"

#include <gtest/gtest.h>

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

std::vector<std::string> problems(const char* document, const char* schema) {
  std::vector<std::string> out;
  for (const SchemaViolation& v : check_against_schema(ojson::parse(document), ojson::parse(schema))) {
    out.push_back(describe(v));
  }
  return out;
}

using Lines = std::vector<std::string>;

TEST(JsonSchemaCheck, Types) {
  EXPECT_EQ(problems("3", R"({"type": "integer"})"), Lines{});
  EXPECT_EQ(problems("3.0", R"({"type": "integer"})"), Lines{}) << "an integral number is an integer";
  EXPECT_EQ(problems("3.5", R"({"type": "integer"})"), Lines{"must be of type integer, got number"});
  EXPECT_EQ(problems("3", R"({"type": "number"})"), Lines{});
  EXPECT_EQ(problems("\"3\"", R"({"type": "number"})"), Lines{"must be of type number, got string"});
  EXPECT_EQ(problems("null", R"({"type": ["number", "null"]})"), Lines{});
  EXPECT_EQ(problems("true", R"({"type": ["number", "null"]})"),
            Lines{"must be of type [\"number\",\"null\"], got boolean"});
  EXPECT_EQ(problems("[]", R"({"type": "object"})"), Lines{"must be of type object, got array"});
}

TEST(JsonSchemaCheck, EnumAndConst) {
  EXPECT_EQ(problems("\"ok\"", R"({"enum": ["ok", "diverged"]})"), Lines{});
  EXPECT_EQ(problems("\"bad\"", R"({"enum": ["ok", "diverged"]})"),
            Lines{"must be one of [\"ok\",\"diverged\"], got \"bad\""});
  EXPECT_EQ(problems("2", R"({"enum": [2]})"), Lines{});
  EXPECT_EQ(problems("1", R"({"enum": [2]})"), Lines{"must be one of [2], got 1"});
  EXPECT_EQ(problems("\"tcsb\"", R"({"const": "tcsb"})"), Lines{});
  EXPECT_EQ(problems("\"x\"", R"({"const": "tcsb"})"), Lines{"must be \"tcsb\", got \"x\""});
}

TEST(JsonSchemaCheck, RangesAndLengths) {
  EXPECT_EQ(problems("0", R"({"minimum": 0, "maximum": 1})"), Lines{});
  EXPECT_EQ(problems("-1", R"({"minimum": 0})"), Lines{"must be >= 0, got -1"});
  EXPECT_EQ(problems("1.5", R"({"maximum": 1})"), Lines{"must be <= 1, got 1.5"});
  EXPECT_EQ(problems("\"abc\"", R"({"minLength": 3, "maxLength": 3})"), Lines{});
  EXPECT_EQ(problems("\"ab\"", R"({"minLength": 3})"), Lines{"must have at least 3 characters, got 2"});
  EXPECT_EQ(problems("\"h\u00e9\u00e9\"", R"({"maxLength": 3})"), Lines{}) << "characters, not bytes";
  EXPECT_EQ(problems("[1]", R"({"minItems": 2})"), Lines{"must have at least 2 entries, got 1"});
}

TEST(JsonSchemaCheck, ObjectsNameTheFieldPath) {
  const char* schema = R"({
    "type": "object", "required": ["a", "b"], "additionalProperties": false,
    "properties": {
      "a": {"type": "array", "items": {"type": "object", "required": ["x"],
                                       "properties": {"x": {"type": "string"}}}},
      "b": {"type": "integer"}
    }})";
  EXPECT_EQ(problems(R"({"a": [{"x": "s"}], "b": 1})", schema), Lines{});
  EXPECT_EQ(problems(R"({"a": [{"x": "s"}, {"x": 5}, {}], "c": 1})", schema),
            (Lines{"b: missing (required)", "a[1].x: must be of type string, got integer", "a[2].x: missing (required)",
                   "c: unexpected key"}));
}

TEST(JsonSchemaCheck, AdditionalPropertiesAsASchema) {
  const char* schema = R"({"type": "object", "additionalProperties": {"type": "number"}})";
  EXPECT_EQ(problems(R"({"p": 1, "q": 2.5})", schema), Lines{});
  EXPECT_EQ(problems(R"({"p": "1"})", schema), Lines{"p: must be of type number, got string"});
  EXPECT_EQ(problems(R"({"anything": [1, "x"]})", R"({"type": "object"})"), Lines{}) << "open by default";
}

TEST(JsonSchemaCheck, RefsAndBooleanSchemas) {
  const char* schema = R"({
    "$defs": {"nn": {"type": ["number", "null"]}},
    "properties": {"a": {"$ref": "#/$defs/nn"}, "b": false, "c": true}})";
  EXPECT_EQ(problems(R"({"a": null, "c": [1]})", schema), Lines{});
  EXPECT_EQ(problems(R"({"a": "x", "b": 1})", schema),
            (Lines{"a: must be of type [\"number\",\"null\"], got string", "b: is not allowed here"}));
}

TEST(JsonSchemaCheck, UnsupportedSchemasAreRefused) {
  EXPECT_THROW(problems("1", R"({"pattern": "^a"})"), SchemaError) << "a keyword we do not check";
  EXPECT_THROW(problems("1", R"({"properties": {"a": {"oneOf": []}}})"), SchemaError) << "nested";
  EXPECT_THROW(problems("1", R"({"$defs": {"x": {"format": "date"}}})"), SchemaError) << "even if unused";
  EXPECT_THROW(problems("1", R"({"type": "float"})"), SchemaError);
  EXPECT_THROW(problems("1", R"({"$ref": "#/$defs/missing"})"), SchemaError);
  EXPECT_THROW(problems("1", R"({"$ref": "other.json#/x"})"), SchemaError);
  EXPECT_THROW(problems("1", R"({"$defs": {"a": {"$ref": "#/$defs/a"}}, "$ref": "#/$defs/a"})"), SchemaError)
      << "a reference cycle";
  EXPECT_THROW(problems("1", R"({"minLength": -1})"), SchemaError);
  EXPECT_THROW(problems("1", "[]"), SchemaError);
  EXPECT_EQ(problems("1", R"({"title": "t", "description": "d", "$comment": "c", "$schema": "s"})"), Lines{})
      << "annotations are fine";
}

}  // namespace
}  // namespace tcsb
