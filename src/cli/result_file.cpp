#include "cli/result_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "cli/cli_common.h"
#include "report/json_report.h"
#include "report/result_schema.h"

namespace tcsb::cli {

LoadedResult load_result_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(path + ": cannot read the file (" + std::strerror(errno) + ")");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};

  LoadedResult result;
  try {
    result.document = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // A syntax error (parse_error) or a number too large for a double, such as a time of 1e400 (out_of_range.406):
    // both are bad input, never an internal error. e.what() starts with "[json.exception.parse_error.101] ": the
    // reader wants where and what, not the id.
    const std::string what = e.what();
    const std::size_t cut = what.find("] ");
    throw UsageError(path + ": not valid JSON: " + (cut == std::string::npos ? what : what.substr(cut + 2)));
  }
  const nlohmann::ordered_json& doc = result.document;
  if (!doc.is_object() || !doc.contains("tool") || doc["tool"] != "tcsb") {
    throw UsageError(path + ": not a tcsb result (no \"tool\": \"tcsb\")");
  }
  if (const auto kind = doc.find("kind"); kind != doc.end()) {
    // Only `tcsb frames` writes a kind so far; a run result has none.
    throw UsageError(path + ": kind: " + kind->dump() + ": not a run result (a `tcsb frames` file, say); give the " +
                     "output of `tcsb run` or `tcsb reproduce`");
  }
  const auto version = doc.find("schema_version");
  if (version == doc.end() || !version->is_number_integer() || *version != kNativeJsonSchemaVersion) {
    throw UsageError(path + ": schema_version: " + (version == doc.end() ? std::string("missing") : version->dump()) +
                     ", but this tcsb reads version " + std::to_string(kNativeJsonSchemaVersion) +
                     " (rerun the suite with this build)");
  }
  const std::vector<SchemaViolation> violations = check_result_document(doc);
  if (!violations.empty()) {
    std::string message = path + ": not a valid tcsb result: " + describe(violations.front());
    if (violations.size() > 1) message += " (and " + std::to_string(violations.size() - 1) + " more problems)";
    throw UsageError(message);
  }
  try {
    result.view = read_result(doc, path);
  } catch (const ResultFileError& e) {
    throw UsageError(e.what());
  }
  return result;
}

}  // namespace tcsb::cli
