#include "result/result_file.h"

#include "base/input_error.h"
#include "base/json_file.h"
#include "result/result_schema.h"

namespace tcsb {

LoadedResult load_result_file(const std::string& path) {
  LoadedResult result;
  result.document = read_json_file<nlohmann::ordered_json>(path, kResultJsonLimits);
  const nlohmann::ordered_json& doc = result.document;
  check_tcsb_document(doc, path);
  if (const auto kind = doc.find("kind"); kind != doc.end()) {
    // Only `tcsb frames` writes a kind so far; a run result has none.
    throw InputError(path, "kind",
                     kind->dump() + ": not a run result (a `tcsb frames` file, say); give the output of `tcsb run` " +
                         "or `tcsb reproduce`");
  }
  const auto version = doc.find("schema_version");
  if (version == doc.end() || !version->is_number_integer() || *version != kNativeJsonSchemaVersion) {
    throw InputError(path, "schema_version",
                     (version == doc.end() ? std::string("missing") : version->dump()) +
                         ", but this tcsb reads version " + std::to_string(kNativeJsonSchemaVersion) +
                         " (rerun the suite with this build)");
  }
  const std::vector<SchemaViolation> violations = check_result_document(doc);
  if (!violations.empty()) {
    std::string message = "not a valid tcsb result: " + describe(violations.front());
    if (violations.size() > 1) message += " (and " + std::to_string(violations.size() - 1) + " more problems)";
    throw InputError(path, "", message);
  }
  result.view = read_result(doc, path);
  return result;
}

}  // namespace tcsb
