// The native result schema (results/schema/tcsb-result.schema.json), compiled into the binary so `tcsb compare` and
// `tcsb export` can reject files that are not tcsb results wherever the binary runs, and one function that checks
// a document against it.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "base/json_schema_check.h"

namespace tcsb {

/// Version of the native JSON layout. Bumped whenever the layout changes (a key added, removed, renamed or changing
/// meaning), together with results/schema/tcsb-result.schema.json, which pins it in its schema_version enum; tests
/// validate real runs against that schema. 2: first version with a schema.
inline constexpr int kNativeJsonSchemaVersion = 2;

/// The schema as parsed JSON (parsed once; the text is embedded at configure time).
const nlohmann::ordered_json& result_schema();

/// Every violation of the result schema by `document`; empty when it is a valid native result.
std::vector<SchemaViolation> check_result_document(const nlohmann::ordered_json& document);

}  // namespace tcsb
