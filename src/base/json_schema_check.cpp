#include "base/json_schema_check.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

// Keywords that only annotate: allowed anywhere, never checked.
const std::set<std::string> kAnnotations = {"$schema",     "$id",      "$comment", "title",
                                            "description", "examples", "default"};
// Keywords this validator implements.
const std::set<std::string> kKeywords = {
    "$defs", "$ref",     "type",    "enum",    "const",     "properties", "required",
    "items", "minItems", "minimum", "maximum", "minLength", "maxLength",  "additionalProperties"};
const std::set<std::string> kTypes = {"object", "array", "string", "number", "integer", "boolean", "null"};
// A $ref that leads to a $ref ... without descending into the document: a cycle in the schema.
constexpr int kMaxRefChain = 32;

std::string key_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

bool is_count(const ojson& j) { return j.is_number_unsigned() || (j.is_number_integer() && j.get<long long>() >= 0); }

const ojson& resolve(const ojson& root, const ojson& ref) {
  const std::string prefix = "#/$defs/";
  if (!ref.is_string() || ref.get<std::string>().rfind(prefix, 0) != 0) {
    throw SchemaError("$ref " + ref.dump() + ": only \"#/$defs/NAME\" references are supported");
  }
  const std::string name = ref.get<std::string>().substr(prefix.size());
  const auto defs = root.find("$defs");
  if (defs == root.end() || !defs->is_object() || !defs->contains(name)) {
    throw SchemaError("$ref " + ref.dump() + ": no such definition");
  }
  return (*defs)[name];
}

/// Throws SchemaError unless every keyword of `schema` (and of its subschemas) is supported and well-formed.
void check_schema(const ojson& schema, const ojson& root, const std::string& where) {
  if (schema.is_boolean()) return;
  if (!schema.is_object()) throw SchemaError(where + ": a schema must be an object or a boolean");
  for (const auto& [key, value] : schema.items()) {
    const std::string at = where + "/" + key;
    if (kAnnotations.count(key)) continue;
    if (!kKeywords.count(key)) throw SchemaError(at + ": unsupported keyword");
    if (key == "type") {
      const ojson list = value.is_array() ? value : ojson::array({value});
      if (list.empty()) throw SchemaError(at + ": empty type list");
      for (const ojson& t : list) {
        if (!t.is_string() || !kTypes.count(t.get<std::string>())) throw SchemaError(at + ": unknown type " + t.dump());
      }
    } else if (key == "enum") {
      if (!value.is_array() || value.empty()) throw SchemaError(at + ": must be a non-empty array");
    } else if (key == "required") {
      if (!value.is_array() || !std::all_of(value.begin(), value.end(), [](const ojson& k) { return k.is_string(); })) {
        throw SchemaError(at + ": must be an array of strings");
      }
    } else if (key == "properties" || key == "$defs") {
      if (!value.is_object()) throw SchemaError(at + ": must be an object");
      for (const auto& [name, sub] : value.items()) check_schema(sub, root, at + "/" + name);
    } else if (key == "items" || key == "additionalProperties") {
      check_schema(value, root, at);
    } else if (key == "minItems" || key == "minLength" || key == "maxLength") {
      if (!is_count(value)) throw SchemaError(at + ": must be a non-negative integer");
    } else if (key == "minimum" || key == "maximum") {
      if (!value.is_number()) throw SchemaError(at + ": must be a number");
    } else if (key == "$ref") {
      resolve(root, value);
    }
  }
}

bool has_type(const ojson& j, const std::string& type) {
  if (type == "object") return j.is_object();
  if (type == "array") return j.is_array();
  if (type == "string") return j.is_string();
  if (type == "boolean") return j.is_boolean();
  if (type == "null") return j.is_null();
  if (type == "number") return j.is_number();
  // JSON Schema: an integer is any number without a fractional part, so 3.0 is one.
  if (type == "integer") {
    return j.is_number_integer() || (j.is_number_float() && std::trunc(j.get<double>()) == j.get<double>());
  }
  return false;
}

const char* type_of(const ojson& j) {
  if (j.is_object()) return "object";
  if (j.is_array()) return "array";
  if (j.is_string()) return "string";
  if (j.is_boolean()) return "boolean";
  if (j.is_null()) return "null";
  return j.is_number_integer() ? "integer" : "number";
}

