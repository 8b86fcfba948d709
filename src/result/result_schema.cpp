#include "result/result_schema.h"

#include "result_schema_text.h"

namespace tcsb {

const nlohmann::ordered_json& result_schema() {
  static const nlohmann::ordered_json schema = nlohmann::ordered_json::parse(generated::kResultSchemaText);
  return schema;
}

std::vector<SchemaViolation> check_result_document(const nlohmann::ordered_json& document) {
  return check_against_schema(document, result_schema());
}

}  // namespace tcsb
