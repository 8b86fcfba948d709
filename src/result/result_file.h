// Reading a result file given on the command line (`tcsb compare`, `tcsb export`): the file must exist, parse as
// JSON, be a tcsb result of this build's schema_version, and conform to the result schema. Anything else is bad
// input: one InputError line naming the file and, where there is one, the field (exit 2).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "result/result_view.h"

namespace tcsb {

/// A result file, checked and read.
struct LoadedResult {
  nlohmann::ordered_json document;  ///< as parsed (key order kept)
  ResultView view;                  ///< its typed reading
};

/// Loads `path`. Throws InputError when the file is unreadable, not JSON, not a tcsb result, of another
/// schema_version, or breaks the schema (the first violation is named, the others counted).
LoadedResult load_result_file(const std::string& path);

}  // namespace tcsb
