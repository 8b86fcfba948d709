#include "paper/paper_reference.h"

#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "base/json_file.h"

namespace tcsb {

namespace {

double number(const nlohmann::json& row, const char* key, const std::string& file, const std::string& where) {
  const auto it = row.find(key);
  if (it == row.end() || !it->is_number()) throw InputError(file, where + "." + key, "must be a number");
  return it->get<double>();
}

std::string text(const nlohmann::json& row, const char* key, const std::string& file, const std::string& where) {
  const auto it = row.find(key);
  if (it == row.end() || !it->is_string()) {
    throw InputError(file, where.empty() ? std::string(key) : where + "." + key, "must be a string");
  }
  return it->get<std::string>();
}

/// A string member that may be absent ("").
std::string optional_text(const nlohmann::json& root, const char* key, const std::string& file) {
  return root.contains(key) ? text(root, key, file, "") : std::string();
}

const nlohmann::json& rows(const nlohmann::json& root, const char* table, const std::string& file) {
  if (!root.contains(table) || !root[table].is_object() || !root[table].contains("rows") ||
      !root[table]["rows"].is_array())
    throw InputError(file, std::string(table) + ".rows", "must be an array of rows");
  return root[table]["rows"];
}

}  // namespace

double PaperReference::time_ratio(const std::string& compression) const {
  double plain = 0, tc = 0;
  for (const PaperTable2Row& r : table2) {
    if (r.method == "Bullet SoftBody") plain = r.total_ms;
    if (r.method == "TC-SB" && r.compression == compression) tc = r.total_ms;
  }
  return plain > 0 ? tc / plain : 0.0;
}

PaperReference load_paper_reference(const std::filesystem::path& path) {
  const std::string file = path.string();
  const nlohmann::json root = read_json_file<nlohmann::json>(path, kSuiteJsonLimits);
  if (!root.is_object()) throw InputError(file, "", "must be a JSON object");
  PaperReference ref;
  ref.source = optional_text(root, "source", file);
  ref.hardware = optional_text(root, "hardware", file);
  const nlohmann::json& t1 = rows(root, "table1", file);
  for (std::size_t i = 0; i < t1.size(); ++i) {
    const std::string where = "table1.rows[" + std::to_string(i) + "]";
    const nlohmann::json& r = t1[i];
    ref.table1.push_back({text(r, "operation", file, where), number(r, "N", file, where), number(r, "L", file, where),
                          number(r, "node_ops_ms", file, where), number(r, "node_ops_pct", file, where),
                          number(r, "link_ops_ms", file, where), number(r, "link_ops_pct", file, where),
                          number(r, "complete_ms", file, where)});
  }
  const nlohmann::json& t2 = rows(root, "table2", file);
  for (std::size_t i = 0; i < t2.size(); ++i) {
    const std::string where = "table2.rows[" + std::to_string(i) + "]";
    const nlohmann::json& r = t2[i];
    ref.table2.push_back({text(r, "method", file, where), text(r, "compression", file, where),
                          number(r, "N", file, where), number(r, "L", file, where), number(r, "I", file, where),
                          number(r, "total_ms", file, where)});
  }
  return ref;
}

}  // namespace tcsb