std::size_t code_points(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

std::string brief(const ojson& j) {
  std::string text = j.dump(-1, ' ', false, ojson::error_handler_t::replace);
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

class Validator {
 public:
  Validator(const ojson& root, std::vector<SchemaViolation>& out) : root_(root), out_(out) {}

  void validate(const ojson& doc, const ojson& schema, const std::string& path, int ref_chain = 0) {
    if (schema.is_boolean()) {
      if (!schema.get<bool>()) fail(path, "is not allowed here");
      return;
    }
    if (const auto ref = schema.find("$ref"); ref != schema.end()) {
      if (ref_chain >= kMaxRefChain) throw SchemaError("$ref " + ref->dump() + ": reference cycle");
      validate(doc, resolve(root_, *ref), path, ref_chain + 1);
    }
    if (const auto type = schema.find("type"); type != schema.end()) {
      const ojson list = type->is_array() ? *type : ojson::array({*type});
      const bool ok =
          std::any_of(list.begin(), list.end(), [&](const ojson& t) { return has_type(doc, t.get<std::string>()); });
      if (!ok) {
        // A wrong type makes every further check on this value noise: one message is enough.
        fail(path, "must be of type " + (type->is_array() ? type->dump() : type->get<std::string>()) + ", got " +
                       type_of(doc));
        return;
      }
    }
    if (const auto e = schema.find("enum"); e != schema.end()) {
      if (std::find(e->begin(), e->end(), doc) == e->end()) {
        fail(path, "must be one of " + brief(*e) + ", got " + brief(doc));
      }
    }
    if (const auto c = schema.find("const"); c != schema.end() && doc != *c) {
      fail(path, "must be " + brief(*c) + ", got " + brief(doc));
    }
    if (doc.is_number()) check_number(doc, schema, path);
    if (doc.is_string()) check_string(doc, schema, path);
    if (doc.is_array()) check_array(doc, schema, path);
    if (doc.is_object()) check_object(doc, schema, path);
  }

 private:
  void fail(const std::string& path, const std::string& message) { out_.push_back({path, message}); }

  void check_number(const ojson& doc, const ojson& schema, const std::string& path) {
    const double v = doc.get<double>();
    if (const auto lo = schema.find("minimum"); lo != schema.end() && v < lo->get<double>()) {
      fail(path, "must be >= " + lo->dump() + ", got " + doc.dump());
    }
    if (const auto hi = schema.find("maximum"); hi != schema.end() && v > hi->get<double>()) {
      fail(path, "must be <= " + hi->dump() + ", got " + doc.dump());
    }
  }

  void check_string(const ojson& doc, const ojson& schema, const std::string& path) {
    const std::size_t n = code_points(doc.get<std::string>());
    if (const auto lo = schema.find("minLength"); lo != schema.end() && n < lo->get<std::size_t>()) {
      fail(path, "must have at least " + lo->dump() + " characters, got " + std::to_string(n));
    }
    if (const auto hi = schema.find("maxLength"); hi != schema.end() && n > hi->get<std::size_t>()) {
      fail(path, "must have at most " + hi->dump() + " characters, got " + std::to_string(n));
    }
  }

  void check_array(const ojson& doc, const ojson& schema, const std::string& path) {
    if (const auto lo = schema.find("minItems"); lo != schema.end() && doc.size() < lo->get<std::size_t>()) {
      fail(path, "must have at least " + lo->dump() + " entries, got " + std::to_string(doc.size()));
    }
    if (const auto items = schema.find("items"); items != schema.end()) {
      for (std::size_t i = 0; i < doc.size(); ++i) validate(doc[i], *items, path + "[" + std::to_string(i) + "]");
    }
  }

  void check_object(const ojson& doc, const ojson& schema, const std::string& path) {
    if (const auto required = schema.find("required"); required != schema.end()) {
      for (const ojson& key : *required) {
        if (!doc.contains(key.get<std::string>())) fail(key_path(path, key.get<std::string>()), "missing (required)");
      }
    }
    const auto properties = schema.find("properties");
    const auto additional = schema.find("additionalProperties");
    for (const auto& [key, value] : doc.items()) {
      const std::string sub = key_path(path, key);
      if (properties != schema.end() && properties->contains(key)) {
        validate(value, (*properties)[key], sub);
      } else if (additional != schema.end()) {
        if (additional->is_boolean() && !additional->get<bool>())
          fail(sub, "unexpected key");
        else
          validate(value, *additional, sub);
      }
    }
  }

  const ojson& root_;
  std::vector<SchemaViolation>& out_;
};

}  // namespace

std::vector<SchemaViolation> check_against_schema(const ojson& document, const ojson& schema) {
  check_schema(schema, schema, "#");
  std::vector<SchemaViolation> violations;
  Validator(schema, violations).validate(document, schema, "");
  return violations;
}

std::string describe(const SchemaViolation& violation) {
  return violation.path.empty() ? violation.message : violation.path + ": " + violation.message;
}

}  // namespace tcsb
