// A validator for the small subset of JSON Schema (draft 2020-12) that results/schema/tcsb-result.schema.json uses.
// No JSON-Schema library is packaged for us, and the subset is small: type, enum, const, properties, required,
// additionalProperties, items, minItems, minimum, maximum, minLength, maxLength, and $ref to "#/$defs/NAME".
// A schema using any other keyword is rejected outright rather than half-checked, so the schema can never claim
// more than this code verifies.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tcsb {

/// The schema itself uses something this validator does not implement (or is malformed).
class SchemaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One place where a document breaks the schema.
struct SchemaViolation {
  std::string path;     ///< e.g. "cases[3].repetitions[0].final_state_hash"; "" for the document itself
  std::string message;  ///< e.g. "must be of type string, got number"
};

/// Every violation of `schema` by `document`, in document order; empty when it conforms. Checks the whole schema
/// first and throws SchemaError when it uses an unsupported keyword or a $ref that does not resolve.
std::vector<SchemaViolation> check_against_schema(const nlohmann::ordered_json& document,
                                                  const nlohmann::ordered_json& schema);

/// "path: message" (or just the message at the root): one line for an error report.
std::string describe(const SchemaViolation& violation);

}  // namespace tcsb
